// SPDX-License-Identifier: Apache-2.0
#pragma once
// The variables of a Sinumerik program and the values of its expressions.
//
// Variables: R parameters (`R0`..`R999`, always defined, 0 at the start as on the control after a
// reset of the program's R parameters is NOT assumed: an R parameter read before the program sets
// it is refused, its value being the control's), and the program's `DEF REAL|INT|BOOL|STRING
// name[=value][, ...]` variables (DEF without a value: 0, FALSE, "" as the control sets them).
// INT takes the rounded value of what is assigned (the control rounds), BOOL 1 or 0.
//
// Expressions are evaluated by the G-code reader's evaluator (gcode_expression.hpp) where the
// semantics agree: the Sinumerik text is rewritten into its bracket syntax, `(` -> `[`, names ->
// `#<name>`, `==` -> EQ, `<>` -> NE, `>=` -> GE, `<=` -> LE, `>` -> GT, `<` -> LT, `ATAN2(a,b)` ->
// `ATAN[a]/[b]`, `POT(x)` -> `[x]**2`, `TRUNC` -> `FIX`, TRUE/FALSE -> 1/0. Functions SIN COS TAN
// ASIN ACOS ATAN2 SQRT ABS POT TRUNC ROUND LN EXP (degrees), operators + - * / MOD AND OR XOR.
// Where the languages differ the expression is refused by name: comparisons and AND/OR/XOR at the
// same parenthesis level (Sinumerik binds comparisons last, the evaluator first: write
// parentheses), DIV, NOT, B_AND/B_OR/B_XOR, `<<`, system variables (`$...`), arrays, and strings
// outside MSG and T=.
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "ncpost/postproc/read/gcode/gcode_expression.hpp"

namespace ncpost::sinumerik {

/// A bad expression: `offset` is 0-based in the expression text.
struct ValueError {
  std::size_t offset;
  std::string what;
};

enum class VarType { real, integer, boolean, string };

class Values {
 public:
  /// Defines `name` (upper case) of `type`; redefinition in the same scope is an error (ValueError).
  void define(const std::string& name, VarType type);
  /// Whether `name` is a variable (R parameters included).
  bool known(const std::string& name) const;
  /// Sets a variable, converting to its type; ValueError for an unknown name or a string mismatch.
  void assign(const std::string& name, double value);
  void assign_string(const std::string& name, const std::string& value);
  std::optional<std::string> string_value(const std::string& name) const;
  /// The value of an expression (Sinumerik syntax); ValueError.
  double evaluate(std::string_view expression) const;
  /// A string expression: a literal "..." or a STRING variable.
  std::string evaluate_string(std::string_view expression) const;

  /// The variables saved for a subprogram's scope, and restored when it returns.
  struct Saved {
    std::map<std::string, VarType> types;
    gcode::Parameters params;
    std::map<std::string, std::string> strings;
  };
  Saved save() const { return {types_, params_, strings_}; }
  /// Back to `s`, except the R parameters, which are the channel's (global): they keep their values.
  void restore_scope(Saved s);

 private:
  struct Level;  ///< one parenthesis level of an expression being rewritten
  std::string to_bracket_syntax(std::string_view e) const;
  std::size_t name_token(std::string_view e, std::size_t i, std::string& out, std::vector<Level>& levels) const;
  std::map<std::string, VarType> types_;
  gcode::Parameters params_;
  std::map<std::string, std::string> strings_;
  std::set<std::string> r_set_;  ///< the R parameters set so far (their keys)
};

/// `R12` -> 12; -1 when `name` is no R parameter.
int r_parameter(std::string_view name);

}  // namespace ncpost::sinumerik
