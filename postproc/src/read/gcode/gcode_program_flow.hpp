// SPDX-License-Identifier: Apache-2.0
#pragma once
// Jumps and loops of a G-code program with macro statements (gcode_macro.hpp MacroFlow), on the
// program's line source:
//   GOTO n         the block numbered N n: searched forward to the end of the program, then from
//                  its start (as Fanuc searches); InputError when there is none
//   WHILE [c] DO m while c holds the lines up to END m run, then the WHILE is read again;
//                  otherwise the program goes on after END m. `DO m` alone loops until a GOTO
//                  leaves it.
// The input must be seekable (a file); a program that jumps more than kMaxJumps times (a loop
// that never ends) is an InputError.
#include <cstdint>
#include <string>
#include <vector>

#include "ncpost/postproc/read/gcode/gcode_macro.hpp"
#include "ncpost/postproc/read/line_source.hpp"

namespace ncpost::gcode {

class ProgramFlow {
 public:
  static constexpr long kMaxJumps = 1'000'000;

  ProgramFlow(LineSource& source, std::string file) : source_(source), file_(std::move(file)) {}

  /// Follows `flow`, the statement of the line `line_number` that starts at `line_offset`
  /// (LineSource::next_line_offset() before it was read). `first_line`: the program's first line
  /// after any leader (a backward search starts there).
  void follow(const MacroFlow& flow, std::uint64_t line_offset, int line_number, int first_line);

 private:
  struct Loop {
    int number;
    std::uint64_t offset;
    int line;
  };
  void jump_to_block(int n, int line_number, int column, int first_line);
  void skip_loop(int m, int line_number, int column);
  [[noreturn]] void fail(int line, int column, const std::string& what) const;

  LineSource& source_;
  std::string file_;
  std::vector<Loop> loops_;
  long jumps_ = 0;
};

/// The loop number m of an `END m` statement on `line` (outside comments), or -1.
int loop_end_number(std::string_view line);

}  // namespace ncpost::gcode
