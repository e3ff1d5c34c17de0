// SPDX-License-Identifier: Apache-2.0
// Q parameters and formulas of Klartext, evaluated by the G-code expression evaluator
// (klartext_q.hpp).
#include "read/klartext/klartext_q.hpp"
#include "read/char_scan.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <set>
#include <vector>

namespace ncpost::klartext {
namespace {

char lower(char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); }

/// A formula function: written before its argument, rewritten as `prefix arg suffix`.
struct Function {
  std::string_view name;
  std::string_view prefix;
  std::string_view suffix;
};
constexpr Function kFunctions[] = {
    {"SIN", "SIN[", "]"},   {"COS", "COS[", "]"},   {"TAN", "TAN[", "]"},   {"ASIN", "ASIN[", "]"},
    {"ACOS", "ACOS[", "]"}, {"ATAN", "ATAN[", "]"}, {"SQRT", "SQRT[", "]"}, {"ABS", "ABS[", "]"},
    {"LN", "LN[", "]"},     {"EXP", "EXP[", "]"},   {"SQ", "[[", "]**2]"},  {"NEG", "[-[", "]]"},
};
constexpr std::string_view kRefused[] = {"LOG", "INT", "FRAC", "SGN"};

/// A Klartext formula rewritten into the G-code expression syntax; the parameters it reads.
class Rewriter {
 public:
  explicit Rewriter(std::string_view text) : in_(text) {}

  bool run(QError& error) {
    while (at_ < in_.size()) {
      const char c = in_[at_];
      if (c == '(') {
        emit("[", at_++);
        closers_.emplace_back("]");
      } else if (c == ')') {
        if (closers_.empty()) return fail(error, "a ')' without its '('");
        emit(closers_.back(), at_++);
        closers_.pop_back();
      } else if (c == '^') {
        emit("**", at_++);
      } else if (c == '%') {
        return fail(error, "'%' (the remainder) in a Q formula is not read");
      } else if (is_alpha(c)) {
        if (!word(error)) return false;
      } else if (is_digit(c) || c == '.' || c == '+' || c == '-' || c == '*' || c == '/' || c == ' ' || c == '\t') {
        emit(std::string(1, c), at_++);
      } else if (decimal_comma_at(at_)) {  // -54,887: a decimal comma (as in coordinates: klartext_block)
        emit(".", at_++);
      } else {
        return fail(error, fmt::format("unexpected '{}' in a Q formula", c));
      }
    }
    if (!closers_.empty()) return fail(error, "a '(' without its ')'");
    return true;
  }

  const std::string& text() const { return out_; }
  const std::set<std::string>& reads() const { return reads_; }
  std::size_t source_offset(std::size_t out_offset) const {
    return out_offset < map_.size() ? map_[out_offset] : in_.size();
  }

 private:
  bool decimal_comma_at(std::size_t i) const {
    return in_[i] == ',' && i > 0 && is_digit(in_[i - 1]) && i + 1 < in_.size() && is_digit(in_[i + 1]);
  }
  void emit(std::string_view s, std::size_t from) {
    out_ += s;
    map_.insert(map_.end(), s.size(), from);
  }
  bool fail(QError& error, std::string what) const {
    error = {at_, std::move(what)};
    return false;
  }

  /// A parameter, PI, or a function and its argument.
  bool word(QError& error) {
    std::size_t length = 0;
    if (const auto q = q_name_at(in_.substr(at_), length)) {
      parameter(*q);
      at_ += length;
      return true;
    }
    std::string name;
    const std::size_t start = at_;
    while (at_ < in_.size() && is_alpha(in_[at_])) name += upper(in_[at_++]);
    if (name == "PI") {
      emit("3.14159265358979323846", start);
      return true;
    }
    for (std::string_view r : kRefused)
      if (name == r) return fail(error, fmt::format("{} in a Q formula is not read", name));
    for (const Function& f : kFunctions)
      if (name == f.name) return argument(f, error);
    at_ = start;
    return fail(error, fmt::format("'{}' is not a Q formula function or parameter", name));
  }

  void parameter(const std::string& q) {
    std::string key;
    for (char c : q) key += lower(c);
    emit("#<" + key + ">", at_);
    reads_.insert(q);
  }

  /// `SIN(...)`, or `SIN Q1` / `SIN +30` (one value without brackets).
  bool argument(const Function& f, QError& error) {
    while (at_ < in_.size() && (in_[at_] == ' ' || in_[at_] == '\t')) ++at_;
    emit(f.prefix, at_);
    if (at_ < in_.size() && in_[at_] == '(') {
      ++at_;
      closers_.emplace_back(f.suffix);
      return true;
    }
    if (at_ < in_.size() && (in_[at_] == '+' || in_[at_] == '-')) emit(std::string(1, in_[at_]), at_), ++at_;
    std::size_t length = 0;
    if (const auto q = q_name_at(in_.substr(at_), length)) {
      parameter(*q);
      at_ += length;
    } else if (at_ < in_.size() && (is_digit(in_[at_]) || in_[at_] == '.')) {
      while (at_ < in_.size() && (is_digit(in_[at_]) || in_[at_] == '.' || decimal_comma_at(at_)))
        emit(in_[at_] == ',' ? "." : std::string(1, in_[at_]), at_), ++at_;
    } else {
      return fail(error, fmt::format("{}: expected its argument, a number, a Q parameter or ( ... )", f.name));
    }
    emit(f.suffix, at_);
    return true;
  }

  std::string_view in_;
  std::size_t at_ = 0;
  std::string out_;
  std::vector<std::size_t> map_;
  std::vector<std::string> closers_;
  std::set<std::string> reads_;
};

std::string key_of(std::string_view name) {
  std::string key;
  for (char c : name) key += lower(c);
  return key;
}

}  // namespace

std::optional<std::string> q_name_at(std::string_view text, std::size_t& length) {
  if (text.empty() || upper(text[0]) != 'Q') return std::nullopt;
  std::size_t p = 1;
  std::string name = "Q";
  if (p < text.size() && (upper(text[p]) == 'L' || upper(text[p]) == 'R')) name += upper(text[p++]);
  const std::size_t digits = p;
  while (p < text.size() && is_digit(text[p])) ++p;
  if (p == digits || p - digits > 5 || (p < text.size() && is_alpha(text[p]))) return std::nullopt;
  const long n = std::stol(std::string(text.substr(digits, p - digits)));
  if (n > (name == "Q" ? 1999 : 499)) return std::nullopt;
  length = p;
  return name + std::to_string(n);
}

std::optional<double> QParameters::get(std::string_view name) const { return store_.get(key_of(name)); }

void QParameters::set(std::string_view name, double value) { store_.set(key_of(name), value); }

std::optional<double> QParameters::evaluate(std::string_view text, QError& error) const {
  Rewriter r(text);
  if (!r.run(error)) return std::nullopt;
  for (const std::string& q : r.reads())
    if (!get(q)) {
      error = {text.find(q), fmt::format("{} is not set in this program (the TNC would use the value it holds from "
                                         "before); set it before it is read",
                                         q)};
      return std::nullopt;
    }
  try {
    const gcode::Evaluator e(store_);
    std::size_t at = 0;
    const gcode::ParamValue v = e.expression(r.text(), at);
    while (at < r.text().size() && (r.text()[at] == ' ' || r.text()[at] == '\t')) ++at;
    if (at < r.text().size()) {
      error = {r.source_offset(at),
               fmt::format("unexpected '{}' after the formula's value", text.substr(r.source_offset(at)))};
      return std::nullopt;
    }
    if (!v || !std::isfinite(*v)) {
      error = {0, "the formula has no finite value"};
      return std::nullopt;
    }
    return v;
  } catch (const gcode::ExpressionError& x) {
    error = {r.source_offset(x.offset()), x.what()};
    return std::nullopt;
  }
}

std::optional<QStatement> q_assignment_of(std::string_view text, QError& error) {
  std::size_t length = 0;
  const auto q = q_name_at(text, length);
  const std::size_t equals = text.find('=');
  if (!q || equals == std::string_view::npos || trimmed(text.substr(length, equals - length)) != "") {
    error = {0, "expected a Q parameter assignment Q1 = formula (Q0 .. Q1999, QL0 .. QL499, QR0 .. QR499)"};
    return std::nullopt;
  }
  QStatement s;
  s.target = *q;
  s.formula = trimmed(text.substr(equals + 1));
  if (s.formula.empty()) {
    error = {equals, fmt::format("{} = without a value", *q)};
    return std::nullopt;
  }
  return s;
}

}  // namespace ncpost::klartext
