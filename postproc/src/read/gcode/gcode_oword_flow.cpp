// SPDX-License-Identifier: Apache-2.0
// LinuxCNC o-word control flow (see gcode_oword_flow.hpp).
#include "read/gcode/gcode_oword_flow.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ncpost/machines/input_error.hpp"

namespace ncpost::gcode {

void OWordFlow::fail(int line, int column, const std::string& what) const {
  throw InputError({source_.file(), line, column}, what + calls_.chain());
}

double OWordFlow::value_at(std::string_view line, std::size_t at, int line_number, const OWord& w) const {
  try {
    const ParamValue v = Evaluator(params_).value(line, at);
    if (!v)
      fail(line_number, static_cast<int>(at) + 1,
           fmt::format("{} {}: the value is vacant", w.label, keyword_name(w.keyword)));
    return *v;
  } catch (const ExpressionError& e) {
    fail(line_number, static_cast<int>(e.offset()) + 1, e.what());
  }
}

std::vector<ParamValue> OWordFlow::arguments(std::string_view line, std::size_t at, int line_number,
                                             const OWord& w) const {
  std::vector<ParamValue> out;
  for (;;) {
    while (at < line.size() && (line[at] == ' ' || line[at] == '\t')) ++at;
    if (at >= line.size() || line[at] == '(' || line[at] == ';') return out;
    if (line[at] != '[')
      fail(line_number, static_cast<int>(at) + 1,
           fmt::format("{} call: expected an argument in brackets [...]", w.label));
    try {
      out.push_back(Evaluator(params_).value(line, at));
    } catch (const ExpressionError& e) {
      fail(line_number, static_cast<int>(e.offset()) + 1, e.what());
    }
  }
}

OWord OWordFlow::skip_to(const std::string& label, std::initializer_list<K> keywords, int line_number,
                         const OWord& from) {
  std::string_view text;
  while (source_.next(text)) {
    const std::optional<OWord> w = read_o_word(text);
    if (!w || w->label != label) continue;
    if (std::find(keywords.begin(), keywords.end(), w->keyword) == keywords.end()) continue;
    found_line_ = std::string(text);
    return *w;
  }
  fail(line_number, from.column,
       fmt::format("{} {} without its {}", from.label, keyword_name(from.keyword), keyword_name(*keywords.begin())));
}

void OWordFlow::jump(std::uint64_t offset, int line, int line_number, const OWord& w) {
  if (++jumps_ > kMaxJumps)
    fail(line_number, w.column,
         fmt::format("more than {} loop turns: a loop that never ends? (its condition is never "
                     "false)",
                     kMaxJumps));
  if (!source_.seek(offset, line))
    fail(line_number, w.column, "a loop needs to read its lines again, and this input cannot be re-read (a pipe)");
}

std::vector<OWordFlow::Loop>::iterator OWordFlow::loop_of(const std::string& label) {
  const auto it = std::find_if(loops_.rbegin(), loops_.rend(), [&](const Loop& l) { return l.label == label; });
  return it == loops_.rend() ? loops_.end() : std::next(it).base();
}

void OWordFlow::follow(const OWord& w, std::string_view line, std::uint64_t line_offset, int line_number) {
  const SubprogramCalls::Position next{source_.next_line_offset(), line_number + 1};
  switch (w.keyword) {
    case K::sub:
      skip_to(w.label, {K::endsub}, line_number, w);
      return;  // a definition
    case K::call:
      calls_.note_loops(loops_.size());
      calls_.call_sub(w.label, arguments(line, w.argument_at, line_number, w), params_, next, line_number, w.column);
      return;
    case K::endsub:
    case K::return_:
      loops_.resize(std::min(loops_.size(), calls_.leave(false, params_, line_number, w.column)));
      return;
    case K::if_:
      follow_if(w, line, line_number);
      return;
    case K::elseif:
    case K::else_:
      skip_to(w.label, {K::endif}, line_number, w);
      return;  // after a branch taken
    case K::endif:
      return;
    case K::while_:
      follow_while(w, line, line_offset, line_number);
      return;
    case K::do_:
      if (const auto it = loop_of(w.label); it != loops_.end()) loops_.erase(it, loops_.end());
      loops_.push_back(Loop{w.label, LoopKind::do_, next.offset, next.line});
      return;
    case K::repeat: {
      const double n = value_at(line, w.argument_at, line_number, w);
      if (n != std::floor(n) || n > 1e9)
        fail(line_number, w.column, fmt::format("{} repeat: expected a whole count", w.label));
      if (n < 1.0) {
        skip_to(w.label, {K::endrepeat}, line_number, w);
        return;
      }
      loops_.push_back(Loop{w.label, LoopKind::repeat, next.offset, next.line, static_cast<long>(n)});
      return;
    }
    case K::endwhile:
    case K::endrepeat:
      follow_loop_end(w, line_number);
      return;
    case K::break_:
    case K::continue_:
      follow_break_continue(w, line_number);
      return;
  }
}

void OWordFlow::follow_if(const OWord& w, std::string_view line, int line_number) {
  if (value_at(line, w.argument_at, line_number, w) != 0.0) return;
  for (;;) {
    const OWord b = skip_to(w.label, {K::endif, K::elseif, K::else_}, line_number, w);
    if (b.keyword != K::elseif) return;  // else: its branch runs; endif: none does
    if (value_at(found_line_, b.argument_at, source_.line_number(), b) != 0.0) return;
  }
}

// `while` opens a while loop, or closes a do loop of the same label
void OWordFlow::follow_while(const OWord& w, std::string_view line, std::uint64_t line_offset, int line_number) {
  const bool holds = value_at(line, w.argument_at, line_number, w) != 0.0;
  const auto it = loop_of(w.label);
  if (it != loops_.end() && it->kind == LoopKind::do_) {
    if (holds)
      jump(it->offset, it->line, line_number, w);
    else
      loops_.erase(it, loops_.end());
    return;
  }
  if (it != loops_.end()) loops_.erase(it, loops_.end());
  if (holds)
    loops_.push_back(Loop{w.label, LoopKind::while_, line_offset, line_number});
  else
    skip_to(w.label, {K::endwhile}, line_number, w);
}

void OWordFlow::follow_loop_end(const OWord& w, int line_number) {
  const auto it = loop_of(w.label);
  if (it == loops_.end())
    fail(line_number, w.column, fmt::format("{} {} without its loop", w.label, keyword_name(w.keyword)));
  if (it->kind == LoopKind::while_) {
    const Loop loop = *it;
    loops_.erase(it, loops_.end());
    jump(loop.offset, loop.line, line_number, w);  // the while line again: its condition decides
    return;
  }
  if (--it->left > 0) {
    jump(it->offset, it->line, line_number, w);
    return;
  }
  loops_.erase(it, loops_.end());
}

void OWordFlow::follow_break_continue(const OWord& w, int line_number) {
  const auto it = loop_of(w.label);
  if (it == loops_.end())
    fail(line_number, w.column, fmt::format("{} {} outside its loop", w.label, keyword_name(w.keyword)));
  const LoopKind kind = it->kind;
  const K end = kind == LoopKind::while_ ? K::endwhile : kind == LoopKind::repeat ? K::endrepeat : K::while_;
  if (w.keyword == K::break_) {
    loops_.erase(it, loops_.end());
    skip_to(w.label, {end}, line_number, w);
    return;
  }
  loops_.erase(std::next(it), loops_.end());
  const OWord closing = skip_to(w.label, {end}, line_number, w);
  const int closing_line = source_.line_number();
  const std::string text = found_line_;
  follow(closing, text, 0, closing_line);  // the loop's end decides on its next turn
}

}  // namespace ncpost::gcode
