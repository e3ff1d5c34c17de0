// SPDX-License-Identifier: Apache-2.0
#pragma once
// Pass/fail by the ISO 14253-1 decision rule (issue 25 item 4; docs/cli.md `identify`): a figure
// v ≥ 0 with expanded uncertainty U (k = 2) against an upper tolerance T (the figures of ISO 230-2
// and ISO 230-4 are one-sided: the smaller the better):
//   v + U ≤ T   conformance proven        PASS
//   v − U > T   non-conformance proven    FAIL
//   otherwise   neither can be proven     NOT PROVEN (the tolerance lies within v ± U)
// The uncertainty always counts against the one who claims: a supplier proving conformance, a
// customer proving non-conformance.
#include <map>
#include <optional>
#include <string>

namespace ncpost::comp {

enum class Verdict { pass, fail, not_proven };

Verdict decide(double value, double expanded_uncertainty, double tolerance);

const char* to_string(Verdict v);  ///< "PASS", "FAIL", "NOT PROVEN"
const char* css_class(Verdict v);  ///< "pass", "fail", "unproven"

/// The figure kinds a tolerance is given for (µm): ISO 230-2 A, B, E, M, R of a linear axis and
/// ISO 230-4 G of a circular test.
inline constexpr const char* kToleranceKinds[] = {"A", "B", "E", "M", "R", "G"};

/// One tolerance per figure kind (µm).
struct Tolerances {
  std::map<std::string, double> by_kind_um;
  std::optional<double> of(const std::string& kind) const;
  bool empty() const { return by_kind_um.empty(); }
};

/// "G=10,A=8" → tolerances; an unknown kind, a missing `=`, a value that is not a positive finite
/// number (µm), or a kind given twice is an error whose text says which (std::invalid_argument).
Tolerances parse_tolerances(const std::string& text);

}  // namespace ncpost::comp
