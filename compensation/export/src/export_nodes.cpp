// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/export_nodes.hpp"
#include "ncpost/kinematics/units.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace ncpost::comp {

namespace {

/// Intervals of the even grid of a smooth error (harmonics, polynomials): at most, for a table of the
/// commanded position (as many as the rows allow), and at least, for an equidistant one.
constexpr int kSmoothIntervalsMax = 1000;
constexpr int kSmoothIntervalsMin = 200;

/// `n` on the file's grid of `resolution`, as a whole count.
long long count_of(double n, double resolution) { return std::llround(n / resolution); }

}  // namespace

std::vector<double> commanded_nodes(const MachineModel& model, const AxisExport& a, int max_nodes, double resolution) {
  const long long lo = count_of(a.travel_min, resolution), hi = count_of(a.travel_max, resolution);
  const long long turn = a.continuous ? count_of(kTwoPi, resolution) : 0;
  std::set<long long> must{lo, hi};
  auto add = [&](std::set<long long>& to, double n) {
    long long k = count_of(n, resolution);
    if (a.continuous) k = ((k - lo) % turn + turn) % turn + lo;  // round the turn
    if (k >= lo && k <= hi) to.insert(k);
  };
  // the kinks of the trim: where the drive, moving either way, passes a node of the error
  for (double x : a.model_nodes)
    for (bool falling : {false, true}) add(must, x + axis_positioning_error(model, a.axis_index, x, falling));
  if (static_cast<int>(must.size()) > max_nodes)
    throw ExportRefusal(
        ExportRefusal::Source::model,
        fmt::format("axis {} needs {} points (the kinks of its error, each direction of motion), more than "
                    "the {} the table can hold",
                    a.letter, must.size(), max_nodes));
  std::set<long long> nodes = must;
  for (double x : a.model_nodes) {
    std::set<long long> one;
    add(one, x);
    if (static_cast<int>(nodes.size() + one.size()) <= max_nodes) nodes.insert(one.begin(), one.end());
  }
  if (!a.piecewise_linear && hi > lo) {
    const int room = max_nodes - static_cast<int>(nodes.size());
    const int intervals = std::clamp(room - 1, 1, kSmoothIntervalsMax);
    for (int k = 1; k < intervals; ++k) nodes.insert(lo + (hi - lo) * k / intervals);
  }
  std::vector<double> out;
  for (long long k : nodes) out.push_back(static_cast<double>(k) * resolution);
  return out;
}

EquidistantPoints equidistant_points(const AxisExport& a, int max_points) {
  EquidistantPoints p;
  p.min = a.travel_min;
  const double span = a.travel_max - a.travel_min;
  if (span <= 0.0) {
    p.count = 1;
    return p;
  }
  std::vector<double> kinks{a.travel_min};
  for (double x : a.model_nodes)
    if (x > a.travel_min && x <= a.travel_max) kinks.push_back(x);
  kinks.push_back(a.travel_max);
  std::sort(kinks.begin(), kinks.end());
  double gap = span;
  for (std::size_t i = 1; i < kinks.size(); ++i)
    if (kinks[i] - kinks[i - 1] > 1e-12 * std::max(1.0, span)) gap = std::min(gap, kinks[i] - kinks[i - 1]);
  const double finest = a.piecewise_linear ? span : span / std::min(kSmoothIntervalsMax, max_points - 1);
  for (int divide = 1; span / (gap / divide) + 1.0 <= max_points + 1e-9; ++divide) {
    const double step = gap / divide;
    const bool on_grid = std::all_of(kinks.begin(), kinks.end(), [&](double x) {
      const double k = (x - a.travel_min) / step;
      return std::abs(k - std::round(k)) < 1e-7;
    });
    if (on_grid && step <= finest * (1.0 + 1e-12)) {
      p.step = step;
      p.count = static_cast<int>(std::lround(span / step)) + 1;
      return p;
    }
  }
  p.nodes_on_grid = false;
  p.step = span / 1000.0;
  p.count = 1001;
  return p;
}

}  // namespace ncpost::comp
