// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/simulate.hpp"

#include <random>

#include "ncpost/compensation/laser_reading.hpp"
#include "ncpost/compensation/prediction.hpp"
#include "ncpost/compensation/thermal_correction.hpp"

namespace ncpost::comp {

MeasurementSet simulate(const Machine& m, const MeasurementSet& plan, const ErrorParameters& truth,
                        const SimulationOptions& options) {
  const ModelLayout layout(m, truth.names());
  // laser sets with approach directions: ISO 230-2 reversal per row (laser_reading.hpp)
  const std::vector<double> values = plan.type == MeasurementType::laser
                                         ? predict_laser_set(m, plan, layout, truth.values().data())
                                         : predict_set<double>(m, plan, layout, truth.values().data());
  std::mt19937_64 rng(options.seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  const double sigma = options.noise_um * 1e-3 / value_unit_mm(plan);
  MeasurementSet out = plan;
  out.has_values = true;
  const int n = plan.values_per_row();
  for (std::size_t k = 0; k < out.rows.size(); ++k)
    for (int v = 0; v < n; ++v) {
      const double e = options.noise_um > 0.0 ? sigma * noise(rng) : 0.0;
      out.rows[k].value[v] = values[k * static_cast<std::size_t>(n) + static_cast<std::size_t>(v)] + e;
    }
  expand_to_measuring_temperature(out);  // what the instrument reads at the plan's temperature
  return out;
}

}  // namespace ncpost::comp
