// SPDX-License-Identifier: Apache-2.0
#pragma once
// The call stack of a G-code program's subprograms, expanded on its line source (the input must
// be a file: calls re-read it):
//   Fanuc/Haas  M98 P<o> L<k>   the program O<o> of the same file (O blocks after M30 too) runs k
//                               times; Fanuc's M98 P<kkkk><oooo> (k in front of a 4-digit number)
//                               where the file has O<oooo> but no O<kkkkoooo>
//               M97 P<n> L<k>   Haas local subprogram: from block N<n> of the same file
//               M99             back to the block after the call (or the body again while repeats
//                               are left); M99 P<n>: to block N<n> of the calling program instead
//                               (the one such block from the caller's start to its end; none or
//                               two are input errors)
//   LinuxCNC    o<name> call [a] [b] ...   to `o<name> sub`, #1..#30 set from the arguments (the
//                               caller's #1..#30 are restored on return); endsub/return go back
// A target the program's file (or the file of the running subprogram) does not hold is looked for
// in other files (gcode_subprogram_files.hpp: O<n>.nc ... for M98, name.ngc for o<name>), in the
// directories set_directories() gives; the line source then reads that file, and LineSource::file()
// names it. A call deeper than kMaxDepth, and a call of a subprogram already running (recursion),
// are input errors; so is a target found nowhere. `chain()` names the calls in force for messages
// ("via o100 call at t.ngc:12", each with its own file).
#include <array>
#include <cstdint>
#include <istream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ncpost/postproc/read/gcode/gcode_expression.hpp"
#include "ncpost/postproc/read/line_source.hpp"

namespace ncpost::gcode {

class SubprogramCalls {
 public:
  static constexpr std::size_t kMaxDepth = 10;  ///< nested calls (Fanuc and LinuxCNC allow about as many)
  static constexpr int kLocals = 30;            ///< #1..#30 of an o-word call

  struct Position {
    std::uint64_t offset = 0;  ///< where the line starts (LineSource::next_line_offset())
    int line = 0;              ///< its 1-based number
    int file = -1;             ///< the input it is in (-1: the one being read)
  };

  SubprogramCalls(LineSource& source, std::string file);
  /// Where subprograms in other files are looked for, in order (--subprogram-dir, the program's).
  void set_directories(std::vector<std::string> dirs) { dirs_ = std::move(dirs); }
  /// The program's own file is being read (not a subprogram's file).
  bool in_main_file() const { return current_ == 0; }

  /// M98 P<p> L<times> on line `line` (column: of the M word); `back`: where the program goes on.
  void call_program(double p, int times, Position back, int line, int column);
  /// M97 P<n> L<times>: from block N<n>.
  void call_block(int n, int times, Position back, int line, int column);
  /// `o<name> call`: to its sub with `arguments` in #1..; `params` holds the caller's #1..#30.
  void call_sub(const std::string& label, const std::vector<ParamValue>& arguments, Parameters& params, Position back,
                int line, int column);
  /// M99 (`m99`: true) or endsub/return: back to the caller or into the body again. Returns the
  /// o-word loops in force at the call (for the flow to drop the callee's).
  /// `return_block` > 0: M99 P<n>, back to block N<n> of the calling program.
  std::size_t leave(bool m99, Parameters& params, int line, int column, int return_block = 0);

  bool active() const { return !frames_.empty(); }
  /// The label of the innermost call ("O1000", "N500", "o<name>"), "" at the top level.
  std::string innermost() const { return frames_.empty() ? std::string() : frames_.back().label; }
  /// " via o100 call at t.ngc:12 via O2000 call at t.ngc:3" (innermost first), "" at the top.
  std::string chain() const;
  /// The loops the o-word flow had when the innermost call was made.
  void note_loops(std::size_t loops) { loops_at_call_ = loops; }

 private:
  struct Frame {
    std::string label;
    std::string caller_file;  ///< the file of the call
    Position caller_start;    ///< where the calling program starts (M99 P searches it)
    int call_line = 0;
    Position back;
    Position body;
    int repeats_left = 0;
    std::optional<std::array<ParamValue, kLocals>> saved;  ///< the caller's #1..#30 (o-word calls)
    std::size_t loops = 0;                                 ///< o-word loops at the call
  };
  /// An input: the program's (index 0) or a subprogram's file, opened once.
  struct Input {
    std::string name;
    std::istream* in = nullptr;
    std::unique_ptr<std::istream> owned;
    std::istream::pos_type origin;
  };
  std::optional<Position> find(const std::string& label, int line, int column);
  std::optional<Position> find_in(int file, const std::string& label, int line, int column);
  Position find_elsewhere(const Frame& at, const std::string& label, const std::string& call, int line, int column);
  int open_input(const std::string& path, int line, int column);
  void return_to_block(int n, const Frame& done, Position at_m99, int line, int column);
  Frame frame_at_call(const std::string& label, Position back) const;
  void enter(Frame frame, int line, int column);
  void seek(Position at, int line, int column);
  [[noreturn]] void fail(int line, int column, const std::string& what) const;
  [[noreturn]] void fail_in_caller(const Frame& f, int line, int column, const std::string& what);

  LineSource& source_;
  std::string file_;
  std::vector<Frame> frames_;
  std::map<std::string, Position> found_;  ///< bodies located so far ("label@file")
  std::size_t loops_at_call_ = 0;
  std::vector<Input> inputs_;
  int current_ = 0;  ///< the input being read
  std::vector<std::string> dirs_;
};

}  // namespace ncpost::gcode
