// SPDX-License-Identifier: Apache-2.0
#pragma once
// NC program dialects: words, comments and program framing of the controls ncpost writes for,
// as data read from a dialect file (postproc/dialects/<name>.toml, README "Dialect files"). The
// post's C++ names no dialect: every difference between controls is a field here (motion words,
// feed words, block numbers, spindle, coolant, cycle and arc words), so ISO G-code and Heidenhain
// Klartext are two sets of data for one writer.
//
// Block lists are data: "{tool}" stands for the tool number and "{length}" for its length register
// (the tool's number unless the program gave another, G43 H) (`with_tool`), "{program}" for the
// program name, "{rpm}" for the spindle speed, and an entry "{comments}" in `program_start` for the
// header comments. A space-separated word whose placeholder has no value (no spindle speed yet) is
// left out. A tool change writes `rtcp_off` (if RTCP is on), `tool_call`, then `tool_length_on`
// without RTCP or `rtcp_on` with it, so every tool runs with its own length; when a block of the
// tool call names "{rpm}", the change waits for the next spindle record and takes its speed
// (Klartext `TOOL CALL 6 Z S2000`), the spindle then writes `SpindleWords::after_call`.
#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ncpost/postproc/read/cl_record.hpp"

namespace ncpost {

namespace cl {
struct Cycle;
}

/// The words of the canned drilling cycles. A kind whose word is empty has no native cycle in the
/// dialect and is expanded into explicit moves.
struct CycleWords {
  std::string drill, drill_dwell, deep, chip_break, tap, tap_left, bore, bore_dwell, bore_drag;
  bool dwell_in_ms = true;             ///< P in integer milliseconds (Fanuc, Haas), else seconds with decimals
  bool first_peck_ijk = false;         ///< G83 takes I (first peck), J (reduction), K (minimum peck): Haas
  std::string cancel = "G80";          ///< ends the modal cycle
  std::string return_initial = "G98";  ///< back to the level the cycle started from
  std::string return_r = "G99";        ///< back to the R plane
  /// Blocks before a tapping cycle starts ({rpm}: the spindle speed): Fanuc rigid tapping `M29 S{rpm}`.
  std::vector<std::string> tap_before;
  /// The word of this kind (with or without a dwell at the bottom), empty when not native.
  const std::string& word(const cl::Cycle& c) const;
};

/// G41/G42 D<n> / G40.
struct CompWords {
  std::string left = "G41", right = "G42", off = "G40";
  std::string register_letter = "D";  ///< empty: the control takes the radius of the active tool
};

/// How comments and the program name may be written (nc_text.hpp).
struct CommentRules {
  std::string replaced = "()%;";      ///< characters that must not appear in a comment ...
  std::string replacements = "[]  ";  ///< ... and what each becomes (same length as `replaced`)
  std::size_t max_chars = 120;        ///< comment text length after sanitising (longer: its middle becomes "...")
  std::size_t max_name_chars = 24;    ///< program name length
};

/// Block numbers: `format` with "{n}" for the number, from `start` by `step` ("N10 ", "N20 ";
/// Klartext "0 ", "1 ").
struct BlockNumbers {
  std::string format = "N{n} ";
  long start = 10;
  long step = 10;
  bool comments = false;  ///< comment lines numbered too (Klartext)
};

/// Motion and feed words of straight blocks.
struct MotionWords {
  std::string rapid = "G0";   ///< the motion word of a rapid (Klartext "L")
  std::string linear = "G1";  ///< the motion word of a feed move
  bool modal = true;          ///< the motion word only when it changes, else on every block
  std::string rapid_feed;     ///< word after the axes of a rapid (Klartext "FMAX"), empty: none
  bool plus_sign = false;     ///< '+' before non-negative axis values (Klartext "X+20.0000")
  std::string feed_letter = "F";
  int feed_decimals = 1;             ///< mm/min
  bool feed_modal = true;            ///< F only when it changes, else on every feed block
  std::string per_minute = "G94";    ///< feed-per-minute mode word, empty: the only mode
  std::string inverse_time = "G93";  ///< inverse-time mode word, empty: the dialect has none
  int inverse_time_decimals = 4;     ///< 1/min
};

/// Circular blocks: G2/G3 with incremental centre words in a principal plane.
struct ArcWords {
  std::string clockwise = "G2", counter_clockwise = "G3";
  std::array<std::string, 3> planes{"G17", "G18", "G19"};  ///< XY, ZX, YZ
  std::string centre_letters = "IJK";                      ///< centre − start along X, Y, Z
};

/// Spindle words: "{rpm}" the speed, "{turn}" the `clockwise` or `counter_clockwise` word.
struct SpindleWords {
  std::vector<std::string> start{"S{rpm} {turn}"};  ///< a spindle record: speed and direction
  std::vector<std::string> after_call;              ///< right after a tool call that took the speed ("{rpm}" in it)
  std::vector<std::string> stop{"M5"};
  std::string clockwise = "M3", counter_clockwise = "M4";
};

struct CoolantWords {
  std::vector<std::string> flood{"M8"}, mist{"M7"}, off{"M9"};
};
struct TiltedPlaneWords;  // below: the words of `post --tilted-plane`

struct Dialect {
  std::string name;
  std::string file;  ///< where it was read ("<built-in>/fanuc.toml" for an embedded copy)
  enum class Comments { parentheses, semicolon } comments = Comments::parentheses;
  CommentRules comment_rules;
  bool percent_framing = true;  ///< '%' first and last line
  bool line_numbers = false;    ///< numbered blocks (`numbers`)
  BlockNumbers numbers;
  MotionWords motion;
  std::optional<ArcWords> arcs;  ///< none: arcs are written as lines within the chord tolerance
  SpindleWords spindle;
  CoolantWords coolant;
  std::vector<std::string> program_start{"{comments}", "G90 G21 G94 G17 G40 G49 G80"};
  std::vector<std::string> program_end{"M30"};
  std::vector<std::string> program_stop{"M0"};           ///< a program stop (the operator resumes with cycle start)
  std::vector<std::string> program_optional_stop{"M1"};  ///< a stop only where the optional-stop switch is on
  std::vector<std::string> tool_call{"T{tool} M6"};      ///< blocks of a tool change
  /// blocks of a change to a tool called by name ("{tool_name}"); empty: the control calls tools by
  /// number only (a named tool takes its number from --tool-table)
  std::vector<std::string> tool_call_by_name;
  std::vector<std::string> tool_length_on;  ///< after the tool call without RTCP (empty: the call does it)
  std::vector<std::string> rtcp_on;         ///< RTCP/TCPM on with the tool's length
  std::vector<std::string> rtcp_off;        ///< RTCP/TCPM and the length off (before a tool change, at the end)
  /// [tool] set_offset: the blocks that set a tool offset register the input program set with G10
  /// ("{register}", "{length}", "{radius}", "{diameter}"; a block is written when one of its values
  /// is set, a word whose value is not set is left out); empty: such an input is refused.
  std::vector<std::string> tool_set_offset;
  std::vector<std::string> dwell{"G4 P{ms}"};            ///< "{ms}": milliseconds, "{s}": seconds with 3 decimals
  std::optional<CycleWords> cycles;                      ///< none: every hole as explicit moves
  std::optional<CompWords> compensation;                 ///< none: CUTCOM is refused
  int linear_decimals = 4;                               ///< mm
  int angle_decimals = 4;                                ///< deg
  std::shared_ptr<const TiltedPlaneWords> tilted_plane;  ///< none: `post --tilted-plane` writes today's blocks
  /// [input] control: how the G-code input of a re-post reads where controls differ (G10 L20, G10
  /// L2 P0); unknown: those forms are refused.
  cl::ControlFamily input_control = cl::ControlFamily::unknown;
  /// [input] power_on: the G codes of the modal state the control starts a program in ("G0 G17 G90
  /// G94 G54"), applied before a G-code input's first block; "" none.
  std::string input_power_on;
  /// [input] tool_offsets: what the control's G10 L<n> sets in its tool offsets, by n (empty: none
  /// read, G10 L1/L10-L13 refused).
  std::map<int, cl::ToolOffsetWrite> input_tool_offsets;
  /// [input] integer_words: what a coordinate without a decimal point is on this control ("units":
  /// LinuxCNC, Haas), the reading of `--integer-words auto`; absent: auto's own rule (cl_record.hpp).
  std::optional<cl::IntegerWords> input_integer_words;
};

/// The built-in dialect names, in the order of the help text.
const std::vector<std::string>& builtin_dialect_names();

/// The dialect `name_or_path`: a built-in name (fanuc, haas, linuxcnc, sinumerik, heidenhain) or
/// the path of a dialect file (anything containing '/' or ending in ".toml"). A built-in is read
/// from $NCPOST_DIALECT_DIR/<name>.toml, else <executable>/../share/ncpost/dialects/<name>.toml
/// (the installed, editable copies), else from the copy embedded at build time. Throws
/// std::invalid_argument naming the choices for an unknown name, InputError (file:line:col) for a
/// file that cannot be read or is not a valid dialect.
Dialect dialect_named(const std::string& name_or_path);

/// The dialect described by `text` (TOML), read from `file` (for messages); InputError if invalid.
Dialect parse_dialect(const std::string& text, const std::string& file);

/// `words` with every space-separated word that names `placeholder` left out ("TOOL CALL 1 Z S{rpm}"
/// before any spindle speed is "TOOL CALL 1 Z").
std::string without_word(const std::string& words, const std::string& placeholder);

/// `words` with every "{tool}" replaced by the tool number.
/// "{tool}" -> the tool number, "{length}" -> the length register (the tool's own unless given).
std::string with_tool(const std::string& words, int tool, std::optional<int> length_register = std::nullopt);

/// `words` with every `placeholder` replaced by `value`.
std::string with_value(const std::string& words, const std::string& placeholder, const std::string& value);

/// The words of a tilted work plane (3+2, `post --tilted-plane`, dialect file section
/// [tilted_plane]). `on` defines the plane and turns the rotary axes so that the tool is along its
/// Z; `off` cancels it. Placeholders: "{x}" "{y}" "{z}" the plane's origin in the program frame
/// at home (mm), "{a}" "{b}" "{c}" its three angles (deg) in the convention `angles`, "{dir}" +1
/// when the post's rotary solution has the larger first rotary angle of the two, else -1, and
/// "{rotary}" the rotary words of that solution ("A30.0000 C45.0000"). docs/conventions.md
/// "Tilted work planes" gives the frame and the conventions.
struct TiltedPlaneWords {
  /// euler_zxz: W_R_F = Rz(a) Rx(b) Rz(c) (Fanuc G68.2 I J K, Haas G268 Q313);
  /// fixed_xyz: W_R_F = Rz(c) Ry(b) Rx(a), about the fixed X, then Y, then Z (Heidenhain PLANE SPATIAL SPA SPB SPC)
  enum class Angles { euler_zxz, fixed_xyz } angles = Angles::euler_zxz;
  std::vector<std::string> on;
  std::vector<std::string> off;
};

}  // namespace ncpost
