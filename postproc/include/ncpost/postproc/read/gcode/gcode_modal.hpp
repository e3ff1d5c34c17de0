// SPDX-License-Identifier: Apache-2.0
#pragma once
// The meaning of RS274 blocks: modal state (G0-G3, G17-G19, G20/G21, G90/G91, G90.1/G91.1,
// G93/G94/G95, F, S, T, M, RTCP on/off) and what each block does, in the RS274NGC order of
// execution (comments, feed mode, F, S, T, M6, M3-M5, M7-M9, dwell, modal settings, motion,
// stop). Units are converted here: lengths to mm (G20 inches x 25.4, also F under G94/G95),
// rotary words from degrees to rad; incremental words (G91) are made absolute.
//
// I J K of G2/G3: the vector from the start to the centre (RS274NGC), from the centre to the start,
// or the centre itself (G90.1), as the reader's ArcCentre and the program's G90.1/G91.1 say; an arc
// whose end is not on it is refused, naming the other readings it fits.
//
// Supported and rejected words (InputError with the exact column):
//   G0 G1 G2 G3 G4 G17 G18 G19 G20 G21 G28 G30 G40 G43 G43.1 G43.4 G43.5 G49 G53 G54-G59.3 G54.1 P1-P300
//   (work offsets: placed in one frame, work_frames.hpp) G10 L2/L20 (their values), G10 L1/L10-L13 (tool offsets,
//   gcode_tool_offsets.hpp) G61 G61.1 G64 G73 G74 G80 G81-G86 G89 (canned cycles, as cl::Cycle records) G90 G91 G90.1
//   G91.1 G93 G94 G95 G98 G99 G234 G254 G255; M0-M9 M30 M128 M129 M428 M429 (other M codes pass through as comments
//   with a notice; M91/M92 beside axis words, Heidenhain's machine coordinates, are refused); words A B C D F H I J K L
//   N O P Q R S T X Y Z. G40/G41/G42 (with D: the offset register) become cl::CutterComp records. Control mode words
//   (G05.1 Q1, G05 P10000, G08 P1) are dropped with a notice and Sinumerik G70/G71/ G700/G710 set the units
//   (gcode_control_words.hpp). Dynamic compensation (G41.1/G42.1), G87/G88 and cycles under G91 or with L/K repeats,
//   other G10 forms, G52/G92 offsets, rotation, scaling, polar coordinates, threading, probing, U V W and E are "not
//   supported" errors (M97/M98/M99 are SubprogramCall effects); so are rotary letters the machine lacks.
//
// RTCP (tool-tip programming) is modal: on with M428 (LinuxCNC), G43.4/G43.5 (Fanuc), G234
// (Haas), TRAORI (Sinumerik), M128 (Heidenhain); off with the matching M429, G49, TRAFOOF, M129.
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ncpost/postproc/read/cl_record.hpp"
#include "ncpost/postproc/read/gcode/gcode_arc.hpp"
#include "ncpost/postproc/read/gcode/gcode_block.hpp"
#include "ncpost/postproc/read/gcode/gcode_integer_words.hpp"
#include "ncpost/postproc/read/gcode/work_frames.hpp"

namespace ncpost::gcode {

enum class MotionMode { none, rapid, linear, arc_cw, arc_ccw, cycle };

/// The modal canned cycle (G73, G74, G81-G86, G89): its words as last given, absolute mm.
struct CycleModal {
  int code10 = 0;  ///< 810 for G81, ...
  std::optional<double> bottom_z, r_z, q, p_s;
  double initial_z = 0.0;  ///< Z when the cycle mode started (the G98 return level)
};
enum class FeedMode { per_minute, inverse_time, per_revolution };
using cl::IntegerDwell;  // the unit of a dwell time without a decimal point (cl_record.hpp)
enum class Rtcp { off, m428, g43_4, g234, traori, m128 };

struct ModalState {
  MotionMode motion = MotionMode::none;
  Plane plane = Plane::xy;
  bool inch = false;                                        ///< lengths in inch (G20, G70, G700)
  bool feed_inch = false;                                   ///< feeds in inch (G20, G700; G70 leaves them)
  bool units_programmed = false;                            ///< a units word (G20/G21/G70/G71/G700/G710) was seen
  cl::CutterComp::Side cutter = cl::CutterComp::Side::off;  ///< G40/G41/G42
  bool incremental = false;
  ArcCentre arc_centre = ArcCentre::incremental;  ///< what I J K give: --arc-centre, then G90.1/G91.1
  int arc_centre_line = 0;                        ///< the line of the G90.1/G91.1 in force (0: --arc-centre)
  FeedMode feed_mode = FeedMode::per_minute;
  double feed = 0.0;  ///< mm/min, mm/rev, or 1/min (G93), converted
  double spindle_rpm = 0.0;
  cl::Spindle::Direction spindle = cl::Spindle::Direction::off;
  int tool = 0;  ///< the selected T
  /// cl::ToolWords::load_next: the tool the last `T01 T02 M06` pre-selected (T02) and its line (0: none
  /// pending); the next change must load it
  int preselected_tool = 0, preselected_line = 0;
  Rtcp rtcp = Rtcp::off;
  /// The tool length: G43, G43.4, G43.5, G234 turn it on, G49 (or H0) cancels it.
  enum class Length { not_set, on, cancelled } length = Length::not_set;
  int length_cancelled_line = 0;  ///< where it was cancelled
  std::string work_offset;        ///< "G54", "G54.1 P2", ... ("": none programmed yet)
  int work_offset_line = 0;       ///< where it was selected
  bool moved_in_work = false;     ///< a motion in work coordinates (not G28's return, not G53)
  bool retract_to_r = false;      ///< G99 (else G98)
  CycleModal cycle;               ///< while motion == cycle
  ProgramPoint position{};        ///< the current position (mm, rad)
  std::array<bool, 6> known{};    ///< the axis has been programmed (else its position is 0, assumed)
  bool ended = false;             ///< M2/M30 seen
};

/// A move in the machine's own coordinates: G28/G30 (the named axes to their reference point,
/// after the block's motion to the intermediate point) or G53 (the block's motion to machine
/// coordinates). The reader places it through the machine (gcode_cl_reader.cpp).
struct MachineMove {
  enum class Kind { reference, machine } kind = Kind::reference;
  std::string code;  ///< "G28", "G30", "G53"
  int column = 0;
  std::array<bool, 6> axes{};             ///< the axes (X Y Z A B C slots) it moves
  std::array<double, 6> machine_value{};  ///< G53: the machine coordinate of each (mm, rad)
};

/// A subprogram call or return of a block (Fanuc/Haas M98 P L, Haas M97 P L, M99): the reader
/// follows it after the block's motion (gcode_subprogram_calls.hpp).
struct SubprogramCall {
  int m = 98;      ///< 97, 98 or 99
  double p = 0.0;  ///< M98: the program number; M97: the block number; M99: the block to return to (0: none)
  int times = 1;   ///< L (1 when not given)
  int column = 0;  ///< of the M word
};

/// What one block does. Cleared by `Interpreter::apply` before it fills it.
struct BlockEffect {
  std::optional<cl::Feed> feed;        ///< F under G94/G95
  std::optional<cl::Spindle> spindle;  ///< S while turning, or M3/M4/M5
  std::optional<cl::ToolChange> tool_change;
  std::optional<cl::LengthOffset> length_offset;  ///< G43/G43.4/G43.5/G234 H<n>
  std::optional<cl::ToolOffset> tool_offset;      ///< G10 L1/L10/L12 ...: a tool offset set (gcode_tool_offsets.hpp)
  std::optional<cl::Coolant> coolant;
  std::optional<cl::CutterComp> cutter_comp;   ///< G40, G41/G42 (D: the offset register)
  std::vector<cl::Unsupported> before_motion;  ///< statements passed through as comments
  bool has_motion = false;
  MotionMode motion = MotionMode::none;
  ProgramPoint start{};
  ProgramPoint end{};
  std::optional<ArcMove> arc;               ///< for G2/G3
  std::array<bool, 6> assumed{};            ///< axes (X Y Z A B C) of `end` not programmed yet (0 assumed)
  std::array<bool, 6> programmed{};         ///< axes with a word in this block
  std::optional<MachineMove> machine_move;  ///< G28/G30/G53
  std::optional<double> dwell_s;            ///< G4: the dwell time (s)
  std::optional<double> motion_feed;        ///< F given on this block: mm/min (G94) or 1/min (G93); not G95
  bool inverse_time = false;                ///< G93 active for this motion
  std::vector<cl::Record> after_motion;     ///< M0/M1 (cl::Stop) and unknown M codes (passed through)
  bool program_end = false;                 ///< M2 / M30
  std::optional<SubprogramCall> call;       ///< M97 / M98 / M99
  /// A canned-cycle block: the cycle of this hole (distances from the motion's end, the hole at
  /// its R plane, along machine Z), written before the motion; `cycle_off` ends a cycle first.
  std::optional<cl::Cycle> cycle;
  bool cycle_off = false;

  void clear();
};

class Interpreter {
 public:
  /// `axis_letters`: the axes the program may use (e.g. "XYZAC"); other rotary letters are errors.
  /// Letters with U, V or W (the TRR-XY machine's "XYUVW") name a machine whose words are all
  /// lengths and no Cartesian frame: ProgramPoint slot i is then axis_letters[i] (mm), other axis
  /// letters are errors, and arcs and canned cycles (which need X Y Z) are not supported.
  /// `arc_centre`: what I J K give until the program's G90.1/G91.1 (which contradict any other
  /// reading than `incremental` but the same: InputError).
  Interpreter(std::string file_name, std::string axis_letters, bool default_inch = false,
              IntegerDwell integer_dwell = IntegerDwell::automatic, ArcCentre arc_centre = ArcCentre::incremental);

  /// Applies one block. `line` is the source text (for error carets). Throws InputError.
  void apply(const Block& block, int line_number, std::string_view line, BlockEffect& effect);

  const ModalState& state() const { return state_; }
  /// The reader placed a machine move (MachineMove): the program position is now `p`.
  void moved_to(const ProgramPoint& p) { state_.position = p; }
  /// Where the machine stands, in the words of the other reading: called when RTCP switches on
  /// (`rtcp_on`: the machine axes of `p` become the tool tip in W) or off (the tip becomes machine
  /// axes), before the block's motion. The axes stay where they physically are; without a
  /// converter the words are carried over as they are.
  using Reframe = std::function<ProgramPoint(const ProgramPoint& p, bool rtcp_on)>;
  void on_rtcp_switch(Reframe reframe) { reframe_ = std::move(reframe); }
  std::vector<std::string> take_notices();
  /// The values of the work offsets (null: none known but the program's G10) and the control
  /// whose reading of G10 L20 and G10 L2 P0 applies (docs/formats.md "Work offsets").
  void set_work_offsets(std::shared_ptr<const WorkOffsetTable> table, cl::ControlFamily control);
  /// Applies `codes` (G codes of the modal state the control starts in, e.g. "G0 G17 G90 G94 G54")
  /// before the program's first block; `source` names where they come from (messages). Units among
  /// them are the default units, not the program's own (the units evidence still applies), and are
  /// left out where the user gave the units (`units_given`).
  void power_on(const std::string& codes, const std::string& source, bool units_given);
  const WorkFrames& work_frames() const { return frames_; }
  /// What the control's G10 L<n> sets in its tool offsets (the dialect's [input] tool_offsets).
  /// The file whose lines are applied from now on (a subprogram's file), for messages.
  void set_file(std::string file_name) { file_ = std::move(file_name); }
  void set_tool_offset_writes(std::map<int, cl::ToolOffsetWrite> writes) { tool_offset_writes_ = std::move(writes); }
  /// The machine's axis words are U V W ... (no X Y Z A B C slots).
  bool word_axes() const { return word_axes_; }
  /// What two T words in one block mean and what a coordinate without a decimal point is (--tool-words,
  /// --integer-words; cl_record.hpp). Until set: one T word, whole units.
  void set_word_rules(cl::ToolWords tool_words, cl::IntegerWords integer_words);

 private:
  struct Words;    ///< the words of one block by letter
  struct Context;  ///< the block being applied, its line, how to fail on it
  struct Codes;    ///< its G and M codes by modal group
  void notice_once(const std::string& key, int line, int column, const std::string& text);
  // the steps of apply(), in order
  Words read_words(const Context& cx) const;
  void second_tool_word(const Context& cx, const Word& word, Words& w) const;
  void check_letter(const Context& cx, const Word& word) const;
  bool has_axis_words(const Words& w) const;
  void group_g_codes(const Context& cx, const Words& w, Codes& codes);
  void group_m_codes(const Context& cx, const Words& w, Codes& codes, BlockEffect& fx);
  void apply_units(const Context& cx, const Codes& codes);
  void read_integer_words(const Context& cx, const Codes& codes, Words& w);
  void change_tool(const Context& cx, const Words& w, const Codes& codes, BlockEffect& fx);
  void apply_feed_spindle_tool(const Context& cx, const Words& w, const Codes& codes, BlockEffect& fx);
  void apply_cutter_comp(const Context& cx, const Words& w, const Codes& codes, BlockEffect& fx);
  void apply_modal_settings(const Context& cx, const Words& w, const Codes& codes, BlockEffect& fx);
  void apply_arc_distance(const Context& cx, const Codes& codes);
  void apply_work_offset(const Context& cx, const Words& w, const Codes& codes);
  void apply_g10(const Context& cx, const Words& w, const Codes& codes);
  void apply_tool_offset(const Context& cx, const Words& w, const Codes& codes, BlockEffect& fx);
  void apply_local_offset(const Context& cx, const Words& w, const Codes& codes);
  void note_moved(const Context& cx);
  std::string g10_offset_name(const Context& cx, const Words& w, int kind, int column) const;
  void apply_tool_length(const Context& cx, const Words& w, const Codes& codes, BlockEffect& fx);
  void apply_rtcp(const Context& cx, const Codes& codes);
  void check_length_in_force(const Context& cx, const Words& w, MotionMode motion, int column);
  void apply_motion_mode(const Codes& codes, BlockEffect& fx);
  void read_cycle_words(const Context& cx, const Words& w, const Codes& codes);
  void apply_motion(const Context& cx, const Words& w, const Codes& codes, BlockEffect& fx);
  /// The columns a motion's messages point at: the first axis word (else the block) and the first axis word.
  struct AxisColumns {
    int first_or_block = 0;
    int first_axis = 0;
  };
  void machine_coordinates_motion(const Context& cx, const Words& w, const Codes& codes, BlockEffect& fx);
  void intermediate_motion(const Context& cx, const Words& w, int axis_column, BlockEffect& fx);
  void programmed_motion(const Context& cx, const Words& w, const Codes& codes, AxisColumns columns, BlockEffect& fx);
  void read_dwell(const Context& cx, const Words& w, const Codes& codes, BlockEffect& fx);
  double dwell_seconds(const Context& cx, const Words& w, char letter, std::string_view code);
  void note_reference_return(const Context& cx, const Words& w, const Codes& codes, BlockEffect& fx);
  void note_machine_coordinates(const Context& cx, const Words& w, const Codes& codes, BlockEffect& fx);
  ProgramPoint motion_end(const Context& cx, const Words& w, int axis_column, BlockEffect& fx);
  void read_arc(const Context& cx, const Words& w, const Codes& codes, const ProgramPoint& end, BlockEffect& fx);
  std::string not_modal_hint() const;
  void apply_stop(const Context& cx, const Codes& codes, BlockEffect& fx);
  void apply_call(const Context& cx, const Words& w, const Codes& codes, BlockEffect& fx);

  std::string file_;
  std::string axis_letters_;
  std::array<char, 6> slots_{'X', 'Y', 'Z', 'A', 'B', 'C'};  ///< the letter of each ProgramPoint slot ('\0': none)
  std::array<bool, 6> slot_angle_{false, false, false, true, true, true};  ///< degrees in the program, rad inside
  bool word_axes_ = false;  ///< slots from the axis letters (U V W machines)
  IntegerDwell integer_dwell_ = IntegerDwell::automatic;
  ArcCentre arc_centre_option_ = ArcCentre::incremental;      ///< --arc-centre
  cl::ToolWords tool_words_ = cl::ToolWords::one;             ///< --tool-words
  cl::IntegerWords integer_words_ = cl::IntegerWords::units;  ///< --integer-words
  std::optional<IntegerWordEvidence> integer_evidence_;       ///< IntegerWords::automatic's watch (none: another rule)
  int last_arc_line_ = 0;       ///< the last arc (for the message of an arc without I J or R)
  std::string last_arc_words_;  ///< its centre words ("I and J", "R")
  ModalState state_;
  WorkFrames frames_{nullptr, {}};
  cl::ControlFamily control_ = cl::ControlFamily::unknown;
  std::map<int, cl::ToolOffsetWrite> tool_offset_writes_;
  int local_code_ = 0;  ///< 52 or 92: the word that set the local shift in force
  int local_line_ = 0;  ///< and its line
  Reframe reframe_;
  std::vector<std::string> notices_;
  std::vector<std::string> noticed_keys_;
};

}  // namespace ncpost::gcode
