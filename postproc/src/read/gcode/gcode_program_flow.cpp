// SPDX-License-Identifier: Apache-2.0
#include "read/gcode/gcode_program_flow.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>

#include "ncpost/machines/input_error.hpp"
#include "read/char_scan.hpp"

namespace ncpost::gcode {
namespace {

/// The block number N of `line` (`N10`, `/N0010`), or nullopt.
std::optional<long> block_number(std::string_view line) {
  std::size_t at = 0;
  skip_blanks(line, at);
  if (at < line.size() && line[at] == '/') ++at;
  skip_blanks(line, at);
  if (at >= line.size() || (line[at] != 'N' && line[at] != 'n')) return std::nullopt;
  ++at;
  skip_blanks(line, at);
  long n = 0;
  int digits = 0;
  while (at < line.size() && is_digit(line[at]) && digits < 12) n = n * 10 + (line[at++] - '0'), ++digits;
  if (digits == 0) return std::nullopt;
  return n;
}

}  // namespace

int loop_end_number(std::string_view line) {
  for (std::size_t i = 0; i + 3 <= line.size(); ++i) {
    if (line[i] == '(') {
      int depth = 0;
      for (; i < line.size(); ++i) {
        if (line[i] == '(') ++depth;
        if (line[i] == ')' && --depth == 0) break;
      }
      continue;
    }
    if (line[i] == ';') return -1;
    if ((i > 0 && is_alpha(line[i - 1])) || (line[i] != 'E' && line[i] != 'e')) continue;
    const std::string_view w = line.substr(i, 3);
    if (!((w[1] == 'N' || w[1] == 'n') && (w[2] == 'D' || w[2] == 'd'))) continue;
    std::size_t at = i + 3;
    if (at < line.size() && is_alpha(line[at])) continue;
    skip_blanks(line, at);
    int m = 0, digits = 0;
    while (at < line.size() && is_digit(line[at]) && digits < 9) m = m * 10 + (line[at++] - '0'), ++digits;
    if (digits > 0) return m;
  }
  return -1;
}

void ProgramFlow::fail(int line, int column, const std::string& what) const {
  throw InputError({source_.file(), line, column}, what);
}

void ProgramFlow::follow(const MacroFlow& flow, std::uint64_t line_offset, int line_number, int first_line) {
  using K = MacroFlow::Kind;
  if (flow.kind == K::none) return;
  if (++jumps_ > kMaxJumps)
    fail(line_number, flow.column,
         fmt::format("more than {} jumps and loop turns: a loop that never ends? (its condition is never false)",
                     kMaxJumps));
  switch (flow.kind) {
    case K::go_to:
      jump_to_block(flow.number, line_number, flow.column, first_line);
      break;
    case K::while_do:
      loops_.erase(std::remove_if(loops_.begin(), loops_.end(), [&](const Loop& l) { return l.number == flow.number; }),
                   loops_.end());
      if (flow.condition)
        loops_.push_back({flow.number, line_offset, line_number});
      else
        skip_loop(flow.number, line_number, flow.column);
      break;
    case K::end_loop: {
      const auto it =
          std::find_if(loops_.rbegin(), loops_.rend(), [&](const Loop& l) { return l.number == flow.number; });
      if (it == loops_.rend())
        fail(line_number, flow.column,
             fmt::format("END {} without its WHILE [...] DO {} (or DO {})", flow.number, flow.number, flow.number));
      const Loop loop = *it;
      loops_.erase(std::next(it).base(), loops_.end());  // it and the loops inside it
      if (!source_.seek(loop.offset, loop.line))
        fail(line_number, flow.column,
             "a loop needs to read its lines again, and this input cannot be re-read (a pipe)");
      break;
    }
    case K::none:
      break;
  }
}

void ProgramFlow::jump_to_block(int n, int line_number, int column, int first_line) {
  std::string_view line;
  // forward, to the end of the program
  for (;;) {
    const std::uint64_t offset = source_.next_line_offset();
    if (!source_.next(line) || is_percent_line(line)) break;
    if (block_number(line) == n) {
      source_.seek(offset, source_.line_number());
      return;
    }
  }
  // then from its start up to the GOTO
  if (!source_.seek(0, 1))
    fail(line_number, column,
         "GOTO needs to search the program from its start, and this input cannot be re-read (a pipe)");
  while (source_.line_number() < line_number) {
    const std::uint64_t offset = source_.next_line_offset();
    if (!source_.next(line)) break;
    if (source_.line_number() < first_line) continue;
    if (block_number(line) == n) {
      const int target = source_.line_number();
      loops_.erase(std::remove_if(loops_.begin(), loops_.end(), [&](const Loop& l) { return l.line >= target; }),
                   loops_.end());
      source_.seek(offset, target);
      return;
    }
  }
  fail(line_number, column, fmt::format("GOTO {}: the program has no block N{}", n, n));
}

void ProgramFlow::skip_loop(int m, int line_number, int column) {
  std::string_view line;
  while (source_.next(line)) {
    if (is_percent_line(line)) break;
    if (loop_end_number(line) == m) return;
  }
  fail(line_number, column, fmt::format("WHILE [...] DO {} without its END {}", m, m));
}

}  // namespace ncpost::gcode
