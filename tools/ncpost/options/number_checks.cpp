// SPDX-License-Identifier: Apache-2.0
#include "number_checks.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "commands.hpp"
#include "terminal_text.hpp"

namespace ncpost::cli {
namespace {

std::string range_text(double lo, double hi, const std::string& unit, Bound lower) {
  return fmt::format("a finite number {} {:g} {} {:g}{}", lower == Bound::open ? "above" : "from", lo,
                     lower == Bound::open ? "and at most" : "to", hi, unit.empty() ? "" : " (" + unit + ")");
}

/// "" when `text` is such a number, else what is wrong.
std::string problem(const std::string& text, double lo, double hi, const std::string& unit, Bound lower) {
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(begin, &end);
  const bool whole = end != begin && *end == '\0' && text.find_first_of(" \t\n") == std::string::npos;
  const bool ok = whole && std::isfinite(v) && errno != ERANGE && (lower == Bound::open ? v > lo : v >= lo) && v <= hi;
  if (ok) return {};
  std::string shown = terminal_text(text.size() > 40 ? text.substr(0, 40) + "..." : text);
  return fmt::format("expected {}, got '{}'", range_text(lo, hi, unit, lower), shown);
}

}  // namespace

CLI::Validator finite_in(double lo, double hi, const std::string& unit, Bound lower) {
  return CLI::Validator([=](std::string& text) { return problem(text, lo, hi, unit, lower); },
                        fmt::format("{}{}..{:g}", lower == Bound::open ? "(" : "[", lo, hi));
}

double finite_number(const std::string& text, const std::string& what, double lo, double hi, const std::string& unit,
                     Bound lower) {
  if (const std::string p = problem(text, lo, hi, unit, lower); !p.empty()) throw UsageError(what + ": " + p);
  return std::strtod(text.c_str(), nullptr);
}

}  // namespace ncpost::cli
