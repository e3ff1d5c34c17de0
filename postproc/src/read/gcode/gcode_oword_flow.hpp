// SPDX-License-Identifier: Apache-2.0
#pragma once
// LinuxCNC o-word control flow on the program's line source (gcode_oword.hpp reads a statement):
//   o1 sub ... o1 endsub             a definition: skipped where the program reaches it
//   o1 call [a] [b]                  the sub with #1 #2 ... (gcode_subprogram_calls.hpp)
//   o1 return / o1 endsub            back to the caller
//   o2 if [c] ... o2 elseif [c] ... o2 else ... o2 endif
//   o3 while [c] ... o3 endwhile     the condition before every turn
//   o4 do ... o4 while [c]           the condition after every turn
//   o5 repeat [n] ... o5 endrepeat   n turns
//   o3 break, o3 continue            leave the loop o3, or go on with its next turn
// Conditions and counts are expressions (gcode_expression.hpp); a vacant value is an error. More
// than kMaxJumps jumps (a loop that never ends) is an input error.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "ncpost/postproc/read/gcode/gcode_expression.hpp"
#include "ncpost/postproc/read/line_source.hpp"
#include "read/gcode/gcode_oword.hpp"
#include "read/gcode/gcode_subprogram_calls.hpp"

namespace ncpost::gcode {

class OWordFlow {
 public:
  static constexpr long kMaxJumps = 1'000'000;

  OWordFlow(LineSource& source, std::string file, Parameters& params, SubprogramCalls& calls)
      : source_(source), file_(std::move(file)), params_(params), calls_(calls) {}

  /// Follows the statement `w` of `line` (line number `line_number`, starting at `line_offset`);
  /// the source stands after the line.
  void follow(const OWord& w, std::string_view line, std::uint64_t line_offset, int line_number);

 private:
  enum class LoopKind { while_, do_, repeat };
  struct Loop {
    std::string label;
    LoopKind kind;
    std::uint64_t offset;  ///< while: its own line; do, repeat: the first line of the body
    int line;
    long left = 0;  ///< repeat: turns still to run
  };
  using K = OWord::Keyword;

  double value_at(std::string_view line, std::size_t at, int line_number, const OWord& w) const;
  std::vector<ParamValue> arguments(std::string_view line, std::size_t at, int line_number, const OWord& w) const;
  /// Reads on to the statement of `label` with one of `keywords` (its text in `found_line_`).
  OWord skip_to(const std::string& label, std::initializer_list<K> keywords, int line_number, const OWord& from);
  void follow_if(const OWord& w, std::string_view line, int line_number);
  void follow_while(const OWord& w, std::string_view line, std::uint64_t line_offset, int line_number);
  void follow_loop_end(const OWord& w, int line_number);
  void follow_break_continue(const OWord& w, int line_number);
  void jump(std::uint64_t offset, int line, int line_number, const OWord& w);
  std::vector<Loop>::iterator loop_of(const std::string& label);
  [[noreturn]] void fail(int line, int column, const std::string& what) const;

  LineSource& source_;
  std::string file_;
  Parameters& params_;
  SubprogramCalls& calls_;
  std::vector<Loop> loops_;
  std::string found_line_;
  long jumps_ = 0;
};

}  // namespace ncpost::gcode
