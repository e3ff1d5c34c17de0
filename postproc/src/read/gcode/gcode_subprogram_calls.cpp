// SPDX-License-Identifier: Apache-2.0
// Subprogram calls expanded on the line source (see gcode_subprogram_calls.hpp).
#include "read/gcode/gcode_subprogram_calls.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "ncpost/machines/input_error.hpp"
#include "read/gcode/gcode_oword.hpp"

namespace ncpost::gcode {
namespace {

constexpr long kMaxProgramNumber = 99'999'999;
constexpr int kMaxRepeats = 9999;

bool is_digit(char c) { return c >= '0' && c <= '9'; }

/// The number after the letter `letter` (or ':' for 'O') that starts the statement of `line`
/// (past blanks and a '/'; for 'O' also past an N number), or -1.
long leading_number(std::string_view line, char letter) {
  std::size_t at = 0;
  const auto blanks = [&] {
    while (at < line.size() && (line[at] == ' ' || line[at] == '\t')) ++at;
  };
  blanks();
  if (at < line.size() && line[at] == '/') ++at;
  blanks();
  if (at >= line.size()) return -1;
  const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(line[at])));
  if (!(c == letter || (letter == 'O' && line[at] == ':'))) return -1;
  ++at;
  blanks();
  long n = 0;
  int digits = 0;
  while (at < line.size() && is_digit(line[at]) && digits < 9) n = n * 10 + (line[at++] - '0'), ++digits;
  if (digits == 0) return -1;
  if (letter == 'O' && at < line.size() && (std::isalpha(static_cast<unsigned char>(line[at])) || line[at] == '<'))
    return -1;  // a program name, not a number
  return n;
}

/// Whether `line` opens the body named `label` ("O1000", "N500", "o<name>", "o100").
bool opens(std::string_view line, const std::string& label) {
  if (label[0] == 'O') {
    if (read_o_word(line)) return false;  // `o1000 sub` is LinuxCNC's
    return leading_number(line, 'O') == std::stol(label.substr(1));
  }
  if (label[0] == 'N') return leading_number(line, 'N') == std::stol(label.substr(1));
  const std::optional<OWord> w = read_o_word(line);
  return w && w->keyword == OWord::Keyword::sub && w->label == label;
}

}  // namespace

void SubprogramCalls::fail(int line, int column, const std::string& what) const {
  throw InputError({file_, line, column}, what + chain());
}

std::string SubprogramCalls::chain() const {
  std::string out;
  for (auto it = frames_.rbegin(); it != frames_.rend(); ++it)
    out += fmt::format(" via {} call at {}:{}", it->label, file_, it->call_line);
  return out;
}

void SubprogramCalls::seek(Position at, int line, int column) {
  if (!source_.seek(at.offset, at.line))
    fail(line, column, "a subprogram call needs to read the file again, and this input cannot be re-read (a pipe)");
}

std::optional<SubprogramCalls::Position> SubprogramCalls::find(const std::string& label, int line, int column) {
  if (const auto it = found_.find(label); it != found_.end()) return it->second;
  seek(Position{0, 1}, line, column);
  std::string_view text;
  std::uint64_t offset = 0;
  while (source_.next(text)) {
    if (opens(text, label)) {
      // O<n> and `o.. sub` open the body on the next line; Haas's N<n> is the body's first block
      const Position body = label[0] == 'N' ? Position{offset, source_.line_number()}
                                            : Position{source_.next_line_offset(), source_.line_number() + 1};
      found_[label] = body;
      return body;
    }
    offset = source_.next_line_offset();
  }
  return std::nullopt;
}

void SubprogramCalls::enter(Frame frame, int line, int column) {
  if (frames_.size() >= kMaxDepth)
    fail(line, column,
         fmt::format("{} is called more than {} calls deep: a call that never returns?", frame.label, kMaxDepth));
  if (std::any_of(frames_.begin(), frames_.end(), [&](const Frame& f) { return f.label == frame.label; }))
    fail(line, column, fmt::format("{} calls itself (recursion): not supported", frame.label));
  frame.call_line = line;
  frame.loops = loops_at_call_;
  const Position body = frame.body;
  frames_.push_back(std::move(frame));
  seek(body, line, column);
}

void SubprogramCalls::call_program(double p, int times, Position back, int line, int column) {
  if (!(p >= 1.0 && p <= static_cast<double>(kMaxProgramNumber) && p == static_cast<double>(static_cast<long>(p))))
    fail(line, column, "M98 needs P, the number of the program it calls (O1 .. O99999999)");
  if (times < 1 || times > kMaxRepeats)
    fail(line, column, fmt::format("M98: expected L1 .. L{} (the repeat count)", kMaxRepeats));
  const long number = static_cast<long>(p);
  std::optional<Position> body = find(fmt::format("O{}", number), line, column);
  std::string label = fmt::format("O{}", number);
  if (number > 9999) {  // Fanuc's M98 P<repeats><4-digit program>
    const std::string short_label = fmt::format("O{}", number % 10000);
    const std::optional<Position> split = find(short_label, line, column);
    if (body && split)
      fail(line, column,
           fmt::format("M98 P{}: the file holds both O{} and {} (Fanuc reads P{} as {} times {}): write "
                       "the repeat count with L",
                       number, number, short_label, number, number / 10000, short_label));
    if (split) {
      body = split;
      label = short_label;
      times *= static_cast<int>(number / 10000);
    }
  }
  if (!body)
    fail(line, column,
         fmt::format("M98 P{}: the file holds no program {} (subprograms in the control's memory or in "
                     "other files are not read: append it after M30)",
                     number, label));
  enter(Frame{label, 0, back, *body, times - 1, std::nullopt, 0}, line, column);
}

void SubprogramCalls::call_block(int n, int times, Position back, int line, int column) {
  if (times < 1 || times > kMaxRepeats)
    fail(line, column, fmt::format("M97: expected L1 .. L{} (the repeat count)", kMaxRepeats));
  const std::string label = fmt::format("N{}", n);
  const std::optional<Position> body = find(label, line, column);
  if (!body) fail(line, column, fmt::format("M97 P{}: the file holds no block N{}", n, n));
  enter(Frame{label, 0, back, *body, times - 1, std::nullopt, 0}, line, column);
}

void SubprogramCalls::call_sub(const std::string& label, const std::vector<ParamValue>& arguments, Parameters& params,
                               Position back, int line, int column) {
  if (arguments.size() > static_cast<std::size_t>(kLocals))
    fail(line, column,
         fmt::format("{} call with {} arguments: at most {} (#1 .. #{})", label, arguments.size(), kLocals, kLocals));
  const std::optional<Position> body = find(label, line, column);
  if (!body) fail(line, column, fmt::format("{} call: the file holds no {} sub", label, label));
  Frame f;
  f.label = label;
  f.back = back;
  f.body = *body;
  std::array<ParamValue, kLocals> saved{};
  for (int i = 0; i < kLocals; ++i) {
    saved[static_cast<std::size_t>(i)] = params.get(i + 1);
    params.set(i + 1,
               static_cast<std::size_t>(i) < arguments.size() ? arguments[static_cast<std::size_t>(i)] : std::nullopt);
  }
  f.saved = saved;
  enter(std::move(f), line, column);
}

std::size_t SubprogramCalls::leave(bool m99, Parameters& params, int line, int column) {
  if (frames_.empty())
    fail(line, column,
         m99 ? "M99 in the main program (Fanuc: run it again from its start, endlessly): not supported"
             : "endsub or return without a call");
  Frame& f = frames_.back();
  if (m99 && f.saved)
    fail(line, column, fmt::format("M99 inside the o-word sub {}: expected endsub or return", f.label));
  if (!m99 && !f.saved)
    fail(line, column, fmt::format("endsub or return inside {} (called by M98/M97): expected M99", f.label));
  if (f.repeats_left > 0) {
    --f.repeats_left;
    seek(f.body, line, column);
    return f.loops;
  }
  if (f.saved)
    for (int i = 0; i < kLocals; ++i) params.set(i + 1, (*f.saved)[static_cast<std::size_t>(i)]);
  const Frame done = f;
  frames_.pop_back();
  seek(done.back, line, column);
  return done.loops;
}

}  // namespace ncpost::gcode
