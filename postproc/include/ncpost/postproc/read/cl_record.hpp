// SPDX-License-Identifier: Apache-2.0
#pragma once
// The records of a CL (cutter location) program as the post acts on them, independent of the
// source format (APT CL source from NX, CATIA, Creo; G-code mapped back to CL).
//
// Units: every length is in mm and every angle in degrees *as written* is converted by the
// reader: positions in mm in W, tool axis unit vectors in W, feeds in mm/min (or mm/rev).
// Every record carries the position of its first character in the source.
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "ncpost/kinematics/machine.hpp"
#include "ncpost/machines/input_error.hpp"

namespace ncpost {
struct ToolTable;  // ncpost/postproc/read/tool_table.hpp
}
namespace ncpost::gcode {
struct WorkOffsetTable;  // ncpost/postproc/read/gcode/work_offsets.hpp
}

namespace ncpost::cl {

struct Location {
  int line = 0;    ///< 1-based line of the record's first character
  int column = 0;  ///< 1-based column
};

/// GOTO / FROM / GODLTA (made absolute), one motion. `rapid` for the motion after RAPID.
struct Motion {
  Location where;
  ClPoint point;            ///< tip in mm in W, unit axis in W (the last axis when the record had none)
  bool axis_given = false;  ///< the record carried i, j, k
  bool rapid = false;
  bool from = false;  ///< FROM: the start position, no cutting
  /// Rotary angles programmed in G-code input (rad, machine rotary order); the post keeps them
  /// instead of choosing a solution itself (RTCP programs, re-posted machine-axis programs).
  std::optional<RotaryAngles> rotary_rad;
  bool inverse_time = false;   ///< G93 was active: `feed` of this motion is 1/min
  std::optional<double> feed;  ///< a feed word on this block (mm/min, or 1/min under G93)
};

struct Feed {
  Location where;
  double value = 0.0;  ///< mm/min, or mm/rev when per_rev
  bool per_rev = false;
};

struct Spindle {
  Location where;
  enum class Direction { cw, ccw, off } direction = Direction::cw;
  double rpm = 0.0;
};

struct Coolant {
  Location where;
  bool on = true;
  std::string mode;  ///< FLOOD, MIST, THRU, ... as written
};

/// A tool change: to tool `number`, or, where `name` is not empty, to the tool the control's tool
/// table names so (Klartext `TOOL CALL "name"`, Sinumerik `T="name"`; `number` is then 0): the
/// post writes the name where its dialect calls tools by name, else the number `--tool-table`
/// gives it (tool_table.hpp), else it refuses.
struct ToolChange {
  Location where;
  int number = 0;
  std::optional<double> length_mm;  ///< from LOADTL/n,LENGTH,l or TLDATA where given
  std::string name;                 ///< the tool's name as written, "" when called by number
};

/// G43 H<n> of G-code input: the tool's length from register n (the post writes it where n is not
/// the length already in force, e.g. not the tool's own register after its change).
struct LengthOffset {
  Location where;
  int register_number = 0;
};

/// G10 L1/L10/L12 ... of G-code input (docs/formats.md "Tool offsets"): the program sets the length
/// and/or the radius of offset register `register_number` (on LinuxCNC the tool table's entry of
/// tool `register_number`), which a later G43 H / G41 D uses. The post writes it again with its
/// dialect's [tool] set_offset blocks, or refuses where the dialect has none.
struct ToolOffset {
  Location where;
  int register_number = 0;
  std::optional<double> length_mm;  ///< the tool length set (mm)
  std::optional<double> radius_mm;  ///< the cutter radius set (mm; a diameter is halved)
  std::string text;                 ///< the block as written
};

/// CIRCLE/xc,yc,zc,i,j,k,r,...: the next Motion ends the arc (centre and axis in W, mm).
struct Circle {
  Location where;
  Vec3d center_mm = Vec3d::Zero();
  Vec3d axis = Vec3d::UnitZ();  ///< the tool moves counter-clockwise about it (normalised by the reader)
  double radius_mm = 0.0;
  /// Whole turns about the axis before the arc to the end point (NX `CIRCLE/...,TIMES,n`: n - 1);
  /// the motion rises or sinks along the axis at one pitch over all of them (a helix).
  int extra_turns = 0;
};

/// CYCLE/DRILL|DEEP|TAP|BORE|... (OFF ends it); the GOTOs that follow are the holes. Every
/// distance is along the tool axis from each hole's GOTO point (the hole top): the R plane
/// `rapid_to_mm` above it, the bottom `depth_mm` below it, the retract plane `retract_mm` above it.
/// Read from NX/CATIA APT (RAPTO, FEDTO, RTRCTO, STEP), Creo (DEPTH, CLEAR, TPI) and SOLIDWORKS CAM
/// (FEDTO, RAPTO, RTRCTO, 1STPECK, SUBPECK, INCR) by apt_cycle.cpp, or from G73–G89 G-code input.
struct Cycle {
  Location where;
  enum class Kind {
    off,
    drill,       ///< feed to depth (dwell_s > 0: dwell there), rapid out: G81 / G82
    deep,        ///< peck drilling, full retract after each peck: G83
    chip_break,  ///< peck drilling, short retract after each peck: G73
    tap,         ///< rigid/floating tap: feed in, reverse the spindle, feed out: G84 (G74 left hand)
    bore,        ///< feed in, feed out (also REAM): G85 (dwell_s > 0: G89)
    bore_drag,   ///< feed in, spindle stop, rapid out: G86
  } kind = Kind::off;
  std::string kind_word;             ///< the cycle's words as written (DEEP2, DRILL DEEP, ...)
  double depth_mm = 0.0;             ///< the bottom below the GOTO point
  double rapid_to_mm = 0.0;          ///< the R plane above the GOTO point (feed starts there)
  std::optional<double> retract_mm;  ///< the plane above the GOTO point the tool returns to (none: the R plane)
  double first_peck_mm = 0.0;        ///< first peck (0: `peck_mm`)
  double peck_mm = 0.0;              ///< (subsequent) peck depth; 0 for kinds without pecks
  std::optional<double> feed;  ///< the cycle's own feed (mm/min, or mm/rev when feed_per_rev); none: the feed in force
  bool feed_per_rev = false;
  double dwell_s = 0.0;    ///< dwell at the bottom
  double pitch_mm = 0.0;   ///< thread pitch (tap): PITCH, or 25.4 / TPI
  bool left_hand = false;  ///< left-hand tap (spindle counter-clockwise in)
  std::string text;        ///< the record as written
};

/// CUTCOM/LEFT|RIGHT|OFF (APT) or G41/G42/G40 (G-code): cutter radius compensation in the
/// plane normal to the tool axis, from the next motion on. `offset_register`: the D number where
/// the source names one (CUTCOM/LEFT,5 or G41 D5).
struct CutterComp {
  Location where;
  enum class Side { off, left, right } side = Side::off;
  std::optional<int> offset_register;
  std::string text;  ///< the record as written
};

/// PPRINT, PARTNO, INSERT, `$$` comments and anything passed through as a comment.
struct Comment {
  Location where;
  std::string text;
};

/// A statement the post does not act on: passed through as a comment with a notice.
struct Unsupported {
  Location where;
  std::string text;
};

/// Longest dwell accepted from any reader (s): a day; anything longer is a slip.
inline constexpr double kMaxDwellSeconds = 86400.0;

/// A dwell: the tool stands still for `seconds` (G-code G4 with an unambiguous time, APT DELAY).
struct Dwell {
  Location where;
  double seconds = 0.0;
};

/// A program stop after the motion before it (APT STOP, OPSTOP, AUXFUN/0, AUXFUN/1; G-code M0,
/// M1): the machine stands until the operator presses cycle start. `optional`: only where the
/// control's optional-stop switch is on (OPSTOP, M1). `text`: a message for the operator
/// (CATIA STOP/(text)), "" when none.
struct Stop {
  Location where;
  bool optional = false;
  std::string text;
};

/// END-OF-PATH, FINI, END: the end of an operation or of the program.
struct End {
  Location where;
  bool program = false;  ///< FINI: end of the whole program
};

using Record = std::variant<Motion, Feed, Spindle, Coolant, ToolChange, LengthOffset, Circle, Cycle, CutterComp,
                            Comment, Unsupported, Dwell, Stop, End, ToolOffset>;

/// Where a record starts.
inline Location location_of(const Record& r) {
  return std::visit([](const auto& x) { return x.where; }, r);
}

/// G-code: the unit of a dwell time written without a decimal point (G4 P or X, the P of
/// G82/G89): milliseconds on Fanuc and Haas, seconds on LinuxCNC. A time with a decimal point is
/// seconds everywhere. `automatic` reads 100 and more as milliseconds (as seconds it would be a
/// dwell of minutes), 0 as no dwell, and refuses 1 to 99, which both readings make plausible.
enum class IntegerDwell { automatic, milliseconds, seconds };

/// G-code: what the I J K of a G2/G3 give (docs/cli.md, --arc-centre). `incremental`: the vector
/// from the start to the centre (RS274NGC, Fanuc, Haas; G91.1); `centre_to_start`: the vector from
/// the centre to the start (some NX posts for older controls); `absolute`: the centre's coordinates
/// (G90.1). The program's G90.1 or G91.1 switches `incremental` and is refused beside another.
enum class ArcCentre { incremental, centre_to_start, absolute };

/// G-code: what two T words in one block mean (docs/cli.md, --tool-words). `one`: a block has at most
/// one T word (a second is refused, naming the option); `load_next`: with M06, the first is the tool
/// this change loads and the second the tool pre-selected for the next change (Mazak; NX's Mazak
/// posts write `T01 T02 M06`), which that change must then load.
enum class ToolWords { one, load_next };

/// G-code: what a coordinate written without a decimal point is (docs/cli.md, --integer-words):
/// `units` whole mm / inches / degrees (LinuxCNC, grbl, Haas, a Fanuc with parameter DPI = 1);
/// `increments` least input increments of IS-B (0.001 mm, 0.0001 in, 0.001 deg: a Fanuc with DPI = 0);
/// `automatic` units, unless the program also writes whole numbers with a decimal point (`X20.`
/// and `X20`): then refused, naming both lines and the option (docs/choices.md).
enum class IntegerWords { automatic, units, increments };

/// Options of every CL reader.
/// The control family whose reading of a G-code program applies where controls differ (G10 L20:
/// Fanuc and Haas set an extended offset's value, LinuxCNC makes the current position read the value).
enum class ControlFamily { unknown, fanuc, linuxcnc };

/// G-code: what a control's G10 L<n> P<register> sets in its tool offsets (the dialect's [input]
/// tool_offsets, by L): Fanuc L10 length, L11 length wear, L12 radius, L13 radius wear; Haas L10
/// length, L1/L11 length wear, L12 diameter, L13 diameter wear; LinuxCNC L1 the tool table (Z the
/// length, R the radius), L10/L11 the length that makes the current position read Z.
enum class ToolOffsetWrite {
  length,
  length_wear,
  radius,
  radius_wear,
  diameter,
  diameter_wear,
  tool_table,
  length_reading
};

struct ReaderOptions {
  bool default_inch = false;  ///< the units of a file that does not say (UNITS/... overrides)
  bool units_given = false;   ///< `default_inch` is the user's word (--units), not the default
  /// Accept a file that ends without FINI / END / END-OF-PATH (otherwise: "truncated?", exit 2).
  bool allow_unterminated = false;
  /// NX MSYS (the MCS the GOTOs are written in, given in the part's absolute frame):
  /// `ignore` posts the GOTOs as written, W = the MCS (what NX's own posts do; a file whose MSYS
  /// changes between operations is refused); `apply` maps every position and axis through the
  /// current MSYS into the absolute frame, W = the absolute frame.
  enum class Msys { ignore, apply } msys = Msys::ignore;
  IntegerDwell integer_dwell = IntegerDwell::automatic;  ///< G-code: the unit of a dwell time without a decimal point
  ArcCentre arc_centre = ArcCentre::incremental;         ///< G-code: what I J K of an arc give
  ToolWords tool_words = ToolWords::one;                 ///< G-code: what two T words in one block mean
  IntegerWords integer_words = IntegerWords::automatic;  ///< G-code: a coordinate without a decimal point
  /// Largest distance (mm) between a curve the file describes (NURBS) and the chords posted for it.
  double curve_tolerance_mm = 0.01;
  ControlFamily control = ControlFamily::unknown;  ///< G-code: the control the program was written for
  /// G-code: the modal state the control starts in ("G0 G17 G90 G94 G54"; "" none) and where it
  /// was given (for messages and the program's header).
  std::string power_on, power_on_source;
  /// G-code: the values of the work offsets (`--work-offsets FILE`); null: none given.
  std::shared_ptr<const gcode::WorkOffsetTable> work_offsets;
  /// G-code: what G10 L<n> sets in the tool offsets, by n (the dialect's [input] tool_offsets; empty:
  /// every G10 tool-offset form is refused).
  std::map<int, ToolOffsetWrite> tool_offset_writes;
  /// G-code: where `M98 P<n>` and `o<name> call` look for a subprogram the program's file does not
  /// hold, before the program's own directory (--subprogram-dir; "" none).
  std::string subprogram_dir;
  /// Klartext: the tools' diameters (`--tool-table FILE`, CYCL DEF 208); null: none given.
  std::shared_ptr<const ToolTable> tool_table;
};

/// A pull-style stream of records; readers stream so memory stays flat in the input size.
/// Bad input throws InputError (file:line:column, what was expected).
class Reader {
 public:
  virtual ~Reader() = default;
  virtual std::optional<Record> next() = 0;
  /// Notices gathered so far (unsupported statements, ignored words), with their position.
  virtual std::vector<std::string> take_notices() { return {}; }
  /// What the posted program's header should say about how the input was read (e.g. the power-on
  /// modal state a G-code input was read from); known before the first record.
  virtual std::vector<std::string> header_notes() const { return {}; }
  /// What in the input most likely explains a failure to post it ("" if nothing), for the
  /// message of that failure (e.g. an NX MSYS that rotates the MCS, posted as written).
  virtual std::string failure_hint() const { return {}; }
};

}  // namespace ncpost::cl
