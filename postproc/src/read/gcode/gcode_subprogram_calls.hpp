// SPDX-License-Identifier: Apache-2.0
#pragma once
// The call stack of a G-code program's subprograms, expanded on its line source (the input must
// be a file: calls re-read it):
//   Fanuc/Haas  M98 P<o> L<k>   the program O<o> of the same file (O blocks after M30 too) runs k
//                               times; Fanuc's M98 P<kkkk><oooo> (k in front of a 4-digit number)
//                               where the file has O<oooo> but no O<kkkkoooo>
//               M97 P<n> L<k>   Haas local subprogram: from block N<n> of the same file
//               M99             back to the block after the call (or the body again while repeats
//                               are left)
//   LinuxCNC    o<name> call [a] [b] ...   to `o<name> sub`, #1..#30 set from the arguments (the
//                               caller's #1..#30 are restored on return); endsub/return go back
// A call deeper than kMaxDepth, and a call of a subprogram already running (recursion), are input
// errors; so is a target the file does not hold. `chain()` names the calls in force for messages
// ("via o100 call at t.ngc:12").
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "ncpost/postproc/read/gcode/gcode_expression.hpp"
#include "ncpost/postproc/read/line_source.hpp"

namespace ncpost::gcode {

class SubprogramCalls {
 public:
  static constexpr std::size_t kMaxDepth = 10;  ///< nested calls (Fanuc and LinuxCNC allow about as many)
  static constexpr int kLocals = 30;            ///< #1..#30 of an o-word call

  struct Position {
    std::uint64_t offset = 0;  ///< where the line starts (LineSource::next_line_offset())
    int line = 0;              ///< its 1-based number
  };

  SubprogramCalls(LineSource& source, std::string file) : source_(source), file_(std::move(file)) {}

  /// M98 P<p> L<times> on line `line` (column: of the M word); `back`: where the program goes on.
  void call_program(double p, int times, Position back, int line, int column);
  /// M97 P<n> L<times>: from block N<n>.
  void call_block(int n, int times, Position back, int line, int column);
  /// `o<name> call`: to its sub with `arguments` in #1..; `params` holds the caller's #1..#30.
  void call_sub(const std::string& label, const std::vector<ParamValue>& arguments, Parameters& params, Position back,
                int line, int column);
  /// M99 (`m99`: true) or endsub/return: back to the caller or into the body again. Returns the
  /// o-word loops in force at the call (for the flow to drop the callee's).
  std::size_t leave(bool m99, Parameters& params, int line, int column);

  bool active() const { return !frames_.empty(); }
  /// The label of the innermost call ("O1000", "N500", "o<name>"), "" at the top level.
  std::string innermost() const { return frames_.empty() ? std::string() : frames_.back().label; }
  /// " via o100 call at t.ngc:12 via O2000 call at t.ngc:3" (innermost first), "" at the top.
  std::string chain() const;
  /// The loops the o-word flow had when the innermost call was made.
  void note_loops(std::size_t loops) { loops_at_call_ = loops; }

 private:
  struct Frame {
    std::string label;
    int call_line = 0;
    Position back;
    Position body;
    int repeats_left = 0;
    std::optional<std::array<ParamValue, kLocals>> saved;  ///< the caller's #1..#30 (o-word calls)
    std::size_t loops = 0;                                 ///< o-word loops at the call
  };
  std::optional<Position> find(const std::string& label, int line, int column);
  void enter(Frame frame, int line, int column);
  void seek(Position at, int line, int column);
  [[noreturn]] void fail(int line, int column, const std::string& what) const;

  LineSource& source_;
  std::string file_;
  std::vector<Frame> frames_;
  std::map<std::string, Position> found_;  ///< bodies located so far
  std::size_t loops_at_call_ = 0;
};

}  // namespace ncpost::gcode
