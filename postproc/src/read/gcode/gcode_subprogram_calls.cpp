// SPDX-License-Identifier: Apache-2.0
// Subprogram calls expanded on the line source (see gcode_subprogram_calls.hpp).
#include "read/gcode/gcode_subprogram_calls.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <fstream>

#include "ncpost/machines/input_error.hpp"
#include "read/gcode/gcode_oword.hpp"
#include "read/gcode/gcode_subprogram_files.hpp"
#include "read/char_scan.hpp"

namespace ncpost::gcode {
namespace {

constexpr long kMaxProgramNumber = 99'999'999;
constexpr int kMaxRepeats = 9999;

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

SubprogramCalls::SubprogramCalls(LineSource& source, std::string file) : source_(source), file_(std::move(file)) {
  Input main;
  main.name = file_;
  main.in = &source_.input();
  main.origin = source_.origin();
  inputs_.push_back(std::move(main));
}

void SubprogramCalls::fail(int line, int column, const std::string& what) const {
  throw InputError({source_.file(), line, column}, what + chain());
}

std::string SubprogramCalls::chain() const {
  std::string out;
  for (auto it = frames_.rbegin(); it != frames_.rend(); ++it)
    out += fmt::format(" via {} call at {}:{}", it->label, it->caller_file, it->call_line);
  return out;
}

void SubprogramCalls::fail_in_caller(const Frame& f, int line, int column, const std::string& what) {
  seek(f.back, line, column);  // a search may have left the caller's file
  fail(line, column, what);
}

void SubprogramCalls::seek(Position at, int line, int column) {
  const int file = at.file < 0 ? current_ : at.file;
  if (file != current_) {
    const Input& in = inputs_[static_cast<std::size_t>(file)];
    source_.switch_input(*in.in, in.origin, in.name);
    current_ = file;
  }
  if (!source_.seek(at.offset, at.line))
    fail(line, column, "a subprogram call needs to read the file again, and this input cannot be re-read (a pipe)");
}

/// In the file being read, then in the program's own file.
std::optional<SubprogramCalls::Position> SubprogramCalls::find(const std::string& label, int line, int column) {
  if (auto body = find_in(current_, label, line, column)) return body;
  if (current_ != 0) return find_in(0, label, line, column);
  return std::nullopt;
}

std::optional<SubprogramCalls::Position> SubprogramCalls::find_in(int file, const std::string& label, int line,
                                                                  int column) {
  const std::string key = fmt::format("{}@{}", label, file);
  if (const auto it = found_.find(key); it != found_.end()) return it->second;
  seek(Position{0, 1, file}, line, column);
  std::string_view text;
  std::uint64_t offset = 0;
  while (source_.next(text)) {
    if (opens(text, label)) {
      // O<n> and `o.. sub` open the body on the next line; Haas's N<n> is the body's first block
      const Position body = label[0] == 'N' ? Position{offset, source_.line_number(), file}
                                            : Position{source_.next_line_offset(), source_.line_number() + 1, file};
      found_[key] = body;
      return body;
    }
    offset = source_.next_line_offset();
  }
  return std::nullopt;
}

int SubprogramCalls::open_input(const std::string& path, int line, int column) {
  for (std::size_t i = 0; i < inputs_.size(); ++i)
    if (inputs_[i].name == path) return static_cast<int>(i);
  auto in = std::make_unique<std::ifstream>(path, std::ios::binary);
  if (!*in) fail(line, column, fmt::format("cannot open the subprogram's file '{}'", path));
  Input input;
  input.name = path;
  input.in = in.get();
  input.origin = in->tellg();
  input.owned = std::move(in);
  inputs_.push_back(std::move(input));
  return static_cast<int>(inputs_.size()) - 1;
}

/// A Fanuc program O<n> or a LinuxCNC o<name> sub in a file beside the program; `call` names the
/// call for the message ("M98 P1234").
SubprogramCalls::Position SubprogramCalls::find_elsewhere(const Frame& at, const std::string& label,
                                                          const std::string& call, int line, int column) {
  const bool fanuc = label[0] == 'O';
  const std::string name = fanuc ? std::string() : label.substr(2, label.size() - 3);
  const SubprogramFile file = fanuc ? find_program_file(std::stol(label.substr(1)), dirs_) : find_sub_file(name, dirs_);
  if (file.ambiguous) fail_in_caller(at, line, column, fmt::format("{}: {}", call, file.error));
  if (file.path.empty())
    fail_in_caller(at, line, column,
                   fmt::format("{}: the file holds no {}, and {} (a subprogram in the control's memory: post with "
                               "--subprogram-dir DIR, DIR holding it as {})",
                               call, fanuc ? "program " + label : label + " sub", file.error,
                               fanuc ? label + ".nc" : name + ".ngc"));
  const int index = open_input(file.path, line, column);
  const std::optional<Position> body = find_in(index, label, line, column);
  if (!body)
    fail_in_caller(at, line, column,
                   fmt::format("{}: '{}' holds no {}", call, file.path, fanuc ? label : label + " sub"));
  return *body;
}

/// The frame of a call made now (before any search moves the line source): the caller's file and
/// start, and `back` in the caller's file.
SubprogramCalls::Frame SubprogramCalls::frame_at_call(const std::string& label, Position back) const {
  Frame f;
  f.label = label;
  f.back = back;
  if (f.back.file < 0) f.back.file = current_;
  f.caller_file = inputs_[static_cast<std::size_t>(current_)].name;
  f.caller_start = frames_.empty() ? Position{0, 1, 0} : frames_.back().body;
  return f;
}

void SubprogramCalls::enter(Frame frame, int line, int column) {
  if (frames_.size() >= kMaxDepth)
    fail_in_caller(
        frame, line, column,
        fmt::format("{} is called more than {} calls deep: a call that never returns?", frame.label, kMaxDepth));
  if (std::any_of(frames_.begin(), frames_.end(), [&](const Frame& f) { return f.label == frame.label; }))
    fail_in_caller(frame, line, column, fmt::format("{} calls itself (recursion): not supported", frame.label));
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
  Frame f = frame_at_call("", back);
  std::optional<Position> body = find(fmt::format("O{}", number), line, column);
  std::string label = fmt::format("O{}", number);
  if (number > 9999) {  // Fanuc's M98 P<repeats><4-digit program>
    const std::string short_label = fmt::format("O{}", number % 10000);
    const std::optional<Position> split = find(short_label, line, column);
    if (body && split)
      fail_in_caller(f, line, column,
                     fmt::format("M98 P{}: the file holds both O{} and {} (Fanuc reads P{} as {} times {}): write "
                                 "the repeat count with L",
                                 number, number, short_label, number, number / 10000, short_label));
    if (split) {
      body = split;
      label = short_label;
      times *= static_cast<int>(number / 10000);
    }
  }
  if (!body) body = find_elsewhere(f, label, fmt::format("M98 P{}", number), line, column);
  f.label = label;
  f.body = *body;
  f.repeats_left = times - 1;
  enter(std::move(f), line, column);
}

void SubprogramCalls::call_block(int n, int times, Position back, int line, int column) {
  if (times < 1 || times > kMaxRepeats)
    fail(line, column, fmt::format("M97: expected L1 .. L{} (the repeat count)", kMaxRepeats));
  const std::string label = fmt::format("N{}", n);
  Frame f = frame_at_call(label, back);
  const std::optional<Position> body = find(label, line, column);
  if (!body) fail_in_caller(f, line, column, fmt::format("M97 P{}: the file holds no block N{}", n, n));
  f.body = *body;
  f.repeats_left = times - 1;
  enter(std::move(f), line, column);
}

void SubprogramCalls::call_sub(const std::string& label, const std::vector<ParamValue>& arguments, Parameters& params,
                               Position back, int line, int column) {
  if (arguments.size() > static_cast<std::size_t>(kLocals))
    fail(line, column,
         fmt::format("{} call with {} arguments: at most {} (#1 .. #{})", label, arguments.size(), kLocals, kLocals));
  Frame f = frame_at_call(label, back);
  std::optional<Position> body = find(label, line, column);
  if (!body && label.rfind("o<", 0) == 0) body = find_elsewhere(f, label, label + " call", line, column);
  if (!body) fail_in_caller(f, line, column, fmt::format("{} call: the file holds no {} sub", label, label));
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

std::size_t SubprogramCalls::leave(bool m99, Parameters& params, int line, int column, int return_block) {
  if (frames_.empty())
    fail(line, column,
         m99 ? "M99 in the main program (Fanuc: run it again from its start, endlessly): not supported"
             : "endsub or return without a call");
  Frame& f = frames_.back();
  const Position at_m99{source_.next_line_offset(), source_.line_number() + 1, current_};  // for errors
  if (m99 && f.saved)
    fail(line, column, fmt::format("M99 inside the o-word sub {}: expected endsub or return", f.label));
  if (!m99 && !f.saved)
    fail(line, column, fmt::format("endsub or return inside {} (called by M98/M97): expected M99", f.label));
  if (return_block > 0 && f.repeats_left > 0)
    fail(line, column,
         fmt::format("M99 P{} in {} with repeats (L) left: whether the repeats or the return come "
                     "first differs between controls: not supported",
                     return_block, f.label));
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
  if (return_block > 0) return_to_block(return_block, done, at_m99, line, column);
  return done.loops;
}

/// M99 P<n>: the one block N<n> of the calling program, which runs from `caller_start` to the next
/// program number (O...) or '%' after its first block.
void SubprogramCalls::return_to_block(int n, const Frame& done, Position at_m99, int line, int column) {
  const std::string caller = frames_.empty() ? std::string("the main program") : frames_.back().label;
  seek(done.caller_start, line, column);
  std::vector<Position> hits;
  bool content = false;
  std::string_view text;
  for (std::uint64_t offset = source_.next_line_offset(); source_.next(text); offset = source_.next_line_offset()) {
    const bool boundary = is_percent_line(text) || leading_number(text, 'O') >= 0;
    if (boundary && content) break;
    if (boundary || text.find_first_not_of(" \t") == std::string_view::npos) continue;
    content = true;
    if (leading_number(text, 'N') == n) hits.push_back(Position{offset, source_.line_number(), current_});
  }
  if (hits.size() != 1) seek(at_m99, line, column);  // the error names the M99's file
  if (hits.empty()) fail(line, column, fmt::format("M99 P{}: {} has no block N{} to return to", n, caller, n));
  if (hits.size() > 1)
    fail(line, column,
         fmt::format("M99 P{}: {} has N{} at lines {} and {}: which one the control returns to depends "
                     "on its search; number the blocks apart",
                     n, caller, n, hits[0].line, hits[1].line));
  seek(hits[0], line, column);
}

}  // namespace ncpost::gcode
