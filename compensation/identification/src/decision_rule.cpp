// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/decision_rule.hpp"

#include <fmt/format.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace ncpost::comp {

Verdict decide(double value, double expanded_uncertainty, double tolerance) {
  const double u = std::abs(expanded_uncertainty);
  if (value + u <= tolerance) return Verdict::pass;
  if (value - u > tolerance) return Verdict::fail;
  return Verdict::not_proven;
}

const char* to_string(Verdict v) {
  switch (v) {
    case Verdict::pass:
      return "PASS";
    case Verdict::fail:
      return "FAIL";
    case Verdict::not_proven:
      return "NOT PROVEN";
  }
  return "?";
}

const char* css_class(Verdict v) {
  switch (v) {
    case Verdict::pass:
      return "pass";
    case Verdict::fail:
      return "fail";
    case Verdict::not_proven:
      return "unproven";
  }
  return "";
}

std::optional<double> Tolerances::of(const std::string& kind) const {
  const auto it = by_kind_um.find(kind);
  if (it == by_kind_um.end()) return std::nullopt;
  return it->second;
}

Tolerances parse_tolerances(const std::string& text) {
  Tolerances t;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    item.erase(0, item.find_first_not_of(" \t"));
    item.erase(item.find_last_not_of(" \t") + 1);
    if (item.empty()) continue;
    const auto eq = item.find('=');
    if (eq == std::string::npos) throw std::invalid_argument(fmt::format("expected KIND=µm, found '{}'", item));
    const std::string kind = item.substr(0, eq);
    bool known = false;
    for (const char* k : kToleranceKinds) known = known || kind == k;
    if (!known)
      throw std::invalid_argument(fmt::format("unknown figure kind '{}' (ISO 230-2 A, B, E, M, R; ISO 230-4 G)", kind));
    const std::string number = item.substr(eq + 1);
    std::size_t used = 0;
    double v = 0.0;
    try {
      v = std::stod(number, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (number.empty() || used != number.size() || !std::isfinite(v) || !(v > 0.0))
      throw std::invalid_argument(fmt::format("{}: expected a positive number of µm, found '{}'", kind, number));
    if (!t.by_kind_um.emplace(kind, v).second) throw std::invalid_argument(fmt::format("{} given twice", kind));
  }
  return t;
}

}  // namespace ncpost::comp
