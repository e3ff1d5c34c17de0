// SPDX-License-Identifier: Apache-2.0
// Labels, subprogram calls, section repeats and jumps of a Klartext program (klartext_flow.hpp).
#include "read/klartext/klartext_flow.hpp"

#include <fmt/format.h>

#include "ncpost/machines/input_error.hpp"

namespace ncpost::klartext {

bool ProgramFlow::next(std::string_view& line, int& line_number) {
  if (play_ < lines_.size()) {
    line = lines_[play_].text;
    line_number = lines_[play_].number;
    ++play_;
    current_kept_ = true;
    return true;
  }
  std::string_view read;
  if (!source_.next(read)) return false;
  line_number = source_.line_number();
  if (keeping_) {
    lines_.push_back({std::string(read), line_number});
    play_ = lines_.size();
    current_kept_ = true;
    line = lines_.back().text;
  } else {
    current_.assign(read);
    current_number_ = line_number;
    current_kept_ = false;
    line = current_;
  }
  return true;
}

bool ProgramFlow::each_rest_line(const std::function<bool(std::string_view, int)>& fn) {
  if (!frames_.empty()) return false;
  keep_current();
  std::string_view read;
  while (source_.next(read)) lines_.push_back({std::string(read), source_.line_number()});
  for (std::size_t i = play_ - 1; i < lines_.size(); ++i)
    if (!fn(lines_[i].text, lines_[i].number)) return false;
  return true;
}

void ProgramFlow::keep_current() {
  if (keeping_) return;
  keeping_ = true;
  if (!current_kept_) {
    lines_.push_back({current_, current_number_});
    play_ = lines_.size();
    current_kept_ = true;
  }
}

void ProgramFlow::label(const std::string& key, int line_number) {
  keep_current();
  const std::size_t at = play_ - 1;
  if (key == "0") {
    if (frames_.empty()) return;  // (the end of a subprogram reached without a call: the TNC runs on)
    play_ = frames_.back().return_to;
    frames_.pop_back();
    return;
  }
  const auto [it, inserted] = labels_.emplace(key, at);
  if (!inserted && it->second != at)
    fail(line_number,
         fmt::format("LBL {} is defined twice (lines {} and {})", key, lines_[it->second].number, line_number));
}

void ProgramFlow::call(const std::string& key, int repeats, int line_number) {
  keep_current();
  const std::size_t at = play_ - 1;
  const std::string statement = fmt::format("CALL LBL {}{}", key, repeats > 0 ? fmt::format(" REP {}", repeats) : "");
  if (key == "0")
    fail(line_number, fmt::format("{}: LBL 0 marks the end of a subprogram and cannot be called", statement));
  const std::size_t target = find(key, statement, line_number);
  if (repeats > 0) {
    if (target > at)
      fail(line_number, fmt::format("{}: LBL {} comes after the call; a repeat runs the lines from the label back to "
                                    "the call, so the label must come before it",
                                    statement, key));
    auto left = repeats_left_.try_emplace(at, repeats).first;
    if (left->second == 0) {
      repeats_left_.erase(left);
      return;
    }
    --left->second;
    count_jump(statement, line_number);
    play_ = target + 1;
    return;
  }
  if (frames_.size() >= kMaxDepth)
    fail(line_number, fmt::format("{}: subprograms nested deeper than {} (the TNC's limit): {} > {} (line {})",
                                  statement, kMaxDepth, chain(), statement, line_number));
  frames_.push_back({key, play_, line_number});
  count_jump(statement, line_number);
  play_ = target + 1;
}

void ProgramFlow::jump(const std::string& key, int line_number) {
  keep_current();
  const std::string statement = fmt::format("GOTO LBL {}", key);
  const std::size_t target = find(key, statement, line_number);
  count_jump(statement, line_number);
  play_ = target + 1;
}

std::string ProgramFlow::chain() const {
  std::string s;
  for (const Frame& f : frames_)
    s += fmt::format("{}CALL LBL {} (line {})", s.empty() ? "" : " > ", f.label, f.call_line);
  return s.empty() ? "the main program" : s;
}

std::size_t ProgramFlow::find(const std::string& key, const std::string& statement, int line_number) {
  if (const auto it = labels_.find(key); it != labels_.end()) return it->second;
  std::string_view read;
  while (source_.next(read)) {
    lines_.push_back({std::string(read), source_.line_number()});
    const std::string defined = label_in_(read);
    if (defined.empty() || defined == "0") continue;
    const auto [it, inserted] = labels_.emplace(defined, lines_.size() - 1);
    if (!inserted)
      fail(source_.line_number(), fmt::format("LBL {} is defined twice (lines {} and {})", defined,
                                              lines_[it->second].number, source_.line_number()));
    if (defined == key) return lines_.size() - 1;
  }
  fail(line_number, fmt::format("{}: LBL {} is not in the program", statement, key));
}

void ProgramFlow::count_jump(const std::string& statement, int line_number) {
  if (++jumps_ > kMaxJumps)
    fail(line_number, fmt::format("{}: more than {} jumps and calls: the program loops without end (check the FN "
                                  "9 .. 12 conditions and the REP counts)",
                                  statement, kMaxJumps));
}

void ProgramFlow::fail(int line_number, const std::string& what) const {
  throw InputError({source_.file(), line_number, 0}, what);
}

}  // namespace ncpost::klartext
