// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/diagnose_structure.hpp"

#include <fmt/format.h>

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

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

/// The group means about their mean (groups with rows only).
struct GroupSpread {
  double mean = 0.0;
  double var = 0.0;    ///< variance of the means
  double peak = 0.0;   ///< the largest deviation (signed)
  std::size_t at = 0;  ///< its group
  int n = 0;           ///< groups with rows
};

GroupSpread group_spread(const std::vector<double>& means, const std::vector<int>& counts) {
  const std::size_t g = means.size();
  GroupSpread sp;
  for (std::size_t j = 0; j < g; ++j)
    if (counts[j] > 0) sp.mean += means[j], ++sp.n;
  sp.mean /= std::max(sp.n, 1);
  for (std::size_t j = 0; j < g; ++j) {
    if (counts[j] == 0) continue;
    const double d = means[j] - sp.mean;
    sp.var += d * d;
    if (std::abs(d) > std::abs(sp.peak)) sp.peak = d, sp.at = j;
  }
  sp.var /= std::max(sp.n, 1);
  return sp;
}

/// The harmonic order that carries most of the variance of the means of a turning axis.
struct Harmonic {
  int order = 0;
  double share = 0.0;  ///< of the variance
  double amplitude_um = 0.0;
};

Harmonic dominant_harmonic(const std::vector<double>& centres, const std::vector<double>& means,
                           const std::vector<int>& counts, const GroupSpread& sp) {
  const std::size_t g = centres.size();
  Harmonic best;
  const int top = std::min<int>((sp.n - 1) / 2, kMaxHarmonicOrder * 2);
  for (int k = 1; k <= top; ++k) {
    double c = 0.0, sn = 0.0, cc = 0.0, ss = 0.0;
    for (std::size_t j = 0; j < g; ++j) {
      if (counts[j] == 0) continue;
      const double q = centres[j] * kPi / 180.0;
      c += (means[j] - sp.mean) * std::cos(k * q), sn += (means[j] - sp.mean) * std::sin(k * q);
      cc += std::cos(k * q) * std::cos(k * q), ss += std::sin(k * q) * std::sin(k * q);
    }
    const double a = cc > 0 ? c / cc : 0.0, b = ss > 0 ? sn / ss : 0.0;
    const double share = sp.var > 0 ? 0.5 * (a * a + b * b) / sp.var : 0.0;
    if (share > best.share) best.share = share, best.order = k, best.amplitude_um = std::hypot(a, b);
  }
  return best;
}

/// Width of the peak (groups): contiguous groups round the turn with |mean − mean| above half the
/// peak and of its sign.
int peak_width(const std::vector<double>& means, const std::vector<int>& counts, const GroupSpread& sp) {
  const std::size_t g = means.size();
  int width = 1;
  for (int dir : {-1, 1})
    for (std::size_t step = 1; step < g; ++step) {
      const std::size_t j = (sp.at + g + dir * static_cast<long>(step)) % g;
      if (counts[j] == 0 || std::abs(means[j] - sp.mean) < 0.5 * std::abs(sp.peak) ||
          (means[j] - sp.mean) * sp.peak < 0)
        break;
      ++width;
    }
  return width;
}

/// The shape of the means of a turning axis (a dominant harmonic, a local peak or irregular) and
/// the finer grid that would resolve it.
void describe_turning(ResidualStructure& s, const std::vector<double>& centres, const std::vector<double>& means,
                      const std::vector<int>& counts, const GroupSpread& sp, const AxisSampling& sampling) {
  const std::size_t g = centres.size();
  const std::string axis(1, s.axis);
  const Harmonic best = dominant_harmonic(centres, means, counts, sp);
  double gap = 360.0;
  if (g > 1) gap = 360.0 / double(g);
  if (best.share >= 0.7) {
    s.order = best.order;
    s.shape = fmt::format("{} per revolution of {}, {:.2f} µm", s.order, axis, best.amplitude_um);
  } else {
    s.order = 0;
    const double wide = peak_width(means, counts, sp) * 360.0 / double(g);
    s.shape =
        wide <= 120.0
            ? fmt::format("local: {:.2f} µm at {} {:.0f}°, about {:.0f}° wide", sp.peak, axis, s.at_deg, wide)
            : fmt::format("irregular over the turn of {} (largest {:.2f} µm at {:.0f}°)", axis, sp.peak, s.at_deg);
  }
  const double finer = std::max(1.0, std::floor(std::max(sampling.coarsest_gap_deg, gap) / 2.0));
  s.proposal = fmt::format(
      "measure {} on a finer grid (every {:.0f}°) to resolve its shape, and from a second sphere position (another "
      "radius from {} and height) to tell a component of {} from the instrument and from the other axis",
      axis, finer, axis, axis);
}

/// The shape of the means of an axis that does not turn (a linear trend against it, or not) and
/// the levels that would resolve it.
void describe_linear(ResidualStructure& s, const std::vector<double>& centres, const std::vector<double>& means,
                     const std::vector<int>& counts, const GroupSpread& sp) {
  const std::size_t g = centres.size();
  const std::string axis(1, s.axis);
  const int n = sp.n;
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t j = 0; j < g; ++j) {
    if (counts[j] == 0) continue;
    sx += centres[j], sy += means[j] - sp.mean, sxx += centres[j] * centres[j],
        sxy += centres[j] * (means[j] - sp.mean);
  }
  const double den = n * sxx - sx * sx;
  const double slope = den > 0 ? (n * sxy - sx * sy) / den : 0.0;
  double lo = 1e300, hi = -1e300;
  for (std::size_t j = 0; j < g; ++j)
    if (counts[j] > 0) lo = std::min(lo, centres[j]), hi = std::max(hi, centres[j]);
  const double explained = sp.var > 0 ? slope * slope * (sxx / n - (sx / n) * (sx / n)) / sp.var : 0.0;
  s.shape = explained >= 0.7
                ? fmt::format("grows with {}: {:.2f} µm over {:.0f}…{:.0f}°", axis, slope * (hi - lo), lo, hi)
                : fmt::format("varies with {} (largest {:.2f} µm at {:.0f}°)", axis, sp.peak, s.at_deg);
  s.proposal = fmt::format(
      "measure at more levels of {} (every {:.0f}°) with the other rotary axis turned at each, from two sphere "
      "positions: an error of one axis that changes with {} is not in the catalogue",
      axis, std::max(1.0, std::floor((hi - lo) / std::max(2.0 * (n - 1), 1.0))), axis);
}

/// Shape of the group means: the spread and its largest, then as the axis turns or not.
void describe(ResidualStructure& s, const std::vector<double>& centres, const std::vector<double>& means,
              const std::vector<int>& counts, bool turns, const AxisSampling& sampling) {
  const GroupSpread sp = group_spread(means, counts);
  s.spread_um = std::sqrt(sp.var);
  s.largest_um = sp.peak;
  s.at_deg = centres[sp.at];
  if (turns)
    describe_turning(s, centres, means, counts, sp, sampling);
  else
    describe_linear(s, centres, means, counts, sp);
}

/// One set's rows in the stacked residual vector.
struct SetSlice {
  const MeasurementSet* set = nullptr;
  std::size_t index = 0;   ///< of the set among the sets
  Eigen::Index first = 0;  ///< its first residual
  int values = 0;          ///< residuals per row
  /// Residual (µm) of value column v of row i.
  double um(const Eigen::VectorXd& r, std::size_t i, int v) const {
    return 1e3 * r[first + static_cast<Eigen::Index>(i) * values + v];
  }
};

std::vector<SetSlice> slices_of(const std::vector<MeasurementSet>& sets) {
  std::vector<SetSlice> slices;
  Eigen::Index offset = 0;
  for (const auto& s : sets) {
    const int nv = s.values_per_row();
    slices.push_back({&s, slices.size(), offset, nv});
    offset += static_cast<Eigen::Index>(s.rows.size()) * nv;
  }
  return slices;
}

/// The command of rotary axis `index` in every row (deg, wrapped when it turns); empty when the
/// axis stands still in the set.
std::vector<double> axis_degrees(const MeasurementSet& s, int index, bool turns) {
  std::vector<double> at(s.rows.size());
  double lo = 1e300, hi = -1e300;
  for (std::size_t i = 0; i < s.rows.size(); ++i) {
    const double q = s.rows[i].command[index];
    lo = std::min(lo, q), hi = std::max(hi, q);
    at[i] = turns ? wrap_deg(q) : q * 180.0 / kPi;
  }
  if (hi - lo < 1e-6) return {};
  return at;
}

/// The one-way analysis of variance of one value column over g groups of rows.
struct GroupTest {
  std::vector<double> means;
  std::vector<int> counts;
  int used = 0;  ///< groups with rows
  double f_statistic = 0.0;
  double p_value = 1.0;
};

/// nullopt when the groups leave no degrees of freedom or there is no scatter within them.
std::optional<GroupTest> group_test(const SetSlice& sl, const Eigen::VectorXd& r, int v, const std::vector<int>& key,
                                    std::size_t g) {
  const std::size_t rows = sl.set->rows.size();
  GroupTest t;
  std::vector<double> sum(g, 0.0);
  t.means.assign(g, 0.0);
  t.counts.assign(g, 0);
  double total = 0.0;
  for (std::size_t i = 0; i < rows; ++i) {
    const double y = sl.um(r, i, v);
    sum[static_cast<std::size_t>(key[i])] += y, ++t.counts[static_cast<std::size_t>(key[i])], total += y;
  }
  const double grand = total / double(rows);
  double ssb = 0.0, ssw = 0.0;
  for (std::size_t j = 0; j < g; ++j)
    if (t.counts[j] > 0)
      t.means[j] = sum[j] / t.counts[j], ssb += t.counts[j] * (t.means[j] - grand) * (t.means[j] - grand), ++t.used;
  for (std::size_t i = 0; i < rows; ++i) {
    const double d = sl.um(r, i, v) - t.means[static_cast<std::size_t>(key[i])];
    ssw += d * d;
  }
  const double df1 = t.used - 1, df2 = double(rows) - t.used;
  if (df1 < 1 || df2 < 1 || ssw <= 0) return std::nullopt;
  t.f_statistic = (ssb / df1) / (ssw / df2);
  t.p_value = f_upper_tail(t.f_statistic, df1, df2);
  return t;
}

/// Every value column of the set against every rotary axis it moves.
void axis_columns(const Machine& m, const SetSlice& sl, const Eigen::VectorXd& r,
                  std::vector<ResidualStructure>& found) {
  const MeasurementSet& s = *sl.set;
  for (int k = 0; k < m.rotary_count(); ++k) {
    const int index = 3 + k;
    const AxisSampling sampling = axis_sampling({s}, index);
    const std::vector<double> at = axis_degrees(s, index, sampling.turns);
    if (at.empty()) continue;
    std::vector<double> centres;
    const std::vector<int> key = group_rows(at, sampling.turns, centres);
    const std::size_t g = centres.size();
    if (g < 3 || s.rows.size() < 2 * g) continue;
    for (int v = 0; v < sl.values; ++v) {
      const std::optional<GroupTest> t = group_test(sl, r, v, key, g);
      if (!t) continue;
      ResidualStructure st;
      st.file = s.file;
      st.value = value_name(s, v);
      st.axis = m.axes[static_cast<std::size_t>(index)].letter;
      st.groups = t->used;
      st.f_statistic = t->f_statistic;
      st.p_value = t->p_value;
      describe(st, centres, t->means, t->counts, sampling.turns, sampling);
      st.set_index = sl.index;
      st.value_index = v;
      st.group_of_row = key;
      found.push_back(std::move(st));
    }
  }
}

/// The rotary axes that move in the set ("C and A"); `st.axis` gets the one that travels furthest.
std::string moving_axes(const Machine& m, const MeasurementSet& s, ResidualStructure& st) {
  std::string moving;
  double travel = -1.0;
  for (int k = 0; k < m.rotary_count(); ++k) {
    double lo = 1e300, hi = -1e300;
    for (const auto& row : s.rows) lo = std::min(lo, row.command[3 + k]), hi = std::max(hi, row.command[3 + k]);
    if (hi - lo < 1e-6) continue;
    moving += (moving.empty() ? "" : " and ") + std::string(1, m.rotary(k).letter);
    if (hi - lo > travel) travel = hi - lo, st.axis = m.rotary(k).letter;
  }
  return moving;
}

/// The path test of value column v of a ballbar run (von Neumann's ratio); nullopt without scatter.
std::optional<ResidualStructure> path_column(const Machine& m, const SetSlice& sl, const Eigen::VectorXd& r, int v) {
  const MeasurementSet& s = *sl.set;
  const std::size_t rows = s.rows.size();
  auto y = [&](std::size_t i) { return sl.um(r, i, v); };
  double mean = 0.0;
  for (std::size_t i = 0; i < rows; ++i) mean += y(i);
  mean /= double(rows);
  double ss = 0.0, sd = 0.0;
  for (std::size_t i = 0; i < rows; ++i) ss += (y(i) - mean) * (y(i) - mean);
  for (std::size_t i = 1; i < rows; ++i) sd += (y(i) - y(i - 1)) * (y(i) - y(i - 1));
  if (ss <= 0) return std::nullopt;
  const double n = double(rows), eta = sd / ss;
  const double z = (2.0 - eta) / std::sqrt(4.0 * (n - 2.0) / (n * n - 1.0));
  ResidualStructure st;
  st.file = s.file;
  st.value = value_name(s, v);
  const std::string moving = moving_axes(m, s, st);
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
  st.set_index = sl.index;
  st.value_index = v;
  for (std::size_t i = 0; i < rows; ++i) st.group_of_row.push_back(static_cast<int>(i / 10));
  return st;
}

}  // namespace

std::vector<ResidualStructure> residual_columns(const Machine& m, const std::vector<MeasurementSet>& sets,
                                                const Eigen::VectorXd& r, const MeasurementType* only_type) {
  std::vector<ResidualStructure> found;
  const std::vector<SetSlice> slices = slices_of(sets);
  for (const SetSlice& sl : slices)
    if (!only_type || sl.set->type == *only_type) axis_columns(m, sl, r, found);
  // what no one axis shows: a residual that varies smoothly along a continuous path (a ballbar
  // run) where noise alone would not (von Neumann's ratio of successive differences to the
  // variance, 2 for noise, z-test one-sided): an effect of several axes together
  for (const SetSlice& sl : slices) {
    const MeasurementSet& s = *sl.set;
    if ((only_type && s.type != *only_type) || s.type != MeasurementType::ballbar || s.rows.size() < 30) continue;
    for (int v = 0; v < sl.values; ++v)
      if (std::optional<ResidualStructure> st = path_column(m, sl, r, v)) found.push_back(std::move(*st));
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
