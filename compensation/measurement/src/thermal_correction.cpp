// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/thermal_correction.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "ncpost/compensation/laser_reading.hpp"

namespace ncpost::comp {
namespace {

bool positioning_line(const MeasurementSet& set) {
  return set.type == MeasurementType::laser && set.component - 'X' == laser_moving_axis(set);
}

/// Maps every measured length of the set through ℓ → ℓ · scale; returns the largest change (µm).
double scale_lengths(MeasurementSet& set, double scale) {
  double largest_um = 0.0;
  if (set.type == MeasurementType::ballbar) {
    for (auto& r : set.rows) {
      const double corrected_mm = r.value[0] * scale;
      largest_um = std::max(largest_um, 1e3 * std::abs(corrected_mm - r.value[0]));
      r.value[0] = corrected_mm;
    }
  } else if (positioning_line(set)) {
    const int axis = laser_moving_axis(set);
    struct Zero {
      double command_mm, reading_um;
    };
    std::map<int, Zero> zero_of_run;
    for (auto& r : set.rows) {
      auto it = zero_of_run.find(r.run);
      if (it == zero_of_run.end()) it = zero_of_run.emplace(r.run, Zero{r.command[axis], r.value[0]}).first;
      const double moved_mm = r.command[axis] - it->second.command_mm;
      const double read_mm = moved_mm + 1e-3 * (r.value[0] - it->second.reading_um);
      const double corrected_um = it->second.reading_um + 1e3 * (read_mm * scale - moved_mm);
      largest_um = std::max(largest_um, std::abs(corrected_um - r.value[0]));
      r.value[0] = corrected_um;
    }
  }
  return largest_um;
}

}  // namespace

bool has_lengths_to_correct(const MeasurementSet& set) {
  return set.type == MeasurementType::ballbar || positioning_line(set);
}

void correct_to_20c(MeasurementSet& set) {
  if (set.corrected_to_20c || !set.conditions.corrects() || !set.has_values || !has_lengths_to_correct(set)) return;
  set.thermal_correction_max_um = scale_lengths(set, 1.0 / set.conditions.expansion_factor());
  set.corrected_to_20c = true;
}

void expand_to_measuring_temperature(MeasurementSet& set) {
  if (!set.conditions.corrects() || !has_lengths_to_correct(set)) return;
  scale_lengths(set, set.conditions.expansion_factor());
}

std::vector<std::string> temperature_warnings(const std::vector<MeasurementSet>& sets) {
  const MeasurementSet* coldest = nullptr;
  const MeasurementSet* warmest = nullptr;
  for (const auto& s : sets) {
    if (!s.conditions.temperature_c) continue;
    if (!coldest || *s.conditions.temperature_c < *coldest->conditions.temperature_c) coldest = &s;
    if (!warmest || *s.conditions.temperature_c > *warmest->conditions.temperature_c) warmest = &s;
  }
  std::vector<std::string> out;
  if (!coldest) return out;
  const double spread_k = *warmest->conditions.temperature_c - *coldest->conditions.temperature_c;
  if (spread_k > kTemperatureAgreementK)
    out.push_back(
        fmt::format("the files of this identification were measured {:.1f} K apart ({} at {:g} °C, {} at {:g} °C), "
                    "more than {:g} K: the machine's errors change with its temperature, so one model fitted to "
                    "both holds for neither; measure again at one temperature or identify each file alone",
                    spread_k, coldest->file, *coldest->conditions.temperature_c, warmest->file,
                    *warmest->conditions.temperature_c, kTemperatureAgreementK));
  std::string without;
  for (const auto& s : sets)
    if (!s.conditions.temperature_c) without += (without.empty() ? "" : ", ") + s.file;
  if (!without.empty())
    out.push_back(
        fmt::format("no '# temperature:' in {}: its temperature cannot be compared with the other files'", without));
  return out;
}

}  // namespace ncpost::comp
