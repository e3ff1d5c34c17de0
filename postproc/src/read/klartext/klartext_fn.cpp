// SPDX-License-Identifier: Apache-2.0
// FN 0 .. 12 and LBL of Klartext (klartext_q.hpp): each FN statement as a formula assignment or a
// conditional jump.
#include <fmt/format.h>

#include <cctype>

#include "read/klartext/klartext_q.hpp"
#include "read/char_scan.hpp"

namespace ncpost::klartext {
namespace {

/// `text` split at the blank-separated word `word` (upper case): left, right; nullopt without it.
std::optional<std::pair<std::string, std::string>> split_at_word(std::string_view text, std::string_view word) {
  const std::string u = upper_of(text);
  const std::string key = fmt::format(" {} ", word);
  const std::size_t at = u.find(key);
  if (at == std::string::npos) return std::nullopt;
  return std::make_pair(trimmed(text.substr(0, at)), trimmed(text.substr(at + key.size())));
}

/// What FN 1 .. 8 write between their operands, rewritten as a formula.
std::optional<std::string> fn_formula(int n, const std::string& rhs) {
  switch (n) {
    case 0:
    case 1:
    case 2:
    case 3:
    case 5:
    case 6:
    case 7:
      return rhs;
    case 4: {
      const auto parts = split_at_word(rhs, "DIV");
      if (!parts) return std::nullopt;
      return fmt::format("({}) / ({})", parts->first, parts->second);
    }
    case 8: {
      const auto parts = split_at_word(rhs, "LEN");
      if (!parts) return std::nullopt;
      return fmt::format("SQRT(SQ({}) + SQ({}))", parts->first, parts->second);
    }
    default:
      return std::nullopt;
  }
}

constexpr const char* kFnNames[] = {"assignment",     "addition",   "subtraction",
                                    "multiplication", "division",   "square root",
                                    "sine",           "cosine",     "root of a sum of squares",
                                    "IF EQU GOTO",    "IF NE GOTO", "IF GT GOTO",
                                    "IF LT GOTO",     "angle (ANG)"};

/// FN 9 .. 12: `IF a OP b GOTO LBL n`.
std::optional<QStatement> fn_jump(int n, std::string_view body, QError& error) {
  static constexpr std::string_view kCompare[] = {"EQU", "NE", "GT", "LT"};
  const std::string_view op = kCompare[n - 9];
  const std::string u = upper_of(trimmed(body));
  const auto go = split_at_word(trimmed(body), "GOTO");
  const auto sides = go ? split_at_word(go->first, op) : std::nullopt;
  const std::string target = go ? go->second : std::string();
  const bool lbl = upper_of(target).rfind("LBL", 0) == 0;
  if (u.rfind("IF ", 0) != 0 || !sides || !lbl || !label_of(target.substr(3))) {
    error = {0, fmt::format("FN {}: expected IF value {} value GOTO LBL n (or LBL \"name\")", n, op)};
    return std::nullopt;
  }
  QStatement s;
  s.formula = trimmed(std::string_view(sides->first).substr(2));  // after IF
  s.compare = std::string(op);
  s.right = sides->second;
  s.label = *label_of(target.substr(3));
  return s;
}

}  // namespace

bool compare_holds(const std::string& compare, double left, double right) {
  if (compare == "EQU") return left == right;
  if (compare == "NE") return left != right;
  if (compare == "GT") return left > right;
  return left < right;
}

std::optional<QStatement> fn_statement_of(std::string_view text, QError& error) {
  std::size_t p = 0;
  while (p < text.size() && text[p] == ' ') ++p;
  const std::size_t digits = p;
  while (p < text.size() && std::isdigit(static_cast<unsigned char>(text[p]))) ++p;
  const std::size_t colon = text.find(':', p);
  if (p == digits || colon == std::string_view::npos || trimmed(text.substr(p, colon - p)) != "") {
    error = {0, "expected FN n: ... (a Q parameter function)"};
    return std::nullopt;
  }
  const int n = std::stoi(std::string(text.substr(digits, p - digits)));
  const std::string_view body = text.substr(colon + 1);
  if (n >= 9 && n <= 12) return fn_jump(n, body, error);
  if (n > 8) {
    error = {digits, fmt::format("FN {}{} is not read (FN 0 .. 12 are)", n,
                                 n == 13 ? fmt::format(" ({})", kFnNames[13]) : std::string())};
    return std::nullopt;
  }
  std::optional<QStatement> s = q_assignment_of(trimmed(body), error);
  if (!s) return std::nullopt;
  const auto formula = fn_formula(n, s->formula);
  if (!formula) {
    error = {colon + 1, fmt::format("FN {} ({}): expected Q = value {} value", n, kFnNames[n], n == 4 ? "DIV" : "LEN")};
    return std::nullopt;
  }
  s->formula = *formula;
  return s;
}

std::optional<std::string> label_of(std::string_view text) {
  const std::string t = trimmed(text);
  if (t.empty()) return std::nullopt;
  if (t.front() == '"') {
    const std::size_t close = t.find('"', 1);
    if (close == std::string::npos || close == 1) return std::nullopt;
    return t.substr(0, close + 1);
  }
  std::size_t p = 0;
  while (p < t.size() && std::isdigit(static_cast<unsigned char>(t[p]))) ++p;
  if (p == 0 || p > 6 || (p < t.size() && t[p] != ' ')) return std::nullopt;
  return std::to_string(std::stol(t.substr(0, p)));
}

std::string label_defined_in(std::string_view line) {
  std::size_t p = 0;
  const auto blanks = [&] {
    while (p < line.size() && (line[p] == ' ' || line[p] == '\t')) ++p;
  };
  blanks();
  if (p < line.size() && line[p] == '/') ++p;
  blanks();
  while (p < line.size() && std::isdigit(static_cast<unsigned char>(line[p]))) ++p;
  blanks();
  if (upper_of(line.substr(p, 4)) != "LBL ") return "";
  const std::string_view rest =
      line.substr(p + 4, line.find(';') == std::string_view::npos ? std::string_view::npos : line.find(';') - p - 4);
  return label_of(rest).value_or("");
}

}  // namespace ncpost::klartext
