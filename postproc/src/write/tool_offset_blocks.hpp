// SPDX-License-Identifier: Apache-2.0
#pragma once
// How a tool offset the input program set (cl::ToolOffset, G10 L1/L10/L12 of G-code input) is
// written: the dialect's [tool] set_offset blocks with "{register}", "{length}", "{radius}" and
// "{diameter}" filled in (lengths with the dialect's decimals). A block is written when one of its
// values is set; a word whose value is not set is left out (LinuxCNC's `G10 L1 P1 R3` keeps the
// length). A dialect without set_offset (sinumerik, heidenhain: the tool table is the control's)
// cannot carry it: InputError at the record, naming the dialects that can.
#include <string>

#include "ncpost/postproc/read/cl_record.hpp"
#include "ncpost/postproc/write/nc_writer.hpp"

namespace ncpost::detail {

/// Writes `t` with `writer`'s dialect; `input` names the input file for the error.
void write_tool_offset(NcWriter& writer, const cl::ToolOffset& t, const std::string& input);

/// The words of one set_offset block for `t` ("" when none of its values is set): exposed for tests.
std::string tool_offset_block(const std::string& pattern, const cl::ToolOffset& t, const NcWriter& writer);

}  // namespace ncpost::detail
