// SPDX-License-Identifier: Apache-2.0
#pragma once
// Numeric options: every value must be a finite number in the option's range. The check runs on
// the text as given, so the message repeats what the user typed (never a 300-digit expansion)
// and names the option (CLI11 prefixes it): "--tool-length: expected a finite number from 0 to
// 2000 (mm), got 'nan'".
#include <CLI/CLI.hpp>

#include <string>

namespace ncpost::cli {

enum class Bound { closed, open };

/// A CLI11 check: a finite number within [lo, hi] (or (lo, hi] with `Bound::open` below).
CLI::Validator finite_in(double lo, double hi, const std::string& unit, Bound lower = Bound::closed);

/// The same check for values parsed by hand (a list item, NAME=VALUE): the number, or
/// UsageError naming `what`.
double finite_number(const std::string& text, const std::string& what, double lo, double hi, const std::string& unit,
                     Bound lower = Bound::closed);

}  // namespace ncpost::cli
