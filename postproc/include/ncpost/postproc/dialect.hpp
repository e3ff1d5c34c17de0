// SPDX-License-Identifier: Apache-2.0
#pragma once
// NC program dialects: words, comments and program framing of the controls ncpost writes for.
// Output is ISO G-code (RS274 family) except Heidenhain, which gets Klartext L blocks.
//
// Tool words are data: each entry is a list of blocks in which "{tool}" stands for the tool
// number (`with_tool`). A tool change writes `rtcp_off` (if RTCP is on), `tool_call`, then
// `tool_length_on` without RTCP or `rtcp_on` with it, so every tool runs with its own length.
#include <string>
#include <vector>

namespace ncpost {

struct Dialect {
  std::string name;
  enum class Comments { parentheses, semicolon } comments = Comments::parentheses;
  bool percent_framing = true;     ///< '%' first and last line
  bool line_numbers = false;       ///< N words
  bool klartext = false;           ///< Heidenhain conversational (L X.. Y.. FMAX)
  std::vector<std::string> tool_call{"T{tool} M6"};  ///< blocks of a tool change
  std::vector<std::string> tool_length_on;  ///< after the tool call without RTCP (empty: the call does it)
  std::vector<std::string> rtcp_on;         ///< RTCP/TCPM on with the tool's length
  std::vector<std::string> rtcp_off;        ///< RTCP/TCPM and the length off (before a tool change, at the end)
  std::string program_end = "M30";
  int linear_decimals = 4;         ///< mm
  int angle_decimals = 4;          ///< deg
};

/// The dialect of this name (fanuc, haas, linuxcnc, sinumerik, heidenhain); throws
/// std::invalid_argument naming the choices for an unknown name.
Dialect dialect_named(const std::string& name);

/// `words` with every "{tool}" replaced by the tool number.
std::string with_tool(const std::string& words, int tool);

}  // namespace ncpost
