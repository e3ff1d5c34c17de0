// SPDX-License-Identifier: Apache-2.0
#pragma once
// NC program dialects: words, comments and program framing of the controls ncpost writes for,
// as data read from a dialect file (postproc/dialects/<name>.toml, README "Dialect files"). The
// post's C++ names no dialect: every difference between controls is a field here.
// Output is ISO G-code (RS274 family) unless `klartext` (Heidenhain conversational L blocks).
//
// Block lists are data: "{tool}" stands for the tool number (`with_tool`), "{program}" for the
// program name, and an entry "{comments}" in `program_start` for the header comments. A tool change
// writes `rtcp_off` (if RTCP is on), `tool_call`, then `tool_length_on` without RTCP or `rtcp_on`
// with it, so every tool runs with its own length.
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ncpost {

namespace cl {
struct Cycle;
}

/// The words of the canned drilling cycles. A kind whose word is empty has no native cycle in the
/// dialect and is expanded into explicit moves.
struct CycleWords {
  std::string drill, drill_dwell, deep, chip_break, tap, tap_left, bore, bore_dwell, bore_drag;
  bool dwell_in_ms = true;       ///< P in integer milliseconds (Fanuc, Haas), else seconds with decimals
  bool first_peck_ijk = false;   ///< G83 takes I (first peck), J (reduction), K (minimum peck): Haas
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

struct TiltedPlaneWords;  // below: the words of `post --tilted-plane`

struct Dialect {
  std::string name;
  std::string file;                ///< where it was read ("<built-in>/fanuc.toml" for an embedded copy)
  enum class Comments { parentheses, semicolon } comments = Comments::parentheses;
  CommentRules comment_rules;
  bool percent_framing = true;     ///< '%' first and last line
  bool line_numbers = false;       ///< N words (Klartext: 0, 1, ...)
  bool klartext = false;           ///< Heidenhain conversational (L X.. Y.. FMAX)
  std::vector<std::string> program_start{"{comments}", "G90 G21 G94 G17 G40 G49 G80"};
  std::vector<std::string> program_end{"M30"};
  std::vector<std::string> tool_call{"T{tool} M6"};  ///< blocks of a tool change
  std::vector<std::string> tool_length_on;  ///< after the tool call without RTCP (empty: the call does it)
  std::vector<std::string> rtcp_on;         ///< RTCP/TCPM on with the tool's length
  std::vector<std::string> rtcp_off;        ///< RTCP/TCPM and the length off (before a tool change, at the end)
  std::vector<std::string> dwell{"G4 P{ms}"};  ///< "{ms}": milliseconds, "{s}": seconds with 3 decimals
  std::optional<CycleWords> cycles;         ///< none: every hole as explicit moves
  std::optional<CompWords> compensation;    ///< none: CUTCOM is refused
  int linear_decimals = 4;         ///< mm
  int angle_decimals = 4;          ///< deg
  std::shared_ptr<const TiltedPlaneWords> tilted_plane;  ///< none: `post --tilted-plane` writes today's blocks
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

/// `words` with every "{tool}" replaced by the tool number.
std::string with_tool(const std::string& words, int tool);

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
