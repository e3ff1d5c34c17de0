// SPDX-License-Identifier: Apache-2.0
// Sinumerik variables and expressions through the G-code evaluator (sinumerik_values.hpp).
#include "read/sinumerik/sinumerik_values.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <vector>

#include "read/sinumerik/sinumerik_line.hpp"

namespace ncpost::sinumerik {
namespace {

bool is_identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '$'; }

std::string key_of(const std::string& name) {
  std::string k;
  for (char c : name) k += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return k;
}

/// Function names and their bracket-syntax spelling ("" : refused).
struct Function {
  std::string_view name;
  std::string_view open;   ///< written for "NAME("
  std::string_view comma;  ///< written for the top-level ',' (ATAN2 only)
  std::string_view close;  ///< written for the ')'
};
constexpr Function kFunctions[] = {
    {"SIN", "SIN[", "", "]"},       {"COS", "COS[", "", "]"},   {"TAN", "TAN[", "", "]"}, {"ASIN", "ASIN[", "", "]"},
    {"ACOS", "ACOS[", "", "]"},     {"SQRT", "SQRT[", "", "]"}, {"ABS", "ABS[", "", "]"}, {"ROUND", "ROUND[", "", "]"},
    {"TRUNC", "FIX[", "", "]"},     {"LN", "LN[", "", "]"},     {"EXP", "EXP[", "", "]"}, {"POT", "[[", "", "]**2]"},
    {"ATAN2", "ATAN[", "]/[", "]"},
};

const Function* function_named(const std::string& n) {
  for (const Function& f : kFunctions)
    if (f.name == n) return &f;
  return nullptr;
}

}  // namespace

struct Values::Level {
  const Function* function = nullptr;  ///< the call this '(' opened, if any
  bool comparison = false;
  bool logic = false;
};

int r_parameter(std::string_view name) {
  if (name.size() < 2 || (name[0] != 'R' && name[0] != 'r')) return -1;
  int n = 0;
  for (std::size_t i = 1; i < name.size(); ++i) {
    if (!std::isdigit(static_cast<unsigned char>(name[i]))) return -1;
    n = n * 10 + (name[i] - '0');
    if (n > gcode::Parameters::kLastUserNumber) return -1;
  }
  return n;
}

void Values::define(const std::string& name, VarType type) {
  if (r_parameter(name) >= 0) throw ValueError{0, fmt::format("DEF {}: R parameters are predefined", name)};
  const auto letter_ = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; };
  if (name.size() < 2 || !letter_(name[0]) || !letter_(name[1]))
    throw ValueError{
        0, fmt::format("DEF {}: a name starts with two letters or underscores (one letter is an address)", name)};
  types_[name] = type;
  if (type == VarType::string)
    strings_[name] = "";
  else
    params_.set(key_of(name), 0.0);
}

bool Values::known(const std::string& name) const { return r_parameter(name) >= 0 || types_.count(name) > 0; }

void Values::assign(const std::string& name, double value) {
  if (r_parameter(name) >= 0) {
    params_.set(key_of(name), value);
    r_set_.insert(key_of(name));
    return;
  }
  const auto it = types_.find(name);
  if (it == types_.end())
    throw ValueError{0, fmt::format("{} is not defined (DEF REAL/INT/BOOL {} first)", name, name)};
  if (it->second == VarType::string)
    throw ValueError{0, fmt::format("{} is a STRING: a number cannot be assigned", name)};
  if (it->second == VarType::integer) value = std::round(value);
  if (it->second == VarType::boolean) value = value != 0.0 ? 1.0 : 0.0;
  params_.set(key_of(name), value);
}

void Values::assign_string(const std::string& name, const std::string& value) {
  const auto it = types_.find(name);
  if (it == types_.end() || it->second != VarType::string)
    throw ValueError{0, fmt::format("{} is not a STRING variable", name)};
  strings_[name] = value;
}

void Values::restore_scope(Saved s) {
  for (const std::string& r : r_set_) s.params.set(r, params_.get(r));
  types_ = std::move(s.types);
  params_ = std::move(s.params);
  strings_ = std::move(s.strings);
}

std::optional<std::string> Values::string_value(const std::string& name) const {
  const auto it = strings_.find(name);
  if (it == strings_.end()) return std::nullopt;
  return it->second;
}

std::string Values::evaluate_string(std::string_view e) const {
  while (!e.empty() && e.front() == ' ') e.remove_prefix(1);
  while (!e.empty() && e.back() == ' ') e.remove_suffix(1);
  if (e.size() >= 2 && e.front() == '"' && e.back() == '"' &&
      e.substr(1, e.size() - 2).find('"') == std::string_view::npos)
    return std::string(e.substr(1, e.size() - 2));
  if (auto s = string_value(upper(e))) return *s;
  throw ValueError{
      0, fmt::format("'{}': expected a string \"...\" or a STRING variable (string operations are not read)", e)};
}

double Values::evaluate(std::string_view e) const {
  const std::string bracket = "[" + to_bracket_syntax(e) + "]";
  gcode::Evaluator ev(params_);
  std::size_t at = 0;
  try {
    const gcode::ParamValue v = ev.value(bracket, at);
    while (at < bracket.size() && bracket[at] == ' ') ++at;
    if (at != bracket.size()) throw ValueError{0, fmt::format("'{}': unexpected text in the expression", e)};
    if (!v) throw ValueError{0, fmt::format("'{}' has no value (a variable read before it is set)", e)};
    return *v;
  } catch (const gcode::ExpressionError& x) {
    throw ValueError{0, fmt::format("'{}': {}", e, x.what())};
  }
}

/// A name at `i` of `e` (a function call, an operator word, a constant or a variable) in the
/// evaluator's syntax, appended to `out`; the index after it.
std::size_t Values::name_token(std::string_view e, std::size_t i, std::string& out, std::vector<Level>& levels) const {
  std::size_t j = i;
  while (j < e.size() && is_identifier_char(e[j])) ++j;
  const std::string name = upper(e.substr(i, j - i));
  std::size_t k = j;
  while (k < e.size() && e[k] == ' ') ++k;
  if (k < e.size() && e[k] == '(') {
    const Function* f = function_named(name);
    if (!f) throw ValueError{i, fmt::format("{}(...): this function is not read", name)};
    out += f->open;
    levels.push_back(Level{f});
    return k + 1;
  }
  if (name == "AND" || name == "OR" || name == "XOR" || name == "MOD") {
    if (name != "MOD") levels.back().logic = true;
    out += " " + name + " ";
  } else if (name == "TRUE" || name == "FALSE") {
    out += name == "TRUE" ? "1" : "0";
  } else if (name == "DIV" || name == "NOT" || name.rfind("B_", 0) == 0) {
    throw ValueError{i, fmt::format("{} is not read (write the expression with + - * / MOD AND OR XOR)", name)};
  } else if (name[0] == '$') {
    throw ValueError{i, fmt::format("{} is a system variable: its value is the control's, so it is not read", name)};
  } else if (k < e.size() && e[k] == '[') {
    throw ValueError{i, fmt::format("{}[...]: arrays are not read", name)};
  } else if (types_.count(name) && types_.at(name) == VarType::string) {
    throw ValueError{i, fmt::format("{} is a STRING: strings are only read in MSG() and T=", name)};
  } else if (known(name)) {
    out += "#<" + key_of(name) + ">";
  } else {
    throw ValueError{i, fmt::format("{} is not a defined variable (DEF it, or an R parameter)", name)};
  }
  return j;
}

namespace {

constexpr const char* kMixed =
    "a comparison beside AND/OR/XOR without parentheses: Sinumerik binds comparisons last, "
    "other languages first; write (A==1) AND (B==2)";

/// A comparison operator at `i` in the evaluator's words (" EQ " ...), its length in `length`; null otherwise.
const char* comparison_at(std::string_view e, std::size_t i, std::size_t& length) {
  const std::string_view two = e.substr(i, 2);
  length = 2;
  if (two == "==") return " EQ ";
  if (two == "<>") return " NE ";
  if (two == ">=") return " GE ";
  if (two == "<=") return " LE ";
  if (two == "<<") throw ValueError{i, "'<<' (string concatenation) is not read outside MSG()"};
  length = 1;
  if (e[i] == '<') return " LT ";
  if (e[i] == '>') return " GT ";
  return nullptr;
}

}  // namespace

/// The expression in the evaluator's syntax (see the header); ValueError where the languages differ.
std::string Values::to_bracket_syntax(std::string_view e) const {
  std::string out;
  std::vector<Level> levels(1);
  for (std::size_t i = 0; i < e.size();) {
    const char c = e[i];
    std::size_t length = 0;
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_' || c == '$') {
      i = name_token(e, i, out, levels);
    } else if (const char* word = comparison_at(e, i, length)) {
      levels.back().comparison = true;
      out += word;
      i += length;
    } else if (c == '(') {
      out += '[';
      levels.push_back(Level{});
      ++i;
    } else if (c == ')' || c == ',') {
      if (levels.size() < 2) throw ValueError{i, fmt::format("'{}' without its '('", c)};
      const Function* f = levels.back().function;
      if (c == ',' && (!f || f->comma.empty())) throw ValueError{i, "',' outside a function's arguments"};
      if (levels.back().comparison && levels.back().logic) throw ValueError{i, kMixed};
      out += c == ',' ? std::string(f->comma) : f ? std::string(f->close) : std::string("]");
      if (c == ',')
        levels.back().comparison = levels.back().logic = false;
      else
        levels.pop_back();
      ++i;
    } else if (c == '"') {
      throw ValueError{i, "a string is not a number (strings are only read in MSG() and T=)"};
    } else {
      out += c;
      ++i;
    }
  }
  if (levels.back().comparison && levels.back().logic) throw ValueError{0, kMixed};
  return out;
}

}  // namespace ncpost::sinumerik
