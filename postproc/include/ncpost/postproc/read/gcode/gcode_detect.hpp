// SPDX-License-Identifier: Apache-2.0
#pragma once
// Telling G-code from APT CL data, and RTCP programs from machine-axis programs, by content.
#include <istream>
#include <string>
#include <string_view>

#include "ncpost/postproc/read/gcode/gcode_cl_reader.hpp"

namespace ncpost::gcode {

/// True when the first lines of `head` read as RS274 blocks with at least one G, M or axis word
/// (APT statements such as `GOTO/...` do not).
bool looks_like_gcode(std::string_view head);

/// `rtcp` when the program switches RTCP on anywhere (M428, G43.4, G43.5, G234, TRAORI, M128),
/// else `machine`. Reads the whole stream (lexically only; a syntax error ends the scan, the
/// reader reports it).
InputKind scan_input_kind(std::istream& in, const std::string& file_name);

}  // namespace ncpost::gcode
