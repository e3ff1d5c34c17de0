// SPDX-License-Identifier: Apache-2.0
#pragma once
// G10 blocks that set a tool offset from within the program (docs/formats.md "Tool offsets"). The
// same L numbers mean different things on different controls, so what each sets comes from the
// dialect's [input] tool_offsets (cl::ToolOffsetWrite), not from the reader:
//   Fanuc (memory C)  G10 L10 P<h> R<length>   G10 L12 P<d> R<radius>    (L11, L13: wear)
//   Haas              G10 L10 P<h> R<length>   G10 L12 P<d> R<diameter>  (L1, L11, L13: wear)
//   LinuxCNC          G10 L1 P<tool> Z<length> R<radius>   (L10, L11: the length that makes the
//                     current position read Z)
// The geometry forms become a cl::ToolOffset (values in mm, a diameter halved) that the post writes
// again; wear (which adds to a value the program does not give), a length set from where Z stands,
// a form the dialect does not name, G10 under G91 (Fanuc adds, LinuxCNC sets) and words the form
// does not take are InputErrors naming the block.
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "ncpost/postproc/read/cl_record.hpp"

namespace ncpost::gcode {

/// A word of the block: its value (program units) and 1-based column.
struct ToolOffsetWord {
  double value = 0.0;
  int column = 0;
};

/// The G10 block as read.
struct ToolOffsetBlock {
  int l = 0;
  int column = 0;  ///< of the G10
  std::optional<ToolOffsetWord> p, r, z;
  char other = 0;  ///< a further letter the block holds besides G L N P R Z ('\0': none)
  int other_column = 0;
  bool incremental = false;  ///< G91 in force
  double mm_per_unit = 1.0;  ///< 25.4 under G20
};

/// Whether G10 L<l> is one of the tool-offset forms (L1, L10 .. L13) on some control.
bool is_tool_offset_form(double l);

/// The record of `b` as `writes` reads it; InputError at `file`:`line` (with `text`) otherwise.
cl::ToolOffset read_tool_offset(const std::map<int, cl::ToolOffsetWrite>& writes, const ToolOffsetBlock& b,
                                const std::string& file, int line, std::string_view text);

}  // namespace ncpost::gcode
