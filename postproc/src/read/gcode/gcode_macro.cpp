// SPDX-License-Identifier: Apache-2.0
// Macro statements of one line (see gcode_macro.hpp).
#include "ncpost/postproc/read/gcode/gcode_macro.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <utility>
#include <vector>

#include "ncpost/machines/input_error.hpp"
#include "read/char_scan.hpp"
#include "ncpost/postproc/read/gcode/gcode_integer_words.hpp"

namespace ncpost::gcode {
namespace {

bool is_keyword(const std::string& w) {
  return w == "IF" || w == "WHILE" || w == "GOTO" || w == "END" || w == "DO" || w == "THEN";
}

/// The end of the '(' comment at `at` (just after its closing ')', or the end of the line).
std::size_t comment_end(std::string_view s, std::size_t at) {
  int depth = 0;
  for (; at < s.size(); ++at) {
    if (s[at] == '(') ++depth;
    if (s[at] == ')' && --depth == 0) return at + 1;
  }
  return s.size();
}

/// The end of the '"' string at `at` (just after its closing '"', or the end of the line): a
/// Sinumerik MSG("...") text, copied as it is.
std::size_t string_end(std::string_view s, std::size_t at) {
  const std::size_t close = s.find('"', at + 1);
  return close == std::string_view::npos ? s.size() : close + 1;
}

/// One line being rewritten.
struct Rewriter {
  std::string_view line;
  Parameters& params;
  std::string& out;
  const std::string& file;
  int line_number;
  Evaluator ev{params};
  std::vector<std::pair<ParamRef, ParamValue>> assignments;
  MacroFlow flow;

  [[noreturn]] void fail(std::size_t offset, const std::string& what) const {
    throw InputError({file, line_number, static_cast<int>(offset) + 1}, what, std::string(line));
  }

  void blank(std::size_t from, std::size_t to) { out.append(to - from, ' '); }

  /// A whole number >= 0 at `at` (GOTO's block number, a loop number).
  int whole_number(std::size_t& at, const char* what) {
    const std::size_t start = at;
    const ParamValue v = ev.value(line, at);
    if (!v || *v < 0.0 || std::abs(*v - std::round(*v)) > 1e-9 || *v > 1e9)
      fail(start, fmt::format("{}: expected a whole number >= 0", what));
    return static_cast<int>(std::lround(*v));
  }

  double condition(std::size_t& at, const char* keyword) {
    skip_blanks(line, at);
    if (at >= line.size() || line[at] != '[')
      fail(at, fmt::format("{} takes its condition in brackets: {} [...]", keyword, keyword));
    const std::size_t start = at;
    const ParamValue v = ev.value(line, at);
    if (!v) fail(start, fmt::format("the condition of {} is vacant", keyword));
    return *v;
  }

  void set_flow(MacroFlow f, std::size_t at) {
    if (flow.kind != MacroFlow::Kind::none) fail(at, "two control statements (GOTO, WHILE, DO, END) in one block");
    flow = f;
  }

  std::string_view keyword_after(std::size_t& at) {
    skip_blanks(line, at);
    const std::string w = word_at(line, at);
    at += w.size();
    if (w == "GOTO") return "GOTO";
    if (w == "THEN") return "THEN";
    if (w == "DO") return "DO";
    return "";
  }

  /// `#ref = expression` at `at` (the '#'); returns where it ends.
  std::size_t assignment(std::size_t at) {
    const std::size_t start = at;
    const ParamRef ref = ev.reference(line, at);
    skip_blanks(line, at);
    if (at >= line.size() || line[at] != '=')
      fail(start, "a parameter where a word is expected (an assignment is written #1 = value)");
    ++at;
    const ParamValue v = ev.expression(line, at);
    if (ref.name.empty() && ref.number == 0) fail(start, "#0 is always vacant: it cannot be set");
    if (ref.name.empty() && ref.number > Parameters::kLastUserNumber)
      fail(start, fmt::format("#{} is a system variable the program reads (the control sets it): it cannot be set",
                              ref.number));
    assignments.emplace_back(ref, v);
    blank(start, at);
    return at;
  }

  /// The value of the word whose letter ends at `at`, when it is an expression: replaced by its
  /// number. Returns where the word ends.
  std::size_t word_value(std::size_t at, char letter) {
    std::size_t look = at;
    skip_blanks(line, look);
    if (look >= line.size()) return at;
    bool expression = line[look] == '#' || line[look] == '[';
    if (line[look] == '-' || line[look] == '+') {
      std::size_t after = look + 1;
      skip_blanks(line, after);
      expression = after < line.size() && (line[after] == '#' || line[after] == '[');
    }
    if (!expression) return at;
    const std::size_t start = at;
    const ParamValue v = ev.value(line, at);
    if (!v)
      fail(look, fmt::format("{} takes a vacant value (#0 or a parameter never set): Fanuc leaves the word out, "
                             "LinuxCNC reads 0; set the parameter first",
                             letter));
    // a parameter's value is a number in the program's units on every control: a length or angle
    // word gets its decimal point, so that no reading of integers (--integer-words) takes it for
    // least increments
    std::string text = word_number(*v);
    if ((kIntegerWordLetters.find(letter) != std::string_view::npos || letter == 'Q') &&
        text.find('.') == std::string::npos)
      text += '.';
    if (text.size() < at - start) out.append(at - start - text.size(), ' ');
    out += text;
    return at;
  }

  /// The statement `keyword` at `at`; returns where the line goes on.
  std::size_t statement(std::size_t at, const std::string& keyword) {
    const std::size_t start = at;
    const int column = static_cast<int>(at) + 1;
    at += keyword.size();
    if (keyword == "IF") {
      const bool holds = condition(at, "IF") != 0.0;
      std::size_t kw = at;
      const std::string_view then = keyword_after(kw);
      if (then == "GOTO") {
        at = kw;
        const int n = whole_number(at, "GOTO");
        if (holds) set_flow({MacroFlow::Kind::go_to, n, true, column}, start);
        blank(start, at);
        return at;
      }
      if (then == "THEN") {
        blank(start, kw);
        if (holds) return kw;  // the statement after THEN is read as the rest of the line
        blank(kw, line.size());
        return line.size();
      }
      fail(kw, "IF [...] is followed by GOTO n or THEN");
    }
    if (keyword == "GOTO") {
      const int n = whole_number(at, "GOTO");
      set_flow({MacroFlow::Kind::go_to, n, true, column}, start);
    } else if (keyword == "WHILE") {
      const bool holds = condition(at, "WHILE") != 0.0;
      std::size_t kw = at;
      if (keyword_after(kw) != "DO") fail(kw, "WHILE [...] is followed by DO m");
      at = kw;
      set_flow({MacroFlow::Kind::while_do, whole_number(at, "DO"), holds, column}, start);
    } else if (keyword == "DO") {
      set_flow({MacroFlow::Kind::while_do, whole_number(at, "DO"), true, column}, start);
    } else if (keyword == "END") {
      set_flow({MacroFlow::Kind::end_loop, whole_number(at, "END"), true, column}, start);
    } else {
      fail(start, fmt::format("{} without IF", keyword));
    }
    blank(start, at);
    return at;
  }

  /// LinuxCNC o-words (`o100 while [...]`, `o<name> sub`): subroutines and flow, not read here.
  void refuse_o_word_flow() const {
    std::size_t at = 0;
    skip_blanks(line, at);
    if (at < line.size() && line[at] == '/') ++at;
    skip_blanks(line, at);
    if (at >= line.size() || upper(line[at]) != 'O') return;
    std::size_t p = at + 1;
    if (p < line.size() && line[p] == '<') {
      p = line.find('>', p);
      if (p == std::string_view::npos) return;
      ++p;
    } else {
      while (p < line.size() && is_digit(line[p])) ++p;
      if (p == at + 1) return;
    }
    skip_blanks(line, p);
    const std::string w = word_at(line, p);
    static constexpr std::string_view kOWords[] = {"SUB",    "ENDSUB", "CALL",     "RETURN", "IF",
                                                   "ELSEIF", "ELSE",   "ENDIF",    "WHILE",  "ENDWHILE",
                                                   "DO",     "REPEAT", "ENDREPEA", "BREAK",  "CONTINUE"};
    if (std::find(std::begin(kOWords), std::end(kOWords), w) == std::end(kOWords)) return;
    fail(at, fmt::format("LinuxCNC o-word {} (o-word subroutines and control flow) is not supported: post the "
                         "program with its o-words expanded, or the CL data",
                         w));
  }

  void run() {
    refuse_o_word_flow();
    std::size_t i = 0;
    const std::size_t n = line.size();
    while (i < n) {
      const char c = line[i];
      if (c == '(' || c == '"') {
        const std::size_t e = c == '(' ? comment_end(line, i) : string_end(line, i);
        out.append(line.substr(i, e - i));
        i = e;
      } else if (c == ';') {
        out.append(line.substr(i));
        i = n;
      } else if (c == '#') {
        i = assignment(i);
      } else if (is_alpha(c)) {
        if (i == 0 || !is_alpha(line[i - 1])) {
          const std::string w = word_at(line, i);
          if (is_keyword(w)) {
            i = statement(i, w);
            continue;
          }
        }
        out += c;
        ++i;
        if (i < n && !is_alpha(line[i])) i = word_value(i, upper(c));
      } else {
        out += c;
        ++i;
      }
    }
    for (auto& [ref, v] : assignments) {
      if (!ref.name.empty())
        params.set(ref.name, v);
      else
        params.set(ref.number, v);
    }
  }
};

}  // namespace

bool may_hold_macro(std::string_view line) {
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (c == '(' || c == '"') {
      i = (c == '(' ? comment_end(line, i) : string_end(line, i)) - 1;
    } else if (c == ';') {
      return false;
    } else if (c == '#' || c == '[') {
      return true;
    } else if (is_alpha(c) && (i == 0 || !is_alpha(line[i - 1])) && i + 1 < line.size() && is_alpha(line[i + 1])) {
      if (is_keyword(word_at(line, i))) return true;
    }
  }
  return false;
}

MacroFlow apply_macro_line(std::string_view line, Parameters& params, std::string& out, const std::string& file,
                           int line_number) {
  out.clear();
  Rewriter r{line, params, out, file, line_number};
  try {
    r.run();
  } catch (const ExpressionError& e) {
    r.fail(e.offset(), e.what());
  }
  return r.flow;
}

}  // namespace ncpost::gcode
