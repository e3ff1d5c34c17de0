// SPDX-License-Identifier: Apache-2.0
// The parameter and expression evaluator (see gcode_expression.hpp for the rules).
#include "ncpost/postproc/read/gcode/gcode_expression.hpp"
#include "ncpost/kinematics/units.hpp"
#include "read/char_scan.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>

namespace ncpost::gcode {
namespace {

bool whole(double v) { return std::abs(v - std::round(v)) < 1e-9; }

double need(const ParamValue& v, std::size_t offset, const char* where) {
  if (!v)
    throw ExpressionError(offset, fmt::format("a vacant value (#0 or a parameter never set) in {}: Fanuc and "
                                              "LinuxCNC read it differently; set the parameter first",
                                              where));
  return *v;
}

/// The binary operators by level, lowest first.
struct Operator {
  const char* name;
  int level;
};
constexpr Operator kOperators[] = {{"OR", 0}, {"XOR", 0}, {"AND", 1}, {"EQ", 2},  {"NE", 2},
                                   {"GT", 2}, {"GE", 2},  {"LT", 2},  {"LE", 2},  {"+", 3},
                                   {"-", 3},  {"*", 4},   {"/", 4},   {"MOD", 4}, {"**", 5}};
constexpr int kTopLevel = 5;

/// The operator at `at` of `level`, or nullptr.
const Operator* operator_at(std::string_view s, std::size_t at, int level) {
  if (at >= s.size()) return nullptr;
  const std::string w = word_at(s, at);
  for (const Operator& op : kOperators) {
    if (op.level != level) continue;
    const std::string_view name(op.name);
    if (is_alpha(name[0])) {
      if (w == name) return &op;
    } else if (s.substr(at, name.size()) == name) {
      if (name == "*" && s.substr(at, 2) == "**") continue;  // the power, a level above
      return &op;
    }
  }
  return nullptr;
}

double apply(const Operator& op, const ParamValue& a, const ParamValue& b, std::size_t offset) {
  const std::string_view name(op.name);
  if (name == "EQ" || name == "NE") {
    const bool equal = (!a && !b) || (a && b && *a == *b);
    return (name == "EQ") == equal ? 1.0 : 0.0;
  }
  const double x = need(a, offset, fmt::format("{}", name).c_str());
  const double y = need(b, offset, fmt::format("{}", name).c_str());
  if (name == "+") return x + y;
  if (name == "-") return x - y;
  if (name == "*") return x * y;
  if (name == "/") {
    if (y == 0.0) throw ExpressionError(offset, "division by zero");
    return x / y;
  }
  if (name == "**") {
    const double r = std::pow(x, y);
    if (!std::isfinite(r)) throw ExpressionError(offset, fmt::format("{} ** {} has no finite value", x, y));
    return r;
  }
  if (name == "MOD") {
    if (y == 0.0) throw ExpressionError(offset, "MOD by zero");
    if (x < 0.0 || y < 0.0)
      throw ExpressionError(offset, fmt::format("{} MOD {}: the sign of MOD with a negative operand differs between "
                                                "controls; write it with FIX and a division",
                                                x, y));
    return std::fmod(x, y);
  }
  if (name == "GT") return x > y ? 1.0 : 0.0;
  if (name == "GE") return x >= y ? 1.0 : 0.0;
  if (name == "LT") return x < y ? 1.0 : 0.0;
  if (name == "LE") return x <= y ? 1.0 : 0.0;
  // AND OR XOR: logical on LinuxCNC, bitwise on Fanuc; the same for 0 and 1 only
  if (!((x == 0.0 || x == 1.0) && (y == 0.0 || y == 1.0)))
    throw ExpressionError(offset, fmt::format("{} {} {}: AND, OR and XOR of values other than 0 and 1 are bitwise on "
                                              "Fanuc and logical on LinuxCNC; compare first (EQ, NE, GT, ...)",
                                              x, name, y));
  const bool p = x != 0.0, q = y != 0.0;
  if (name == "AND") return p && q ? 1.0 : 0.0;
  if (name == "OR") return p || q ? 1.0 : 0.0;
  return p != q ? 1.0 : 0.0;
}

}  // namespace

ParamValue Parameters::get(const std::string& name) const {
  const auto it = named_.find(name);
  return it == named_.end() ? std::nullopt : it->second;
}

std::string word_number(double v) {
  if (whole(v) && std::abs(v) < 1e15) return fmt::format("{}", static_cast<long long>(std::llround(v)));
  std::string s = fmt::format("{:.10f}", v);
  while (s.back() == '0') s.pop_back();
  return s;
}

ParamRef Evaluator::reference(std::string_view s, std::size_t& at) const {
  const std::size_t start = at;
  ++at;  // '#'
  skip_blanks(s, at);
  ParamRef ref;
  if (at < s.size() && s[at] == '<') {
    const std::size_t close = s.find('>', at);
    if (close == std::string_view::npos) throw ExpressionError(at, "a named parameter without its closing '>'");
    for (std::size_t i = at + 1; i < close; ++i)
      if (s[i] != ' ' && s[i] != '\t') ref.name += static_cast<char>(std::tolower(static_cast<unsigned char>(s[i])));
    if (ref.name.empty()) throw ExpressionError(at, "an empty parameter name '#<>'");
    at = close + 1;
    return ref;
  }
  const ParamValue n = value(s, at);  // #1, #[...], ##1
  const double number = need(n, start, "a parameter number");
  if (!whole(number) || number < 0.0)
    throw ExpressionError(start, fmt::format("#{}: a parameter number is a whole number >= 0", number));
  if (number > Parameters::kLastUserNumber && number < 1e6 && params_.system(static_cast<int>(number))) {
    ref.number = static_cast<int>(number);
    return ref;
  }
  if (number > Parameters::kLastUserNumber)
    throw ExpressionError(start, fmt::format("#{} is a system variable (work offsets, modal state, alarms, tool data, "
                                             "...): its meaning is the control's, so it is not read; set a parameter "
                                             "#1 .. #999 instead",
                                             fmt::format("{:.0f}", number)));
  ref.number = static_cast<int>(number);
  return ref;
}

ParamValue Evaluator::read(const ParamRef& ref, std::size_t) const {
  if (!ref.name.empty()) return params_.get(ref.name);
  if (ref.number == 0) return std::nullopt;
  if (ref.number > Parameters::kLastUserNumber) return params_.system(ref.number);
  return params_.get(ref.number);
}

ParamValue Evaluator::value(std::string_view s, std::size_t& at) const {
  skip_blanks(s, at);
  if (at >= s.size()) throw ExpressionError(at, "expected a value, found the end of the line");
  const std::size_t start = at;
  const char c = s[at];
  if (c == '+' || c == '-') {
    ++at;
    const ParamValue v = value(s, at);
    return c == '-' ? -need(v, start, "a negation") : need(v, start, "a sign");
  }
  if (c == '[') {
    ++at;
    const ParamValue v = binary(s, at, 0);
    skip_blanks(s, at);
    if (at >= s.size() || s[at] != ']') throw ExpressionError(at, "expected ']' closing the expression");
    ++at;
    return v;
  }
  if (c == '#') {
    const ParamRef ref = reference(s, at);
    return read(ref, start);
  }
  if (is_digit(c) || c == '.') {
    std::size_t end = at;
    while (end < s.size() && is_digit(s[end])) ++end;
    if (end < s.size() && s[end] == '.') ++end;
    while (end < s.size() && is_digit(s[end])) ++end;
    if (end == at + 1 && c == '.') throw ExpressionError(at, "malformed number '.'");
    const double v = std::strtod(std::string(s.substr(at, end - at)).c_str(), nullptr);
    if (!std::isfinite(v)) throw ExpressionError(at, "a number beyond the range of numbers");
    at = end;
    return v;
  }
  if (is_alpha(c)) {
    const std::string name = word_at(s, at);
    at += name.size();
    return function(s, at, name, start);
  }
  throw ExpressionError(
      at, fmt::format("expected a value (a number, #parameter, [expression] or function), found '{}'", c));
}

ParamValue Evaluator::expression(std::string_view s, std::size_t& at) const { return binary(s, at, 0); }

ParamValue Evaluator::binary(std::string_view s, std::size_t& at, int level) const {
  if (level > kTopLevel) return value(s, at);
  ParamValue left = binary(s, at, level + 1);
  for (;;) {
    std::size_t look = at;
    skip_blanks(s, look);
    const Operator* op = operator_at(s, look, level);
    if (!op) return left;
    at = look + std::string_view(op->name).size();
    // ** binds to the right (2 ** 3 ** 2 = 2 ** 9)
    const ParamValue right = level == kTopLevel ? binary(s, at, level) : binary(s, at, level + 1);
    left = apply(*op, left, right, look);
    if (left && !std::isfinite(*left))
      throw ExpressionError(look, fmt::format("'{}' gives a value beyond the range of numbers", op->name));
    if (level == kTopLevel) return left;
  }
}

/// EXISTS[#<name>] (LinuxCNC): 1 when the parameter is set, else 0.
ParamValue Evaluator::exists(std::string_view s, std::size_t& at, std::size_t start) const {
  skip_blanks(s, at);
  if (at >= s.size() || s[at] != '[') throw ExpressionError(at, "expected '[' after EXISTS");
  ++at;
  skip_blanks(s, at);
  if (at >= s.size() || s[at] != '#') throw ExpressionError(at, "EXISTS takes a named parameter: EXISTS[#<name>]");
  const ParamRef ref = reference(s, at);
  skip_blanks(s, at);
  if (at >= s.size() || s[at] != ']') throw ExpressionError(at, "expected ']' closing EXISTS");
  ++at;
  if (ref.name.empty()) return read(ref, start).has_value() ? 1.0 : 0.0;
  return params_.exists(ref.name) ? 1.0 : 0.0;
}

ParamValue Evaluator::function(std::string_view s, std::size_t& at, const std::string& name, std::size_t start) const {
  const auto bracketed = [&]() -> ParamValue {
    skip_blanks(s, at);
    if (at >= s.size() || s[at] != '[') throw ExpressionError(at, fmt::format("expected '[' after {}", name));
    return value(s, at);
  };
  if (name == "EXISTS") return exists(s, at, start);
  if (name == "ATAN") {
    const double y = need(bracketed(), start, "ATAN");
    std::size_t look = at;
    skip_blanks(s, look);
    if (look >= s.size() || s[look] != '/') return std::atan(y) / kRadPerDeg;
    at = look + 1;
    return std::atan2(y, need(bracketed(), start, "ATAN")) / kRadPerDeg;
  }
  using Fn = double (*)(double);
  struct Known {
    const char* name;
    Fn fn;
  };
  static const Known kFunctions[] = {
      {"SIN", [](double d) { return std::sin(d * kRadPerDeg); }},
      {"COS", [](double d) { return std::cos(d * kRadPerDeg); }},
      {"TAN", [](double d) { return std::tan(d * kRadPerDeg); }},
      {"ASIN", [](double v) { return std::asin(v) / kRadPerDeg; }},
      {"ACOS", [](double v) { return std::acos(v) / kRadPerDeg; }},
      {"SQRT", [](double v) { return std::sqrt(v); }},
      {"ABS", [](double v) { return std::abs(v); }},
      {"ROUND", [](double v) { return std::round(v); }},
      {"FIX", [](double v) { return std::floor(v); }},
      {"FUP", [](double v) { return std::ceil(v); }},
      {"LN", [](double v) { return std::log(v); }},
      {"EXP", [](double v) { return std::exp(v); }},
  };
  for (const Known& k : kFunctions) {
    if (name != k.name) continue;
    const double arg = need(bracketed(), start, k.name);
    if ((name == "FIX" || name == "FUP") && arg < 0.0 && !whole(arg))
      throw ExpressionError(start,
                            fmt::format("{}[{}]: of a negative fraction Fanuc rounds toward {} zero and "
                                        "LinuxCNC {}; the program's control decides, so it is not read",
                                        name, arg, name == "FIX" ? "" : "away from ", name == "FIX" ? "down" : "up"));
    const double r = k.fn(arg);
    if (!std::isfinite(r)) throw ExpressionError(start, fmt::format("{}[{}] has no finite value", name, arg));
    return r;
  }
  if (name.empty()) throw ExpressionError(start, "expected a value");
  throw ExpressionError(start, fmt::format("unknown function or word '{}' in an expression", name));
}

}  // namespace ncpost::gcode
