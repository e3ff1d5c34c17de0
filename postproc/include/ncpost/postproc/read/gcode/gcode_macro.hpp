// SPDX-License-Identifier: Apache-2.0
#pragma once
// The macro statements of one G-code line (Fanuc Macro B, RS274NGC parameters), evaluated with
// gcode_expression.hpp before the block grammar reads the line:
//   `#1 = expr`, `#<name> = expr`        assignment (several per line: applied after the whole
//                                         line is read, as RS274NGC does)
//   `X#24`, `X-#1`, `X[#510+1]`, `G#1`   a word whose value is an expression: replaced by its
//                                         number, padded with blanks so that the columns after it
//                                         stay where they were whenever the number is not longer
//   `IF [cond] GOTO n`, `GOTO n`         jumps (MacroFlow; the reader searches block N n)
//   `IF [cond] THEN #1 = expr`           a conditional assignment
//   `WHILE [cond] DO m`, `DO m`, `END m` loops (MacroFlow)
// Comments are copied as they are. Errors are InputError at the line and column.
#include <string>
#include <string_view>

#include "ncpost/postproc/read/gcode/gcode_expression.hpp"

namespace ncpost::gcode {

/// A control statement of the line.
struct MacroFlow {
  enum class Kind { none, go_to, while_do, end_loop } kind = Kind::none;
  int number = 0;         ///< GOTO's block number; DO's and END's loop number
  bool condition = true;  ///< WHILE's condition (DO alone: true)
  int column = 0;         ///< 1-based column of the statement
};

/// Whether `line` may hold macro statements ('#', '[', or a statement keyword): lines without
/// them are read as they are (the fast path).
bool may_hold_macro(std::string_view line);

/// Applies the macro statements of `line` to `params` and writes into `out` the line the block
/// grammar reads. Returns the line's control statement. Throws InputError naming `file` and
/// `line_number`.
MacroFlow apply_macro_line(std::string_view line, Parameters& params, std::string& out, const std::string& file,
                           int line_number);

}  // namespace ncpost::gcode
