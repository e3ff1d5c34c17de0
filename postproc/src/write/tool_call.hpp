// SPDX-License-Identifier: Apache-2.0
#pragma once
// How a tool change (cl::ToolChange) is written: a tool called by number keeps its number and the
// dialect's `call`; a tool called by name (Klartext TOOL CALL "name", Sinumerik T="name") keeps its
// name where the dialect calls tools by name (`call_by_name`, "{tool_name}"), else takes its number
// from the tool table (--tool-table), else is refused naming the tool and the option
// (docs/formats.md "Tool tables").
#include <optional>
#include <string>
#include <vector>

#include "ncpost/machines/input_error.hpp"
#include "ncpost/postproc/read/cl_record.hpp"
#include "ncpost/postproc/read/tool_table.hpp"
#include "ncpost/postproc/write/dialect.hpp"

namespace ncpost::detail {

struct ToolCall {
  std::optional<int> number;        ///< the number the control calls the tool by (none: by name only)
  std::vector<std::string> blocks;  ///< the dialect's call, "{tool_name}" filled in ("{tool}", "{rpm}" left)
  std::optional<double> length_mm;  ///< from the record (LOADTL) or else the tool table
  std::string length_from;          ///< where the length came from, for the program's comment
  std::string label;                ///< how messages and comments name the tool: T12, tool "DRILL 8.5"
};

/// The call of `t` in dialect `d`; InputError at `where` when the tool cannot be called there.
ToolCall tool_call_of(const cl::ToolChange& t, const Dialect& d, const ToolTable* table, const SourcePosition& where);

}  // namespace ncpost::detail
