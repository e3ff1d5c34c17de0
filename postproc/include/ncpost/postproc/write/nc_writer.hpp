// SPDX-License-Identifier: Apache-2.0
#pragma once
// Streams an NC program in a dialect: one motion per block, absolute, metric, in the words of the
// dialect (dialect.hpp: motion and feed words, modal or not, block numbers, arc, cycle, spindle
// and coolant words). Values arrive in output units (mm, deg) and are rounded to the dialect's
// decimals here; `rounded()` gives the values the control will see.
#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "ncpost/kinematics/machine.hpp"
#include "ncpost/postproc/write/atomic_file.hpp"
#include "ncpost/postproc/write/dialect.hpp"
#include "ncpost/postproc/verify/written_block.hpp"

namespace ncpost {

/// One motion block in output units: axis words in `letters` order (mm, deg).
struct NcMotion {
  bool rapid = false;
  PerAxis<double> values{};  ///< X Y Z then rotary axes
  enum class FeedMode { per_minute, inverse_time } feed_mode = FeedMode::per_minute;
  double feed = 0.0;  ///< mm/min, or 1/min under inverse time
};

/// A circular block in a principal plane of M (no rotary motion): G2/G3 with incremental centre
/// offsets (I J K from the start), output units (mm), feed per minute.
struct NcArc {
  int plane = 17;                            ///< 17 (XY, I J), 18 (ZX, I K), 19 (YZ, J K)
  bool clockwise = false;                    ///< G2 (seen from the positive end of the plane's normal axis), else G3
  std::array<double, 3> end_mm{};            ///< X Y Z at the end
  std::array<double, 3> centre_offset_mm{};  ///< centre − start (I J K)
  double feed_mm_min = 0.0;
};

/// One hole of a canned cycle along −Z of the program frame, output units (mm): `code` (G81,
/// G83, ...: cycle_words.hpp) with the return word to the initial level (G98: where the tool
/// stands when the cycle starts) or to the R plane (G99). Holes that follow with the same code,
/// words and return level continue the modal cycle (X Y only); anything else is written after the
/// cancel word (G80); CycleWords of the dialect.
struct NcCycle {
  std::string code;
  bool retract_to_r = false;          ///< G99, else G98
  std::array<double, 3> bottom_mm{};  ///< X Y of the hole, Z of its bottom
  double r_plane_mm = 0.0;            ///< Z of the R plane
  std::string words;                  ///< further words as written (" Q2.0000", " P500"), leading blank each
  double feed_mm_min = 0.0;
  std::vector<std::string> before;  ///< blocks before the cycle's first block (Fanuc rigid tapping M29 S)
};

class NcWriter {
 public:
  /// `letters`: the axis words, e.g. "XYZAC".
  NcWriter(AtomicFile& out, Dialect dialect, std::string letters);

  void begin_program(const std::string& name, const std::vector<std::string>& header_comments);
  void comment(const std::string& text);
  /// A raw block (e.g. "M3 S12000"), numbered if the dialect numbers lines.
  void block(const std::string& words);
  /// A raw block with `note` as a comment at its end ("M0 (mount the probe)", Klartext
  /// "M0 ; mount the probe"), sanitised as every comment; no comment when `note` is empty.
  void block(const std::string& words, const std::string& note);
  /// Writes a motion block; false (nothing written) if no axis word changes.
  bool motion(const NcMotion& m) { return motion(m, kNoNote); }
  /// A motion block with `note` as a comment at its end (as `block`).
  bool motion(const NcMotion& m, const std::string& note);
  /// Writes a circular block; the rotary words stay as they are.
  void arc(const NcArc& a);
  /// Writes one canned-cycle hole, continuing the modal cycle when `continues(c)`; the tool ends at
  /// X Y of the hole, Z of the initial level (G98) or of the R plane (G99).
  void cycle(const NcCycle& c);
  /// Blocks of the dialect's tool words (Dialect::tool_call, ...) for `tool`.
  void tool_blocks(const std::vector<std::string>& blocks, int tool, int length_register);
  /// The blocks of a tool change ("{tool}" already replaced). When one names "{rpm}" they wait
  /// for the next spindle start, which puts its speed in them, or are written (with the speed in
  /// force, or without the speed word) before the next block that is not a comment.
  void tool_change(const std::vector<std::string>& blocks);
  /// The spindle on at `rpm` (0: the speed in force), clockwise or not (SpindleWords).
  void spindle_on(double rpm, bool counter_clockwise);
  void spindle_stop();
  /// The spindle's direction word alone (a tap reversing out of its hole).
  void spindle_turn(bool counter_clockwise);
  /// Each of `blocks` (no placeholders), e.g. the dialect's coolant words.
  void blocks(const std::vector<std::string>& blocks);
  /// RTCP/TCPM on with the length of `tool`, or off.
  void rtcp(bool on, int tool, int length_register);
  /// True if the hole continues the active modal cycle: same code, words, feed and return level,
  /// the tool at the return level (`return_z_mm`: the initial level for G98, the R plane for G99).
  bool continues(const NcCycle& c, double return_z_mm) const;
  /// The cycle's cancel word (G80) if a cycle is active (every other block ends it by itself).
  void end_cycle();
  bool cycle_active() const { return active_cycle_.has_value(); }
  void end_program();
  /// Writes the blocks that define a tilted work plane (`on`) or cancel it (tilted_plane.hpp). In
  /// the plane, motion blocks carry X Y Z only, in the plane's coordinates (the first one all three);
  /// after it, the next motion writes every axis word.
  void tilted_plane(const std::vector<std::string>& blocks, bool on);
  bool in_tilted_plane() const { return tilted_; }
  /// `value` as a word value of `axis` (0-2 linear, else angle): rounded, with the dialect's
  /// decimals (and '+' in Klartext).
  std::string word_value(int axis, double value) const;
  /// Flushes buffered output into the file (called on end_program and when the buffer is large).
  void flush();

  /// Keep the text of each block as written (last_line()): `post --verify` reads it back.
  void keep_last_line(bool on) { keep_last_line_ = on; }
  /// The last block written, as it stands in the program (no line end), when keep_last_line().
  const std::string& last_line() const { return last_line_; }
  /// The number of lines written so far (the last block's line in the program file).
  std::size_t lines_written() const { return lines_; }
  /// The modal words in force as the writer holds them (what the next block need not repeat).
  WrittenState in_force() const;

  /// The value as the control will read it (rounded to the dialect's decimals).
  double rounded(int axis, double value) const;
  std::size_t blocks_written() const { return blocks_; }
  const Dialect& dialect() const { return dialect_; }
  const std::string& letters() const { return letters_; }

 private:
  inline static const std::string kNoNote;
  void start_line();
  void end_line();
  /// `note` as a comment at the end of the block being written (nothing when empty).
  void append_note(const std::string& note);
  /// A block as is (no held tool change first).
  void write_block(const std::string& words);
  /// The held tool change, with `rpm` (empty: the speed in force, or none).
  void write_held(const std::string& rpm);
  std::string rpm_text(double rpm) const;
  /// The feed-per-minute word if another feed mode is in force.
  void per_minute_mode();
  /// True when a motion to `m` writes an axis word (a move to where the tool is writes none).
  bool moves_to(const NcMotion& m) const;
  /// The feed-mode and motion words of a motion block where they change.
  void append_motion_words(const NcMotion& m);
  /// The axis words of a motion block that change; how many.
  int append_axis_words(const NcMotion& m);
  /// The feed word of a motion block (a rapid's: the dialect's rapid feed word, if any).
  void append_feed_word(const NcMotion& m);
  /// The axis words a motion block may carry: X Y Z only in a tilted plane.
  std::size_t word_count() const { return tilted_ ? std::min<std::size_t>(3, letters_.size()) : letters_.size(); }

  AtomicFile& out_;
  Dialect dialect_;
  std::string letters_;
  fmt::memory_buffer buf_;
  PerAxis<std::optional<double>> last_{};
  std::optional<int> last_motion_;  ///< 0, 1, 2 or 3
  int plane_ = 17;
  std::optional<NcMotion::FeedMode> last_feed_mode_;
  std::optional<double> last_feed_;
  std::size_t blocks_ = 0;
  long line_number_ = 0;
  double spindle_rpm_ = 0.0;                      ///< the speed in force (0: none yet)
  std::optional<std::vector<std::string>> held_;  ///< a tool change waiting for the spindle's speed
  std::string program_name_;
  std::optional<NcCycle> active_cycle_;
  double cycle_return_z_ = 0.0;  ///< the level the active cycle returns to (rounded)
  bool tilted_ = false;          ///< in a tilted work plane: X Y Z words only
  bool keep_last_line_ = false;
  std::string last_line_;
  std::size_t lines_ = 0;
};

}  // namespace ncpost
