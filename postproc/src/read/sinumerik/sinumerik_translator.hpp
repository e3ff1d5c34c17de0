// SPDX-License-Identifier: Apache-2.0
#pragma once
// Runs a Sinumerik program (sinumerik_program.hpp) as the control would, block by block, and
// writes what it moves as plain ISO blocks for the G-code reader (gcode_cl_reader.hpp), each
// with the line of the Sinumerik block it comes from:
//   - program flow (labels, GOTOF/GOTOB/GOTO, IF/ELSE/ENDIF, WHILE, FOR, REPEAT/UNTIL, LOOP,
//     subprograms L<n>/NAME/CALL/PROC with their parameters, at most `max_call_depth` deep) and
//     DEF/R variables are executed here; the ISO blocks hold numbers only;
//   - frames (TRANS ATRANS ROT AROT SCALE ASCALE, CYCLE800's swivel frame) are applied here: the
//     ISO blocks are in W, always absolute (G90), X=IC(..)/AC(..) and G91 resolved;
//   - arcs (I J K incremental or AC(), CR=) become G2/G3 with incremental I J K where the frame
//     keeps the working plane, otherwise points within `arc_chord_tolerance_mm`;
//   - TRAORI/TRAFOOF pass through (tool-tip input); A3= B3= C3= become the machine's rotary
//     angles (the solution nearest the current angles, within the limits);
//   - CYCLE800 positions the rotary axes (the solution for the plane's normal, _DIR choosing
//     between two) and reads what follows as tool-tip positions in the swivelled plane;
//   - CYCLE81/CYCLE82 (also under MCALL) become G81/G82 or their motions; CYCLE83/85/86 become
//     their motions (sinumerik_holes.cpp); CYCLE84/840 the tap G84/G74 (sinumerik_taps.cpp);
//   - SUPA and G53 blocks become G53 (machine coordinates); D0 becomes G49 (no tool length); where
//     the machine file gives the reference data, the machine position they leave is kept, so that
//     CYCLE800 knows where the tool tip stands in the swivelled plane (the machine position seen in
//     the new frame, as on the control);
//   - G75 FP=n (fixed point approach) becomes G53 G0 to the machine file's `fixed_point`s;
//   - T="name" becomes T0 with the name beside the block (IsoBlock::tool_name), which the reader
//     puts into the tool change (cl::ToolChange::name).
// Everything else is refused by name (InputError with file:line:column).
#include <deque>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "ncpost/kinematics/forward.hpp"
#include "ncpost/kinematics/machine.hpp"
#include "read/sinumerik/sinumerik_frame.hpp"
#include "read/sinumerik/sinumerik_program.hpp"
#include "read/sinumerik/sinumerik_values.hpp"

namespace ncpost::sinumerik {

struct TranslatorOptions {
  double arc_chord_tolerance_mm = 1e-3;
  int max_call_depth = 16;       ///< subprogram levels (the control's limit is 16 with the main program)
  long max_blocks = 50'000'000;  ///< blocks executed before the program is taken as an endless loop
  bool block_skip = true;        ///< '/' blocks are left out
};

/// One ISO block for the G-code reader and the Sinumerik line it comes from.
struct IsoBlock {
  std::string text;
  int line = 0;
  /// The block selects a tool (its T word): by name (T="name": the ISO block says T0), "" by number.
  std::optional<std::string> tool_name;
};

/// A drilling or boring cycle (CYCLE81 82 83 85 86) with its values (lengths in the program unit,
/// absolute along the frame's Z; feeds in the program's feed unit).
struct Drilling {
  std::string name;
  double retract = 0.0, reference = 0.0, safety = 0.0, depth = 0.0, dwell_s = 0.0;
  // CYCLE83
  std::vector<double> stroke_bottoms;  ///< where each infeed ends, the last at `depth`
  bool chip_removal = false;           ///< VARI=1: out to the safety plane after each infeed; 0: back off only
  double first_feed_factor = 1.0;      ///< FRF: the first infeed at F * FRF
  double back_off = 1.0;               ///< _VRT (VARI=0): the retract for chip breaking
  double anticipation = 0.0;           ///< (VARI=1) the rapid re-entry stops this far above the last bottom
  double top_dwell_s = 0.0;            ///< DTS (VARI=1): at the safety plane
  double final_dwell_s = 0.0;          ///< _DTD, else DTB: at the final depth
  // CYCLE85: the feeds in and out; CYCLE86, CYCLE84, CYCLE840: the spindle after the cycle (3: M3, 4: M4, 5: M5)
  double feed_in = 0.0, feed_out = 0.0;
  int spindle_after = 0;
  // CYCLE84 / CYCLE840 (sinumerik_taps.cpp)
  enum class Tap { none, rigid, floating } tap = Tap::none;
  double pitch_mm = 0.0;      ///< signed: > 0 right-hand (CYCLE840 without encoder: 0, the F before)
  double tap_rpm = 0.0;       ///< CYCLE84 SST
  bool with_encoder = false;  ///< CYCLE840 ENC=0
  int retract_spindle = 0;    ///< CYCLE840 SDR (0: reversed)
};

class Translator {
 public:
  Translator(Program program, const Machine& machine, const Setup& setup, TranslatorOptions options = {});

  /// The next ISO block; false after the last.
  bool next(IsoBlock& out);
  std::vector<std::string> take_notices();

  const Program& program() const { return program_; }

 private:
  struct Call {
    std::size_t return_to = 0;
    int unit = 0;
    int line = 0;  ///< the calling line
    std::string name;
    Values::Saved saved;
    long repeats_left = 0;  ///< L<n> P<k>: further runs
  };
  struct Words;
  struct Move;

  // flow (sinumerik_translator.cpp)
  bool step();
  void statement(const ProgramLine& l);
  bool flow_statement(const ProgramLine& l);
  void if_statement(const ProgramLine& l);
  void define(const ProgramLine& l);
  void jump(const ProgramLine& l, const std::string& how, const std::string& label);
  bool condition(const ProgramLine& l, const std::string& text);
  void for_loop(const ProgramLine& l);
  void assign_or_fail(const ProgramLine& l, const std::string& name, double v);
  bool call_if_subprogram(const ProgramLine& l, const Item& item);
  void call(const ProgramLine& l, const std::string& unit_name, const std::vector<std::string>& args, long repeats);
  void return_from_unit();
  void end_program(const ProgramLine& l);
  void modal_call(const ProgramLine& l);

  // blocks (sinumerik_block.cpp)
  void block(const ProgramLine& l);
  void collect(const ProgramLine& l, const Item& item, Words& w);
  void g_word(const ProgramLine& l, const Item& item, Words& w);
  void named(const ProgramLine& l, const Item& item, Words& w);
  void assignment(const ProgramLine& l, const Item& item, Words& w);
  bool axis_address(const ProgramLine& l, const Item& item, Words& w);
  bool tool_name_address(const ProgramLine& l, const Item& item, Words& w);
  void value_address(const ProgramLine& l, const Item& item, Words& w);
  void called(const ProgramLine& l, const Item& item, Words& w);
  void write_block(const ProgramLine& l, Words& w);
  void frames_suppressed(const ProgramLine& l, const Words& w, bool moves);
  void frame_statement(const ProgramLine& l);

  // motion (sinumerik_motion.cpp)
  void motion(const ProgramLine& l, Words& w, std::string& iso);
  void linear_target(const ProgramLine& l, const Words& w, Eigen::Vector3d& target_prog,
                     std::array<bool, 3>& programmed);
  std::string axis_words(const ProgramLine& l, const Eigen::Vector3d& target_prog,
                         const std::array<bool, 3>& programmed, bool all);
  std::string rotary_words(const ProgramLine& l, Words& w);
  void arc(const ProgramLine& l, Words& w, const Eigen::Vector3d& target_prog, std::string& iso,
           const std::string& tail);
  std::string orientation_words(const ProgramLine& l, const Words& w);
  std::string supa_words(const ProgramLine& l, const Words& w);
  std::string fixed_point_words(const ProgramLine& l, const Words& w);
  Eigen::Vector3d current_prog(const ProgramLine& l, int column) const;
  std::optional<RotaryAngles> nearest_solution(const Eigen::Vector3d& axis_W, int direction) const;

  // the machine position (sinumerik_machine_position.cpp)
  std::optional<double> machine_reference_mm(int axis) const;
  void note_machine_words(const Words& w);
  std::array<std::optional<double>, 3> machine_now() const;
  RotaryAngles rotary_now() const;
  void retract_for_swivel(const ProgramLine& l);
  bool rotary_only_under_d0(const Words& w) const;

  // cycles (sinumerik_cycles.cpp)
  void cycle800(const ProgramLine& l, const Item& item);
  void cycle800_reset(const ProgramLine& l);
  Eigen::Matrix3d axis_by_axis(const ProgramLine& l, const Item& item, double mode,
                               const Eigen::Vector3d& angles_deg) const;
  void position_swivel(const ProgramLine& l, const Item& item, const Eigen::Vector3d& axis_W, int dir, bool tilted);
  Drilling drilling(const ProgramLine& l, const Item& item);
  void drill(const ProgramLine& l, const Drilling& d);

  // CYCLE83/85/86 (sinumerik_holes.cpp)
  void hole_parameters(const ProgramLine& l, const Item& item, const Arguments& args, Drilling& d) const;
  void deep_hole_parameters(const ProgramLine& l, const Item& item, const Arguments& args, Drilling& d) const;
  void expand_hole(const ProgramLine& l, const Drilling& d);
  void deep_hole_motions(const ProgramLine& l, const Drilling& d, const Eigen::Vector3d& at);
  void hole_move(const ProgramLine& l, const Eigen::Vector3d& at, const char* g, double z, double feed);

  // CYCLE84/840 (sinumerik_taps.cpp)
  double tap_pitch(const ProgramLine& l, const Item& item, const Arguments& args, std::size_t mpit, std::size_t pit,
                   std::size_t unit) const;
  void tap_parameters(const ProgramLine& l, const Item& item, const Arguments& args, Drilling& d) const;
  bool tap_left_hand(const ProgramLine& l, const Drilling& d) const;
  void tap(const ProgramLine& l, const Drilling& d);

  [[noreturn]] void fail(const ProgramLine& l, int column, const std::string& what) const;
  void notice_once(const ProgramLine& l, const std::string& key, const std::string& what);
  void emit(const ProgramLine& l, std::string text);
  double value(const ProgramLine& l, int column, const std::string& expression) const;
  Frame frame() const { return swivel_.then(programmable_); }

  Program program_;
  Machine machine_;
  Setup setup_;
  TranslatorOptions options_;
  Values values_;

  std::size_t pc_ = 0;
  std::vector<Call> calls_;
  std::map<std::size_t, double> for_end_;
  long executed_ = 0;
  bool ended_ = false;
  bool started_ = false;

  // modal state
  int motion_ = -1;  ///< 0 1 2 3 (G0..G3); -1 none yet
  int plane_ = 17;
  bool incremental_ = false;   ///< G91
  bool traori_ = false;        ///< TRAORI programmed
  bool swivel_tip_ = false;    ///< CYCLE800 made the reader take tool-tip positions
  bool length_off_ = false;    ///< D0 in force
  bool inch_ = false;          ///< G70/G700 in force (lengths in inch)
  int feed_mode_ = 94;         ///< G93 G94 G95
  double feed_ = 0.0;          ///< F as last programmed (0: none yet)
  double spindle_rpm_ = 0.0;   ///< S as last programmed (0: none yet)
  int spindle_direction_ = 0;  ///< 3 4 5 as last programmed by M3 M4 M5 (0: none yet)
  Frame programmable_;
  Frame swivel_;
  Eigen::Vector3d base_ = Eigen::Vector3d::Zero();  ///< the last position in W (program unit)
  std::array<bool, 3> base_known_{};
  /// X Y Z as machine commands in M (mm) where a SUPA/G53 block or CYCLE800's retraction put them
  /// (the machine file's reference data), until a motion moves the linear axes otherwise.
  std::array<std::optional<double>, 3> machine_mm_{};
  std::array<double, 3> rotary_deg_{};  ///< A B C as last programmed
  std::array<bool, 3> rotary_known_{};
  std::optional<Drilling> mcall_;

  std::deque<IsoBlock> out_;
  std::vector<std::string> notices_;
  std::set<std::string> noticed_;
};

}  // namespace ncpost::sinumerik
