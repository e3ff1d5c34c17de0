// SPDX-License-Identifier: Apache-2.0
#pragma once
// G-code input mapped back to CL records (docs/cli.md "post": INPUT may be G-code), streaming.
//
// Two kinds of program (docs/conventions.md frames M and W):
//   machine-axis program: X Y Z and the rotary words are machine commands (no RTCP); each motion
//     is mapped through the NOMINAL forward kinematics of the machine and job set-up to the tool
//     tip and tool axis in W.
//   RTCP program: X Y Z are the tool tip in W, the rotary words are machine angles; the tool axis
//     in W follows from the angles through the rotation part of the forward chain.
// In both, cl::Motion::rotary_rad carries the programmed angles (rad, machine rotary order).
// `InputKind::automatic` follows the program's own RTCP switches (M428/M429, G43.4/G49, G234/G49,
// TRAORI/TRAFOOF, M128/M129: see gcode_modal.hpp); `machine` and `rtcp` force one reading for
// every motion.
//
// Records: comments -> cl::Comment; F under G94/G95 -> cl::Feed (mm/min or mm/rev); S/M3/M4/M5 ->
// cl::Spindle; M6 -> cl::ToolChange (the last T); M7/M8/M9 -> cl::Coolant; G0 -> Motion with
// rapid; G1 -> Motion; under G93 motions carry inverse_time and feed (1/min); M2/M30 -> cl::End
// (the rest of the file is ignored, as controls do); M0/M1 -> cl::Stop (after the block's motion);
// dwell, G28/G30, M60 and unknown M codes -> cl::Unsupported with a notice.
// Arcs (G2/G3, also helical, with P turns) are expanded into points: equal angle steps with a
// chord error <= `arc_chord_tolerance_mm` (1 µm by default), interpolated in program space (the
// control's motion) and then mapped like any motion; under G93 each of the n segments gets
// n x F so that the arc still takes 1/F minutes.
// Units: G20 (inch) lengths and feeds are converted to mm; rotary words are degrees.
// Limits: a motion whose machine commands lie beyond an axis limit is Infeasible (exit 3), in
// every InputKind (GcodeReaderOptions::check_limits).
// Start: rapids before every axis is programmed are held and take the axes' first programmed
// values (no rapid to 0 the source never made); a feed motion, an arc or the end first releases
// them with 0 for the axes still unknown (notice).
// G93: each inverse-time motion is preceded by the cl::Feed max(tip path mm, rotary travel deg)
// x F, with which the post's block time is the source's 1/F minutes.
// Rollover: on a continuous rotary axis whose values stay within 0 .. 360 deg, a jump of more
// than 180 deg turns the short way across 0 (C359.857 -> C367.501, notice); a value outside
// 0 .. 360 marks a turn-counting program, followed as written.
// Units: with no units word and X/Y/Z mostly written with 4 decimals within a 50-unit box, a
// notice says the program looks like inches.
// CutterComp: G41/G42 (D: the register)/G40 records precede the motion of their block.
// Program framing: a leading '%' requires a closing '%' or M2/M30 (otherwise the file is taken
// as truncated: InputError); text after the closing '%' is ignored, and so are lines before the
// opening '%' that hold no motion (a leader, looked for in the first 64 KiB; notice; the rules
// and the refusals of NX's "Information listing" and of motions on both sides of the first '%'
// are in gcode_framing.hpp). A UTF-8 byte order mark is skipped. Blocks starting with '/' are
// skipped while `block_delete` is on. A program that moves nothing while a line of the file has
// motion words (in a deleted block, a leader, after the end) is an InputError, never an empty
// output.
#include <functional>
#include <istream>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "ncpost/kinematics/forward.hpp"
#include "ncpost/kinematics/machine.hpp"
#include "ncpost/postproc/read/cl_record.hpp"
#include "ncpost/postproc/read/gcode/gcode_modal.hpp"

namespace ncpost::gcode {

enum class InputKind { automatic, machine, rtcp };

/// "auto", "machine" or "rtcp" (as the CLI writes them); nullopt otherwise.
std::optional<InputKind> parse_input_kind(std::string_view text);

struct GcodeReaderOptions {
  InputKind kind = InputKind::automatic;
  bool default_inch = false;  ///< G20 in force at the start (G21 otherwise)
  bool units_given = false;   ///< the user gave the units (--units): a program without G20/G21 is not questioned
  bool block_delete = true;   ///< skip blocks that start with '/'
  IntegerDwell integer_dwell = IntegerDwell::automatic;  ///< the unit of a dwell time without a decimal point
  ArcCentre arc_centre = ArcCentre::incremental;         ///< what I J K of G2/G3 give (until G90.1/G91.1)
  cl::ToolWords tool_words = cl::ToolWords::one;         ///< what two T words in one block mean (--tool-words)
  /// what a coordinate without a decimal point is (--integer-words, whose default is `automatic`; the dialect's
  /// [input] integer_words replaces `automatic` where it gives one)
  cl::IntegerWords integer_words = cl::IntegerWords::units;
  double arc_chord_tolerance_mm = 1e-3;  ///< chord error bound of expanded arcs
  /// Every motion's machine commands (machine program: the words; RTCP: the linear axes that put
  /// the tip there at the programmed angles) must lie within the machine's axis limits, else
  /// Infeasible (exit 3) naming the line, the axis and the limit. Off only to study a reading.
  bool check_limits = true;
  /// Single-turn planar arcs with the rotary axes still (not under G93) become a cl::Circle and
  /// their end motion, which the post writes as G2/G3; otherwise every arc is expanded into points.
  bool circles = false;
  /// The values of the work offsets (--work-offsets; null: none) and the control whose reading
  /// of G10 L20 and G10 L2 P0 applies (work_frames.hpp).
  std::shared_ptr<const WorkOffsetTable> work_offsets;
  cl::ControlFamily control = cl::ControlFamily::unknown;
  /// What the control's G10 L<n> sets in its tool offsets (cl::ReaderOptions::tool_offset_writes).
  std::map<int, cl::ToolOffsetWrite> tool_offset_writes;
  /// Where subprograms in other files are looked for before the program's directory ("" none;
  /// docs/formats.md "Subprograms in other files").
  std::string subprogram_dir;
  /// The modal state the control starts in ("G0 G17 G90 G94 G54", Interpreter::power_on) and where it
  /// was given; the posted program's header names it. "" none: the program must set what it uses.
  std::string power_on, power_on_source;
  /// A machine whose words are not a serial chain's (the TRR-XY machine: X Y U V W, all lengths):
  /// `machine.axes` lists the words in program order (their letters and limits), and this maps the
  /// words (AxisPosition slots, mm) to the tool tip and axis in W; nullopt, with `why`, where the
  /// machine has no pose. Arcs, canned cycles and RTCP programs are then input errors.
  std::function<std::optional<ToolPoseT<double>>(const AxisPosition& words, std::string* why)> word_forward;

  /// Empty when valid, else what is wrong.
  std::string validate() const;
};

class GcodeClReader final : public cl::Reader {
 public:
  /// Reads `in` (which must outlive the reader). Throws std::invalid_argument for invalid options.
  GcodeClReader(std::istream& in, std::string file_name, const Machine& machine, const Setup& setup,
                GcodeReaderOptions options = {});
  ~GcodeClReader() override;

  std::optional<cl::Record> next() override;
  std::vector<std::string> take_notices() override;
  std::vector<std::string> header_notes() const override;

  /// Whether the last motion returned was read as an RTCP (tool-tip) motion.
  bool last_motion_rtcp() const;
  /// Lines read so far.
  int lines_read() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

/// Opens and reads a file; InputError (exit code 2) when it cannot be opened.
std::unique_ptr<cl::Reader> open_gcode(const std::string& path, const Machine& machine, const Setup& setup,
                                       GcodeReaderOptions options = {});

}  // namespace ncpost::gcode
