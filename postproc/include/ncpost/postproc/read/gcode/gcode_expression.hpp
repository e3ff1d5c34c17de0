// SPDX-License-Identifier: Apache-2.0
#pragma once
// Parameters and expressions of Fanuc Macro B and RS274NGC (LinuxCNC), evaluated where the
// program's words use them: one evaluator for every reader of G-code.
//
// Parameters: numbered `#1`..`#999` (Fanuc: #1-#33 locals, #100-#199 and #500-#999 commons;
// LinuxCNC: numbered parameters), named `#<name>` and `#<_global>` (LinuxCNC: case and blanks
// do not count), `#[expr]` and `##n` (the parameter whose number is a value). A parameter never
// set, and `#0`, are vacant. System variables (`#1000` and up: `#3000` alarms, `#4001` modal
// state, `#5221` work offsets, ...) are refused with their number: their meaning is the control's;
// the reader may give the few whose value it knows (LinuxCNC's current position `#5420`-`#5425`),
// which are read, never set.
//
// Expressions: `[ ... ]` with, from the lowest precedence, `OR XOR AND`, `EQ NE GT GE LT LE`,
// `+ -`, `* / MOD`, `**`, unary `+ -`; functions `SIN COS TAN` (degrees) `ASIN ACOS` (result in
// degrees), `ATAN[a]/[b]` (atan2, degrees; also `ATAN[a]`), `SQRT ABS ROUND FIX FUP LN EXP`,
// `EXISTS[#<name>]`. Comparisons and the logic operators give 1 or 0.
// Where Fanuc and LinuxCNC differ the evaluator refuses rather than pick one: `FIX`/`FUP` of a
// negative fraction (Fanuc: toward / away from zero, LinuxCNC: floor / ceiling), `MOD` of a
// negative operand, `AND OR XOR` of values other than 0 and 1 (bitwise on Fanuc). A vacant value
// in arithmetic or as a word's value is refused (Fanuc leaves such a word out, LinuxCNC reads 0);
// `EQ`/`NE` compare vacancy (`#1 EQ #0`: #1 is vacant).
#include <array>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace ncpost::gcode {

/// A parameter's value; nullopt is vacant.
using ParamValue = std::optional<double>;

/// An error inside a line: `offset` is the 0-based index in the line where it was found.
class ExpressionError : public std::runtime_error {
 public:
  ExpressionError(std::size_t offset, const std::string& what) : std::runtime_error(what), offset_(offset) {}
  std::size_t offset() const { return offset_; }

 private:
  std::size_t offset_;
};

/// The program's parameters.
class Parameters {
 public:
  static constexpr int kLastUserNumber = 999;  ///< above: system variables (refused)

  ParamValue get(int number) const { return numbered_[static_cast<std::size_t>(number)]; }
  void set(int number, ParamValue v) { numbered_[static_cast<std::size_t>(number)] = v; }
  ParamValue get(const std::string& name) const;
  void set(const std::string& name, ParamValue v) { named_[name] = v; }
  bool exists(const std::string& name) const { return named_.count(name) > 0; }
  /// A system variable whose value the reader knows (nullopt: forget it); read-only to programs.
  void set_system(int number, std::optional<double> v) {
    if (v)
      system_[number] = *v;
    else
      system_.erase(number);
  }
  std::optional<double> system(int number) const {
    const auto it = system_.find(number);
    return it == system_.end() ? std::nullopt : std::optional<double>(it->second);
  }

 private:
  std::array<ParamValue, kLastUserNumber + 1> numbered_{};
  std::map<std::string, ParamValue> named_;
  std::map<int, double> system_;
};

/// Which parameter a `#...` reference names: a number or a normalized name.
struct ParamRef {
  int number = 0;    ///< when `name` is empty
  std::string name;  ///< `#<Name Here>` as `namehere`
};

/// Reads expressions from one line. Every function throws ExpressionError on bad input.
class Evaluator {
 public:
  explicit Evaluator(const Parameters& p) : params_(p) {}

  /// A value at `at`: a number, a parameter, `[expr]`, a function call, or a sign before one.
  /// `at` moves past it (and the blanks before it).
  ParamValue value(std::string_view line, std::size_t& at) const;
  /// A full expression without brackets around it (`#1 = #2 + 3 * #4`), up to what is not part
  /// of one.
  ParamValue expression(std::string_view line, std::size_t& at) const;
  /// `#...` at `at` (at the '#'): which parameter it names.
  ParamRef reference(std::string_view line, std::size_t& at) const;
  /// The value of a parameter; throws for a system variable.
  ParamValue read(const ParamRef& ref, std::size_t offset) const;

 private:
  ParamValue binary(std::string_view line, std::size_t& at, int level) const;
  ParamValue function(std::string_view line, std::size_t& at, const std::string& name, std::size_t start) const;
  ParamValue exists(std::string_view line, std::size_t& at, std::size_t start) const;
  const Parameters& params_;
};

/// The number `v` as a G-code word value: no exponent; integers without a decimal point (as a
/// Fanuc control takes a variable on an address that has no decimal point), others with up to 10
/// decimals.
std::string word_number(double v);

}  // namespace ncpost::gcode
