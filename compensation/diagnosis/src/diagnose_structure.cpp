// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/diagnose_structure.hpp"

#include <fmt/format.h>

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <map>

#include "ncpost/compensation/diagnose_candidates.hpp"
#include "ncpost/compensation/diagnose_screening.hpp"
#include "ncpost/compensation/diagnose_signature.hpp"

namespace ncpost::comp {
namespace {

double wrap_deg(double rad) {
  double d = std::fmod(rad * 180.0 / kPi, 360.0);
  return d < 0 ? d + 360.0 : d;
}

struct Column {
  std::vector<double> y_um;
  std::vector<double> at;  ///< the axis command of each row (deg, wrapped for a turning axis)
};

/// Group key of every row; `centres` gets each group's angle (deg).
std::vector<int> group_rows(const std::vector<double>& at, bool turns, std::vector<double>& centres) {
  std::map<long long, int> distinct;
  for (double a : at) distinct.emplace(std::llround(a * 1e3), 0);
  std::vector<int> key(at.size());
  const std::size_t limit = turns ? 72 : 24;
  if (distinct.size() <= limit) {
    int g = 0;
    for (auto& [k, v] : distinct) v = g++, centres.push_back(double(k) * 1e-3);
    for (std::size_t i = 0; i < at.size(); ++i) key[i] = distinct[std::llround(at[i] * 1e3)];
    return key;
  }
  const int bins = turns ? 36 : 12;
  double lo = turns ? 0.0 : *std::min_element(at.begin(), at.end());
  double hi = turns ? 360.0 : *std::max_element(at.begin(), at.end());
  const double w = (hi - lo) / bins;
  for (int b = 0; b < bins; ++b) centres.push_back(lo + (b + 0.5) * w);
  for (std::size_t i = 0; i < at.size(); ++i) key[i] = std::clamp(static_cast<int>((at[i] - lo) / w), 0, bins - 1);
  return key;
}

/// Shape of the group means of a turning axis: the dominant harmonic order, or a local peak.
void describe(ResidualStructure& s, const std::vector<double>& centres, const std::vector<double>& means,
              const std::vector<int>& counts, bool turns, const AxisSampling& sampling) {
  const std::size_t g = centres.size();
  double mean = 0.0;
  int n = 0;
  for (std::size_t j = 0; j < g; ++j)
    if (counts[j] > 0) mean += means[j], ++n;
  mean /= std::max(n, 1);
  double var = 0.0, peak = 0.0;
  std::size_t at = 0;
  for (std::size_t j = 0; j < g; ++j) {
    if (counts[j] == 0) continue;
    const double d = means[j] - mean;
    var += d * d;
    if (std::abs(d) > std::abs(peak)) peak = d, at = j;
  }
  var /= std::max(n, 1);
  s.spread_um = std::sqrt(var);
  s.largest_um = peak;
  s.at_deg = centres[at];
  const std::string axis(1, s.axis);
  if (turns) {
    // the order that carries most of the variance of the means
    double best_share = 0.0;
    const int top = std::min<int>((n - 1) / 2, kMaxHarmonicOrder * 2);
    double best_amp = 0.0;
    for (int k = 1; k <= top; ++k) {
      double c = 0.0, sn = 0.0, cc = 0.0, ss = 0.0;
      for (std::size_t j = 0; j < g; ++j) {
        if (counts[j] == 0) continue;
        const double q = centres[j] * kPi / 180.0;
        c += (means[j] - mean) * std::cos(k * q), sn += (means[j] - mean) * std::sin(k * q);
        cc += std::cos(k * q) * std::cos(k * q), ss += std::sin(k * q) * std::sin(k * q);
      }
      const double a = cc > 0 ? c / cc : 0.0, b = ss > 0 ? sn / ss : 0.0;
      const double share = var > 0 ? 0.5 * (a * a + b * b) / var : 0.0;
      if (share > best_share) best_share = share, s.order = k, best_amp = std::hypot(a, b);
    }
    double gap = 360.0;
    if (g > 1) gap = 360.0 / double(g);
    if (best_share >= 0.7) {
      s.shape = fmt::format("{} per revolution of {}, {:.2f} µm", s.order, axis, best_amp);
    } else {
      s.order = 0;
      // width of the peak: contiguous groups round the turn with |mean − mean| above half the peak
      int width = 1;
      for (int dir : {-1, 1})
        for (std::size_t step = 1; step < g; ++step) {
          const std::size_t j = (at + g + dir * static_cast<long>(step)) % g;
          if (counts[j] == 0 || std::abs(means[j] - mean) < 0.5 * std::abs(peak) || (means[j] - mean) * peak < 0) break;
          ++width;
        }
      const double wide = width * 360.0 / double(g);
      s.shape = wide <= 120.0
                    ? fmt::format("local: {:.2f} µm at {} {:.0f}°, about {:.0f}° wide", peak, axis, s.at_deg, wide)
                    : fmt::format("irregular over the turn of {} (largest {:.2f} µm at {:.0f}°)", axis, peak, s.at_deg);
    }
    const double finer = std::max(1.0, std::floor(std::max(sampling.coarsest_gap_deg, gap) / 2.0));
    s.proposal = fmt::format(
        "measure {} on a finer grid (every {:.0f}°) to resolve its shape, and from a second sphere position (another "
        "radius from {} and height) to tell a component of {} from the instrument and from the other axis",
        axis, finer, axis, axis);
  } else {
    // linear trend against the axis
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t j = 0; j < g; ++j) {
      if (counts[j] == 0) continue;
      sx += centres[j], sy += means[j] - mean, sxx += centres[j] * centres[j], sxy += centres[j] * (means[j] - mean);
    }
    const double den = n * sxx - sx * sx;
    const double slope = den > 0 ? (n * sxy - sx * sy) / den : 0.0;
    double lo = 1e300, hi = -1e300;
    for (std::size_t j = 0; j < g; ++j)
      if (counts[j] > 0) lo = std::min(lo, centres[j]), hi = std::max(hi, centres[j]);
    const double explained = var > 0 ? slope * slope * (sxx / n - (sx / n) * (sx / n)) / var : 0.0;
    s.shape = explained >= 0.7
                  ? fmt::format("grows with {}: {:.2f} µm over {:.0f}…{:.0f}°", axis, slope * (hi - lo), lo, hi)
                  : fmt::format("varies with {} (largest {:.2f} µm at {:.0f}°)", axis, peak, s.at_deg);
    s.proposal = fmt::format(
        "measure at more levels of {} (every {:.0f}°) with the other rotary axis turned at each, from two sphere "
        "positions: an error of one axis that changes with {} is not in the catalogue",
        axis, std::max(1.0, std::floor((hi - lo) / std::max(2.0 * (n - 1), 1.0))), axis);
  }
}

}  // namespace

std::vector<ResidualStructure> residual_columns(const Machine& m, const std::vector<MeasurementSet>& sets,
                                                const Eigen::VectorXd& r, const MeasurementType* only_type) {
  std::vector<ResidualStructure> found;
  Eigen::Index offset = 0;
  for (const auto& s : sets) {
    const int nv = s.values_per_row();
    const std::size_t rows = s.rows.size();
    const Eigen::Index here = offset;
    offset += static_cast<Eigen::Index>(rows) * nv;
    if (only_type && s.type != *only_type) continue;
    for (int k = 0; k < m.rotary_count(); ++k) {
      const int index = 3 + k;
      const AxisSampling sampling = axis_sampling({s}, index);
      std::vector<double> at(rows);
      double lo = 1e300, hi = -1e300;
      for (std::size_t i = 0; i < rows; ++i) {
        const double q = s.rows[i].command[index];
        lo = std::min(lo, q), hi = std::max(hi, q);
        at[i] = sampling.turns ? wrap_deg(q) : q * 180.0 / kPi;
      }
      if (hi - lo < 1e-6) continue;
      std::vector<double> centres;
      const std::vector<int> key = group_rows(at, sampling.turns, centres);
      const std::size_t g = centres.size();
      if (g < 3 || rows < 2 * g) continue;
      for (int v = 0; v < nv; ++v) {
        std::vector<double> sum(g, 0.0), means(g, 0.0);
        std::vector<int> counts(g, 0);
        double total = 0.0;
        for (std::size_t i = 0; i < rows; ++i) {
          const double y = 1e3 * r[here + static_cast<Eigen::Index>(i) * nv + v];
          sum[static_cast<std::size_t>(key[i])] += y, ++counts[static_cast<std::size_t>(key[i])], total += y;
        }
        const double grand = total / double(rows);
        double ssb = 0.0, ssw = 0.0;
        int used = 0;
        for (std::size_t j = 0; j < g; ++j)
          if (counts[j] > 0)
            means[j] = sum[j] / counts[j], ssb += counts[j] * (means[j] - grand) * (means[j] - grand), ++used;
        for (std::size_t i = 0; i < rows; ++i) {
          const double y = 1e3 * r[here + static_cast<Eigen::Index>(i) * nv + v];
          const double d = y - means[static_cast<std::size_t>(key[i])];
          ssw += d * d;
        }
        const double df1 = used - 1, df2 = double(rows) - used;
        if (df1 < 1 || df2 < 1 || ssw <= 0) continue;
        ResidualStructure st;
        st.file = s.file;
        st.value = value_name(s, v);
        st.axis = m.axes[static_cast<std::size_t>(index)].letter;
        st.groups = used;
        st.f_statistic = (ssb / df1) / (ssw / df2);
        st.p_value = f_upper_tail(st.f_statistic, df1, df2);
        describe(st, centres, means, counts, sampling.turns, sampling);
        st.set_index = static_cast<std::size_t>(&s - sets.data());
        st.value_index = v;
        st.group_of_row = key;
        found.push_back(std::move(st));
      }
    }
  }
  // what no one axis shows: a residual that varies smoothly along a continuous path (a ballbar
  // run) where noise alone would not (von Neumann's ratio of successive differences to the
  // variance, 2 for noise, z-test one-sided): an effect of several axes together
  offset = 0;
  for (const auto& s : sets) {
    const int nv = s.values_per_row();
    const std::size_t rows = s.rows.size();
    const Eigen::Index here = offset;
    offset += static_cast<Eigen::Index>(rows) * nv;
    if ((only_type && s.type != *only_type) || s.type != MeasurementType::ballbar || rows < 30) continue;
    for (int v = 0; v < nv; ++v) {
      auto y = [&](std::size_t i) { return 1e3 * r[here + static_cast<Eigen::Index>(i) * nv + v]; };
      double mean = 0.0;
      for (std::size_t i = 0; i < rows; ++i) mean += y(i);
      mean /= double(rows);
      double ss = 0.0, sd = 0.0;
      for (std::size_t i = 0; i < rows; ++i) ss += (y(i) - mean) * (y(i) - mean);
      for (std::size_t i = 1; i < rows; ++i) sd += (y(i) - y(i - 1)) * (y(i) - y(i - 1));
      if (ss <= 0) continue;
      const double n = double(rows), eta = sd / ss;
      const double z = (2.0 - eta) / std::sqrt(4.0 * (n - 2.0) / (n * n - 1.0));
      ResidualStructure st;
      st.file = s.file;
      st.value = value_name(s, v);
      std::string moving;
      double travel = -1.0;
      for (int k = 0; k < m.rotary_count(); ++k) {
        double lo = 1e300, hi = -1e300;
        for (const auto& row : s.rows) lo = std::min(lo, row.command[3 + k]), hi = std::max(hi, row.command[3 + k]);
        if (hi - lo < 1e-6) continue;
        moving += (moving.empty() ? "" : " and ") + std::string(1, m.rotary(k).letter);
        if (hi - lo > travel) travel = hi - lo, st.axis = m.rotary(k).letter;
      }
      st.groups = static_cast<int>((rows + 9) / 10);
      st.f_statistic = 2.0 / std::max(eta, 1e-9);
      st.p_value = 0.5 * std::erfc(z / std::sqrt(2.0));
      st.spread_um = std::sqrt(ss / n);
      st.shape = fmt::format(
          "smooth along the path, with {} together and not with one alone (successive differences: "
          "von Neumann ratio {:.2f}, 2 for noise; rms {:.2f} µm)",
          moving.empty() ? std::string("the axes") : moving, eta, st.spread_um);
      st.proposal = fmt::format(
          "measure one axis at several fixed positions of the other ({} at each level): an error "
          "of one axis that changes with another is not in the catalogue beyond EA0C:A:p1-like "
          "location terms",
          moving.empty() ? std::string("the axes") : moving);
      st.set_index = static_cast<std::size_t>(&s - sets.data());
      st.value_index = v;
      for (std::size_t i = 0; i < rows; ++i) st.group_of_row.push_back(static_cast<int>(i / 10));
      found.push_back(std::move(st));
    }
  }
  return found;
}

std::vector<ResidualStructure> residual_structure(const Machine& m, const std::vector<MeasurementSet>& sets,
                                                  const Eigen::VectorXd& r, double significance,
                                                  const MeasurementType* only_type) {
  std::vector<ResidualStructure> found = residual_columns(m, sets, r, only_type);
  const double alpha = significance / std::max<double>(double(found.size()), 1.0);
  found.erase(
      std::remove_if(found.begin(), found.end(), [&](const ResidualStructure& s) { return !(s.p_value < alpha); }),
      found.end());
  std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.f_statistic > b.f_statistic; });
  return found;
}

}  // namespace ncpost::comp
