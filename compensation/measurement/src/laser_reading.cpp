// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/laser_reading.hpp"

#include <cmath>
#include <map>

#include "ncpost/compensation/prediction.hpp"

namespace ncpost::comp {

int laser_moving_axis(const MeasurementSet& set) {
  const std::string a = set.meta("axis");
  if (a.size() == 1 && a[0] >= 'X' && a[0] <= 'Z') return a[0] - 'X';
  int best = 0;
  double best_span = -1.0;
  for (int k = 0; k < 3; ++k) {
    double lo = 1e300, hi = -1e300;
    for (const auto& r : set.rows) {
      lo = std::min(lo, r.command[k]);
      hi = std::max(hi, r.command[k]);
    }
    if (hi - lo > best_span) {
      best_span = hi - lo;
      best = k;
    }
  }
  return best;
}

bool has_approach(const MeasurementSet& set) {
  if (set.rows.empty()) return false;
  for (const auto& r : set.rows)
    if (r.approach == 0) return false;
  return true;
}

RowState<double> laser_row_state(const ModelLayout& layout, const double* values, int moving_axis,
                                 const MeasurementRow& row) {
  RowState<double> s;
  s.time_s = row.time_s;
  const int p = layout.reversal_of(moving_axis);
  if (p >= 0 && row.approach < 0) s.reversal[static_cast<std::size_t>(moving_axis)] = values[p];
  return s;
}

double laser_raw_reading_um(const Machine& m, const MeasurementSet& set, const MeasurementRow& row,
                            const ErrorFunctor<double>& errors) {
  const double tl = set.tool_length_mm;
  const ChainPose<double> home = raw_chain_pose<double>(m, AxisPosition{}, tl, errors, true);
  const ChainPose<double> raw = raw_chain_pose<double>(m, row.command, tl, errors, false);
  const Rigid<double> bed_T_table = raw.bed_T_table * home.bed_T_table.inverse();
  const Rigid<double> bed_T_tool = raw.bed_T_tool * home.bed_T_tool.inverse();
  const Vec3d actual = (bed_T_table.inverse() * bed_T_tool).apply(set.tool_point_mm);
  const Vec3d nominal = chain_pose<double>(m, row.command, tl, NominalErrors{}).table_T_tool().apply(set.tool_point_mm);
  const int c = set.component - 'X';
  return 1000.0 * (actual[c] - nominal[c]);
}

std::vector<double> predict_laser_set(const Machine& m, const MeasurementSet& set, const ModelLayout& layout,
                                      const double* values) {
  if (!has_approach(set)) return predict_set<double>(m, set, layout, values);
  const int moving = laser_moving_axis(set);
  ErrorFunctor<double> f(layout, values);
  std::vector<double> out;
  out.reserve(set.rows.size());
  std::map<int, double> run_zero;
  for (const auto& row : set.rows) {
    f.set_state(laser_row_state(layout, values, moving, row));
    const double e = laser_raw_reading_um(m, set, row, f);
    auto it = run_zero.find(row.run);
    if (it == run_zero.end()) it = run_zero.emplace(row.run, e).first;
    out.push_back(e - it->second);
  }
  return out;
}

}  // namespace ncpost::comp
