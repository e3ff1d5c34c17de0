// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/uncertainty_budget.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ncpost/compensation/laser_reading.hpp"

namespace ncpost::comp {
namespace {

/// u of one reading from the file's certificate value, or a missing line.
BudgetLine instrument_line(const MeasurementSet& set, double readings_factor, const std::string& why) {
  const auto& U = set.conditions.instrument_U_um;
  if (!U) return {"instrument", 0.0, "not given (# instrument_uncertainty: U, k = 2, µm)", false};
  return {"instrument", readings_factor * *U / 2.0,
          fmt::format("U = {:g} µm (k = 2) per reading{}", *U, why.empty() ? "" : "; " + why)};
}

BudgetLine temperature_line(const MeasurementSet& set, double length_mm) {
  const MeasurementConditions& c = set.conditions;
  if (!c.temperature_c) return {"temperature", 0.0, "not given (# temperature:)", false};
  if (!c.expansion_per_k)
    return {"temperature", 0.0,
            fmt::format("{:g} °C not corrected to 20 °C: no # material_expansion: (the expansion is unknown)",
                        *c.temperature_c),
            false};
  const double dt_k = *c.temperature_c - kReferenceTemperatureC;
  if (!c.temperature_u_k || !c.expansion_u_per_k)
    return {"temperature", 0.0,
            "the correction's uncertainty not given (# temperature_uncertainty: K, # expansion_uncertainty: 1/K)",
            false};
  const double relative = std::hypot(dt_k * *c.expansion_u_per_k, *c.expansion_per_k * *c.temperature_u_k);
  return {"temperature", 1000.0 * length_mm * relative,
          fmt::format("over {:g} mm: ΔT {:+g} K, u_α {:g} /K, α {:g} /K, u_T {:g} K", length_mm, dt_k,
                      *c.expansion_u_per_k, *c.expansion_per_k, *c.temperature_u_k)};
}

}  // namespace

double UncertaintyBudget::combined_um() const {
  double sum = 0.0;
  for (const auto& l : lines) sum += l.u_um * l.u_um;
  return std::sqrt(sum);
}

bool UncertaintyBudget::complete() const {
  return std::all_of(lines.begin(), lines.end(), [](const BudgetLine& l) { return l.given; });
}

std::string UncertaintyBudget::missing() const {
  std::string out;
  for (const auto& l : lines)
    if (!l.given) out += (out.empty() ? "" : ", ") + l.source;
  return out;
}

double budget_length_mm(const MeasurementSet& set) {
  if (set.type == MeasurementType::ballbar) return set.bar_length_mm;
  if (set.type != MeasurementType::laser || set.rows.empty()) return 0.0;
  const int axis = laser_moving_axis(set);
  double lo = set.rows.front().command[axis], hi = lo;
  for (const auto& r : set.rows) lo = std::min(lo, r.command[axis]), hi = std::max(hi, r.command[axis]);
  return hi - lo;
}

UncertaintyBudget reading_budget(const MeasurementSet& set) {
  UncertaintyBudget b;
  b.lines.push_back(instrument_line(set, 1.0, ""));
  if (set.type == MeasurementType::sphere)
    b.lines.push_back({"temperature", 0.0, "none: the probe reads through the machine's own scales"});
  else
    b.lines.push_back(temperature_line(set, budget_length_mm(set)));
  return b;
}

UncertaintyBudget circularity_budget(const MeasurementSet& set, const std::vector<double>& repeat_G_um) {
  UncertaintyBudget b;
  b.lines.push_back(instrument_line(set, std::sqrt(2.0), "G is the difference of two readings: √2 u"));
  b.lines.push_back({"temperature", 0.0, "none: a uniform expansion changes the radius, not G"});
  if (repeat_G_um.size() >= 2) {
    double mean = 0.0;
    for (double g : repeat_G_um) mean += g;
    mean /= static_cast<double>(repeat_G_um.size());
    double ss = 0.0;
    for (double g : repeat_G_um) ss += (g - mean) * (g - mean);
    const double s = std::sqrt(ss / static_cast<double>(repeat_G_um.size() - 1));
    b.lines.push_back({"repeatability", s, fmt::format("s of G over {} runs of the same test", repeat_G_um.size())});
  } else {
    b.lines.push_back({"repeatability", 0.0, "not repeated (one file of this test): not included", false});
  }
  return b;
}

UncertaintyBudget iso230_2_budget(const MeasurementSet& set, const Iso230Figures& g, char figure) {
  UncertaintyBudget b;
  double s_max = 0.0;
  int n = g.targets.empty() ? 0 : g.targets.front().runs_up;  // the fewest runs of any target and direction
  for (const auto& t : g.targets) {
    s_max = std::max({s_max, t.s_up_um, t.s_down_um});
    n = std::min({n, t.runs_up, t.runs_down});
  }
  if (figure == 'R') {
    b.lines.push_back({"instrument", 0.0, "none: R is a spread of readings (the instrument's noise is in s)"});
    b.lines.push_back({"temperature", 0.0, "none: a spread at one position"});
    b.lines.push_back(n >= 2 ? BudgetLine{"repeatability", g.repeatability_R_um / std::sqrt(2.0 * (n - 1)),
                                          fmt::format("the estimate of s from {} runs: R / √(2 (n − 1))", n)}
                             : BudgetLine{"repeatability", 0.0, "fewer than 2 runs per direction", false});
    return b;
  }
  b.lines.push_back(instrument_line(set, std::sqrt(2.0), "a difference of two positions: √2 u"));
  if (figure == 'B')
    b.lines.push_back({"temperature", 0.0, "none: a difference at one position"});
  else
    b.lines.push_back(temperature_line(set, budget_length_mm(set)));
  b.lines.push_back(n >= 2 ? BudgetLine{"repeatability", std::sqrt(2.0) * s_max / std::sqrt(static_cast<double>(n)),
                                        fmt::format("means of {} runs: √2 s_max / √n, s_max {:.3f} µm", n, s_max)}
                           : BudgetLine{"repeatability", 0.0, "fewer than 2 runs per direction", false});
  return b;
}

}  // namespace ncpost::comp
