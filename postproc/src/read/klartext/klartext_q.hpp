// SPDX-License-Identifier: Apache-2.0
#pragma once
// Q parameters of a Klartext program (TNC 426 ... 640): the store, the formula (`Q1 = Q2 * (3 +
// SIN(Q4))`), the FN functions 0 .. 13, and `X+Q1` in words. A formula is rewritten into the
// G-code expression syntax (gcode_expression.hpp) and evaluated there, where the two languages
// agree: + - * / with the usual precedence, ( ) as [ ], SIN COS TAN ASIN ACOS ATAN in degrees,
// SQRT ABS LN EXP, and comparisons; `^` is `**`, `SQ x` is x², `NEG x` is -x, `PI` is π.
// `LOG`, `INT`, `FRAC`, `SGN` and `%` are refused by name (their meaning is not taken over).
//
// Parameters: Q0 .. Q1999, QL0 .. QL499 (local), QR0 .. QR499 (remanent). A parameter the
// program has not set is refused where it is read ("Q5 is not set in this program"): the TNC
// would use whatever value it holds from before, which the program does not say.
#include <optional>
#include <string>
#include <string_view>

#include "ncpost/postproc/read/gcode/gcode_expression.hpp"

namespace ncpost::klartext {

/// A bad formula: `what` says why, `offset` where in the text (0-based).
struct QError {
  std::size_t offset = 0;
  std::string what;
};

/// The Q, QL and QR parameters of one program run.
class QParameters {
 public:
  /// "Q1", "QL5", "QR2" (upper case): the parameter's value, nullopt when not set.
  std::optional<double> get(std::string_view name) const;
  void set(std::string_view name, double value);

  /// The formula `text` evaluated; a QError when it cannot be.
  std::optional<double> evaluate(std::string_view text, QError& error) const;

 private:
  gcode::Parameters store_;
};

/// The parameter named at the start of `text` ("Q12", "QL3", "QR0"), its length in `length`;
/// nullopt when `text` does not start with one. Numbers beyond the TNC's ranges are refused in
/// `error`.
std::optional<std::string> q_name_at(std::string_view text, std::size_t& length);

/// One Q statement: `Q1 = formula` (from a `Q...` block or an FN 0..8, 13 block), or a
/// conditional jump (FN 9 .. 12: `IF a EQU b GOTO LBL n`).
struct QStatement {
  std::string target;   ///< "Q1" (assignment); "" for a jump
  std::string formula;  ///< the value; for a jump the left side of the comparison
  std::string compare;  ///< a jump's comparison: "EQU", "NE", "GT", "LT"
  std::string right;    ///< a jump's right side
  std::string label;    ///< the jump's label ("5", "\"NAME\"")
};

/// True when the jump's comparison holds for `left` and `right`.
bool compare_holds(const std::string& compare, double left, double right);

/// `Q1 = ...` as written after the statement "Q" (the text from the parameter on).
std::optional<QStatement> q_assignment_of(std::string_view text, QError& error);
/// `FN n: ...` (the text after FN); FN 14 and up are refused by name in `error`.
std::optional<QStatement> fn_statement_of(std::string_view text, QError& error);

/// `LBL n`, `LBL "name"`: the label key ("5", "\"NAME\""); nullopt when `text` names none.
std::optional<std::string> label_of(std::string_view text);
/// The label a whole line defines (`12 LBL 5 ; comment`): its key, or "" when the line is not a
/// label statement.
std::string label_defined_in(std::string_view line);

}  // namespace ncpost::klartext
