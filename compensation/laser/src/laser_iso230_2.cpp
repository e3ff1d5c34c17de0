// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/laser_iso230_2.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "ncpost/compensation/laser_reading.hpp"

namespace ncpost::comp {
namespace {

void mean_and_s(const std::vector<double>& v, double& mean, double& s) {
  mean = 0.0;
  for (double x : v) mean += x;
  mean /= double(v.size());
  double ss = 0.0;
  for (double x : v) ss += (x - mean) * (x - mean);
  s = v.size() > 1 ? std::sqrt(ss / double(v.size() - 1)) : 0.0;
}

}  // namespace

Iso230Figures iso230_2_figures(const MeasurementSet& set) {
  Iso230Figures f;
  f.file = set.file;
  const int j = laser_moving_axis(set);
  f.axis = static_cast<char>('X' + j);
  if (set.type != MeasurementType::laser || set.component != f.axis || !set.has_values) {
    f.message = "not a positioning set of a linear axis";
    return f;
  }
  // target (rounded to 1 µm) → readings per direction
  std::map<long long, std::pair<std::vector<double>, std::vector<double>>> at;
  for (std::size_t k = 0; k < set.rows.size(); ++k) {
    const MeasurementRow& r = set.rows[k];
    int dir = r.approach;
    if (dir == 0) {  // from the order: rising command is +1, a repeated target reverses
      const bool first = k == 0 || set.rows[k - 1].run != r.run;
      const double prev = first ? r.command[j] - 1.0 : set.rows[k - 1].command[j];
      dir = r.command[j] > prev ? 1 : -1;
    }
    auto& slot = at[std::llround(r.command[j] * 1000.0)];
    (dir > 0 ? slot.first : slot.second).push_back(r.value[0]);
  }
  double hi = -1e300, lo = 1e300, ehi = -1e300, elo = 1e300, mhi = -1e300, mlo = 1e300, bsum = 0.0;
  for (const auto& [key, v] : at) {
    if (v.first.size() < 2 || v.second.size() < 2) {
      f.message = "needs at least two runs in each direction at every target";
      return f;
    }
    Iso230Target t;
    t.target_mm = double(key) / 1000.0;
    mean_and_s(v.first, t.mean_up_um, t.s_up_um);
    mean_and_s(v.second, t.mean_down_um, t.s_down_um);
    t.runs_up = static_cast<int>(v.first.size());
    t.runs_down = static_cast<int>(v.second.size());
    const double b = t.reversal_um();
    bsum += b;
    f.reversal_B_um = std::max(f.reversal_B_um, std::abs(b));
    f.repeatability_R_um = std::max(f.repeatability_R_um, t.repeatability_um());
    hi = std::max({hi, t.mean_up_um + 2.0 * t.s_up_um, t.mean_down_um + 2.0 * t.s_down_um});
    lo = std::min({lo, t.mean_up_um - 2.0 * t.s_up_um, t.mean_down_um - 2.0 * t.s_down_um});
    ehi = std::max({ehi, t.mean_up_um, t.mean_down_um});
    elo = std::min({elo, t.mean_up_um, t.mean_down_um});
    const double mean = t.mean_bidirectional_um();
    mhi = std::max(mhi, mean);
    mlo = std::min(mlo, mean);
    f.targets.push_back(t);
  }
  if (f.targets.empty()) {
    f.message = "no rows";
    return f;
  }
  f.accuracy_A_um = hi - lo;
  f.systematic_E_um = ehi - elo;
  f.mean_bidirectional_M_um = mhi - mlo;
  f.mean_reversal_um = bsum / double(f.targets.size());
  f.ok = true;
  return f;
}

double Iso230Target::repeatability_um() const {
  return std::max({2.0 * s_up_um + 2.0 * s_down_um + std::abs(reversal_um()), 4.0 * s_up_um, 4.0 * s_down_um});
}

}  // namespace ncpost::comp
