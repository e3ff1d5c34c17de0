// SPDX-License-Identifier: Apache-2.0
// The Sinumerik block tokenizer (sinumerik_line.hpp).
#include "read/sinumerik/sinumerik_line.hpp"
#include "read/char_scan.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cstdlib>

namespace ncpost::sinumerik {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }
bool is_name_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_' || c == '$'; }
bool is_name_char(char c) { return is_name_start(c) || is_digit(c); }

constexpr std::string_view kStatements[] = {
    "DEF",    "IF",      "ELSE",   "ENDIF", "WHILE", "ENDWHILE", "FOR",    "ENDFOR",  "REPEAT",  "UNTIL",
    "LOOP",   "ENDLOOP", "GOTOF",  "GOTOB", "GOTO",  "GOTOC",    "PROC",   "RET",     "CASE",    "SAVE",
    "EXTERN", "DEFINE",  "STOPRE", "REDEF", "MCALL", "CALL",     "PCALL",  "EXECUTE", "EXECTAB", "REPEATB",
    "TRANS",  "ATRANS",  "ROT",    "AROT",  "SCALE", "ASCALE",   "MIRROR", "AMIRROR", "RPL",     "AROTS",
    "ROTS",   "CROTS",   "SETMS",  "WAITM", "GET",   "RELEASE"};

bool is_statement(const std::string& name) {
  for (std::string_view s : kStatements)
    if (name == s) return true;
  return false;
}

/// Offset of the ';' that starts the comment (outside strings), or npos.
std::size_t comment_start(std::string_view t) {
  bool quoted = false;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] == '"')
      quoted = !quoted;
    else if (t[i] == ';' && !quoted)
      return i;
  }
  return std::string_view::npos;
}

std::size_t skip_blanks(std::string_view t, std::size_t at) {
  while (at < t.size() && is_blank(t[at])) ++at;
  return at;
}

/// The matching ')' of the '(' at `open`.
std::size_t closing_paren(std::string_view t, std::size_t open) {
  int depth = 0;
  bool quoted = false;
  for (std::size_t i = open; i < t.size(); ++i) {
    if (t[i] == '"') quoted = !quoted;
    if (quoted) continue;
    if (t[i] == '(' || t[i] == '[') ++depth;
    if ((t[i] == ')' || t[i] == ']') && --depth == 0) return i;
  }
  throw LexError{open, "'(' without its closing ')'"};
}

/// A signed number at `at` (no exponent); its end, or `at` when none.
std::size_t number_end(std::string_view t, std::size_t at) {
  std::size_t p = at;
  if (p < t.size() && (t[p] == '+' || t[p] == '-')) ++p;
  const std::size_t digits_from = p;
  while (p < t.size() && is_digit(t[p])) ++p;
  if (p < t.size() && t[p] == '.') ++p;
  while (p < t.size() && is_digit(t[p])) ++p;
  const std::string_view body = t.substr(digits_from, p - digits_from);
  return body.empty() || body == "." ? at : p;
}

/// The operand at `at` (a number, a name with its call or index, a string, a parenthesized
/// expression, with signs and NOT before it): its end.
std::size_t operand_end(std::string_view t, std::size_t at) {
  at = skip_blanks(t, at);
  while (at < t.size() && (t[at] == '+' || t[at] == '-')) at = skip_blanks(t, at + 1);
  if (at >= t.size()) throw LexError{at, "expected a value"};
  if (t[at] == '(') return closing_paren(t, at) + 1;
  if (t[at] == '"') {
    const std::size_t close = t.find('"', at + 1);
    if (close == std::string_view::npos) throw LexError{at, "a string without its closing '\"'"};
    return close + 1;
  }
  if (is_name_start(t[at])) {
    std::size_t p = at;
    while (p < t.size() && is_name_char(t[p])) ++p;
    if (upper(t.substr(at, p - at)) == "NOT") return operand_end(t, p);
    if (p < t.size() && (t[p] == '(' || t[p] == '[')) return closing_paren(t, p) + 1;
    return p;
  }
  const std::size_t n = number_end(t, at);
  if (n == at) throw LexError{at, fmt::format("expected a value, found '{}'", t[at])};
  return n;
}

/// The binary operator at `at` (after blanks): its length, or 0.
std::size_t operator_at(std::string_view t, std::size_t at) {
  if (at >= t.size()) return 0;
  const std::string_view two = t.substr(at, 2);
  if (two == "==" || two == "<>" || two == ">=" || two == "<=" || two == "<<") return 2;
  if (std::string_view("+-*/<>").find(t[at]) != std::string_view::npos) return 1;
  for (std::string_view w : {"AND", "OR", "XOR", "DIV", "MOD", "B_AND", "B_OR", "B_XOR"}) {
    if (upper(t.substr(at, w.size())) != w) continue;
    const std::size_t after = at + w.size();
    if (after < t.size() && is_name_char(t[after])) continue;
    if (at > 0 && is_name_char(t[at - 1])) continue;
    return w.size();
  }
  return 0;
}

void read_items(std::string_view t, std::size_t at, Line& line);

/// After a letter, the number from `from` to `to` is part of a name (A3=, R12=, CYCLE81(...) has
/// more letters): unsigned digits followed by '=' (not '==') or '(' or more name characters.
bool extended_address(std::string_view t, std::size_t from, std::size_t to) {
  for (std::size_t i = from; i < to; ++i)
    if (!is_digit(t[i])) return false;
  if (to < t.size() && (std::isalpha(static_cast<unsigned char>(t[to])) || t[to] == '_')) return false;
  const std::size_t after = skip_blanks(t, to);
  if (after >= t.size()) return false;
  if (t[after] == '(') return true;
  return t[after] == '=' && (after + 1 >= t.size() || t[after + 1] != '=');
}

}  // namespace

std::string upper(std::string_view s) {
  std::string u(s);
  for (char& c : u) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return u;
}

std::size_t expression_end(std::string_view t, std::size_t at) {
  std::size_t end = operand_end(t, at);
  for (;;) {
    const std::size_t op_at = skip_blanks(t, end);
    const std::size_t op = operator_at(t, op_at);
    if (op == 0) return end;
    end = operand_end(t, op_at + op);
  }
}

std::vector<std::string> split_arguments(std::string_view inside) {
  std::vector<std::string> out;
  int depth = 0;
  bool quoted = false;
  std::size_t from = 0;
  const auto push = [&](std::size_t to) {
    std::string_view a = inside.substr(from, to - from);
    while (!a.empty() && is_blank(a.front())) a.remove_prefix(1);
    while (!a.empty() && is_blank(a.back())) a.remove_suffix(1);
    out.emplace_back(a);
  };
  for (std::size_t i = 0; i < inside.size(); ++i) {
    const char c = inside[i];
    if (c == '"') quoted = !quoted;
    if (quoted) continue;
    if (c == '(' || c == '[') ++depth;
    if (c == ')' || c == ']') --depth;
    if (c == ',' && depth == 0) {
      push(i);
      from = i + 1;
    }
  }
  push(inside.size());
  if (out.size() == 1 && out[0].empty()) out.clear();
  return out;
}

Line lex_line(std::string_view text) {
  Line line;
  const std::size_t semi = comment_start(text);
  std::string_view t = text.substr(0, semi);
  if (semi != std::string_view::npos) {
    std::string_view c = text.substr(semi + 1);
    while (!c.empty() && is_blank(c.front())) c.remove_prefix(1);
    while (!c.empty() && is_blank(c.back())) c.remove_suffix(1);
    line.comment = std::string(c);
    line.comment_column = static_cast<int>(semi) + 1;
  }
  std::size_t at = skip_blanks(t, 0);
  if (at < t.size() && t[at] == '%') {
    std::string_view h = t.substr(at);
    while (!h.empty() && is_blank(h.back())) h.remove_suffix(1);
    line.header = upper(h);
    return line;
  }
  if (at < t.size() && t[at] == '/') {
    line.skip = true;
    at = skip_blanks(t, at + 1);
  }
  if (at + 1 < t.size() && (t[at] == 'N' || t[at] == 'n' || t[at] == ':') && is_digit(t[at + 1])) {
    std::size_t p = at + 1;
    while (p < t.size() && is_digit(t[p])) ++p;
    if (p >= t.size() || !is_name_char(t[p])) {
      line.block_number = std::strtol(std::string(t.substr(at + 1, p - at - 1)).c_str(), nullptr, 10);
      at = skip_blanks(t, p);
    }
  }
  // a label: name ':' (not '::' and not a block number)
  if (at < t.size() && is_name_start(t[at])) {
    std::size_t p = at;
    while (p < t.size() && is_name_char(t[p])) ++p;
    if (p < t.size() && t[p] == ':') {
      line.label = upper(t.substr(at, p - at));
      at = skip_blanks(t, p + 1);
    }
  }
  read_items(t, at, line);
  return line;
}

namespace {

/// The items of a block from `at`, or its statement and the text after it.
void read_items(std::string_view t, std::size_t at, Line& line) {
  for (at = skip_blanks(t, at); at < t.size(); at = skip_blanks(t, at)) {
    if (!is_name_start(t[at])) throw LexError{at, fmt::format("expected a word, found '{}'", t[at])};
    Item item;
    item.column = static_cast<int>(at) + 1;
    const std::size_t n = number_end(t, at + 1);
    if (std::isalpha(static_cast<unsigned char>(t[at])) && n != at + 1 && !extended_address(t, at + 1, n)) {
      item.kind = Item::Kind::word;
      item.name = upper(t.substr(at, 1));
      item.text = std::string(t.substr(at + 1, n - at - 1));
      item.value = std::strtod(item.text.c_str(), nullptr);
      line.items.push_back(std::move(item));
      at = n;
      continue;
    }
    std::size_t name_end = at;
    while (name_end < t.size() && is_name_char(t[name_end])) ++name_end;
    const std::size_t after = skip_blanks(t, name_end);
    const bool assign = after < t.size() && t[after] == '=' && (after + 1 >= t.size() || t[after + 1] != '=');
    const bool call = after < t.size() && t[after] == '(';
    item.name = upper(t.substr(at, name_end - at));
    if (line.items.empty() && line.statement.empty() && is_statement(item.name) && !assign) {
      line.statement = item.name;
      line.statement_column = item.column;
      std::string_view r = t.substr(skip_blanks(t, name_end));
      line.rest_column = static_cast<int>(t.size() - r.size()) + 1;
      while (!r.empty() && is_blank(r.back())) r.remove_suffix(1);
      line.rest = std::string(r);
      return;
    }
    if (assign) {
      const std::size_t from = skip_blanks(t, after + 1);
      const std::size_t end = expression_end(t, from);
      item.kind = Item::Kind::assign;
      item.text = std::string(t.substr(from, end - from));
      at = end;
    } else if (call) {
      const std::size_t close = closing_paren(t, after);
      item.kind = Item::Kind::call;
      item.text = std::string(t.substr(after + 1, close - after - 1));
      at = close + 1;
    } else {
      item.kind = Item::Kind::name;
      at = name_end;
    }
    line.items.push_back(std::move(item));
  }
}

}  // namespace
}  // namespace ncpost::sinumerik
