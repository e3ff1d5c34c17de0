// SPDX-License-Identifier: Apache-2.0
#pragma once
// The tool table of a job (`post --tool-table FILE`, docs/formats.md "Tool tables"): for each tool
// a program calls by name (Klartext `TOOL CALL "name"`, Sinumerik `T="name"`), the number the
// posted program calls it by on a control that selects tools by number, and optionally its length
// (mm, from the spindle gauge point to the tip).
//
// File (TOML): one table [tools] whose keys are the names exactly as the programs write them
// (case and blanks count), each either a number or an inline table:
//     [tools]
//     "DRILL 8.5" = 12
//     "FRA-P15251-S15.2R0" = { number = 3, length = 154.0 }
// Numbers are whole, 0 .. 999999999, and no two names share one; lengths are mm, > 0 and finite.
#include <map>
#include <optional>
#include <string>

namespace ncpost {

struct ToolTableEntry {
  int number = 0;
  std::optional<double> length_mm;    ///< the tool's length, where the file gives it
  std::optional<double> diameter_mm;  ///< the tool's diameter, where the file gives it (Klartext CYCL DEF 208)
  int line = 0;                       ///< where the file gives it
};

struct ToolTable {
  std::string file;                               ///< where it was read (for messages)
  std::map<std::string, ToolTableEntry> by_name;  ///< keyed by the name as written
};

/// Reads a tool table from `text`; InputError at file:line:column when malformed.
ToolTable parse_tool_table(const std::string& text, const std::string& file);

/// Reads a file; InputError (exit 2) when it cannot be opened or is malformed.
ToolTable load_tool_table(const std::string& path);

}  // namespace ncpost
