// SPDX-License-Identifier: Apache-2.0
#pragma once
// The order in which a Klartext program's lines run: straight on, or through labels (LBL n,
// LBL "name"), subprogram calls (CALL LBL n ... LBL 0), section repeats (CALL LBL n REP m: the
// lines from LBL n to the call run m more times) and jumps (FN 9 .. 12 GOTO LBL n).
//
// Lines are read from the LineSource as long as no label is involved; from the first label
// statement on, every line read is kept, so that a jump back replays it; a jump to a label not
// yet read reads ahead until it is found. Subprograms nest at most kMaxDepth deep (the TNC's
// limit); more than kMaxJumps jumps in one run are taken as an endless loop. Failures throw
// InputError naming the statement and the chain of calls.
#include <deque>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "ncpost/postproc/read/line_source.hpp"

namespace ncpost::klartext {

class ProgramFlow {
 public:
  static constexpr std::size_t kMaxDepth = 19;
  static constexpr long kMaxJumps = 1'000'000;

  /// `label_in(line)`: the label a line defines (LBL n), or "" (used when reading ahead).
  ProgramFlow(LineSource& source, std::function<std::string(std::string_view)> label_in)
      : source_(source), label_in_(std::move(label_in)) {}

  /// The next line to run and its line number; false at the end of the input.
  bool next(std::string_view& line, int& line_number);

  /// The current line is `LBL key`: remembered (LBL 0 ends a subprogram: back after its call).
  void label(const std::string& key, int line_number);
  /// CALL LBL key [REP repeats] in the current line.
  void call(const std::string& key, int repeats, int line_number);
  /// FN 9 .. 12 GOTO LBL key in the current line, the condition holding.
  void jump(const std::string& key, int line_number);
  /// Outside any subprogram call: reads the rest of the input and calls `fn` for every line from the
  /// current one to the end, while it returns true; false when in a call or when `fn` said false.
  bool each_rest_line(const std::function<bool(std::string_view, int)>& fn);
  /// The subprogram calls in progress, outermost first ("CALL LBL 1 (line 12) > CALL LBL 2 (line 40)").
  std::string chain() const;

 private:
  struct Line {
    std::string text;
    int number;
  };
  struct Frame {
    std::string label;
    std::size_t return_to;  ///< index into lines_
    int call_line;
  };
  void keep_current();
  std::size_t find(const std::string& key, const std::string& statement, int line_number);
  void count_jump(const std::string& statement, int line_number);
  [[noreturn]] void fail(int line_number, const std::string& what) const;

  LineSource& source_;
  std::function<std::string(std::string_view)> label_in_;
  std::deque<Line> lines_;  ///< kept from the first label statement on
  bool keeping_ = false;
  std::size_t play_ = 0;       ///< the next line to run, index into lines_ (== size: read on)
  bool current_kept_ = false;  ///< the current line is lines_[play_ - 1]
  std::string current_;        ///< the current line when not kept
  int current_number_ = 0;
  std::map<std::string, std::size_t> labels_;
  std::map<std::size_t, int> repeats_left_;  ///< per CALL ... REP line (index): repeats still to run
  std::vector<Frame> frames_;
  long jumps_ = 0;
};

}  // namespace ncpost::klartext
