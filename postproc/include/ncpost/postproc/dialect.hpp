#pragma once
// NC program dialects: words, comments and program framing of the controls ncpost writes for.
// Output is ISO G-code (RS274 family) except Heidenhain, which gets Klartext L blocks.
#include <string>

namespace ncpost {

struct Dialect {
  std::string name;
  enum class Comments { parentheses, semicolon } comments = Comments::parentheses;
  bool percent_framing = true;     ///< '%' first and last line
  bool line_numbers = false;       ///< N words
  bool klartext = false;           ///< Heidenhain conversational (L X.. Y.. FMAX)
  std::string rtcp_on;             ///< word(s) switching RTCP/TCPM on
  std::string rtcp_off;
  std::string program_end = "M30";
  int linear_decimals = 4;         ///< mm
  int angle_decimals = 4;          ///< deg
};

/// The dialect of this name (fanuc, haas, linuxcnc, sinumerik, heidenhain); throws
/// std::invalid_argument naming the choices for an unknown name.
Dialect dialect_named(const std::string& name);

}  // namespace ncpost
