// SPDX-License-Identifier: Apache-2.0
#include "ncpost/report/circularity.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace ncpost::report {
namespace {

constexpr double kTwoPi = 6.283185307179586;

/// Solves the 3×3 system a x = b (Gaussian elimination with pivoting); false if singular.
bool solve3(double a[3][3], double b[3], double x[3]) {
  for (int c = 0; c < 3; ++c) {
    int p = c;
    for (int r = c + 1; r < 3; ++r)
      if (std::abs(a[r][c]) > std::abs(a[p][c])) p = r;
    if (std::abs(a[p][c]) < 1e-12) return false;
    std::swap(a[p], a[c]);
    std::swap(b[p], b[c]);
    for (int r = c + 1; r < 3; ++r) {
      const double f = a[r][c] / a[c][c];
      for (int k = c; k < 3; ++k) a[r][k] -= f * a[c][k];
      b[r] -= f * b[c];
    }
  }
  for (int r = 2; r >= 0; --r) {
    double s = b[r];
    for (int k = r + 1; k < 3; ++k) s -= a[r][k] * x[k];
    x[r] = s / a[r][r];
  }
  return true;
}

double wrap(double a) {
  a = std::fmod(a, kTwoPi);
  return a < 0 ? a + kTwoPi : a;
}

/// (angle in [0, 2π), value) sorted by angle.
using Curve = std::vector<std::pair<double, double>>;

double interpolate(const Curve& c, double a, bool& inside) {
  inside = false;
  if (c.size() < 2) return 0.0;
  auto it =
      std::lower_bound(c.begin(), c.end(), a, [](const std::pair<double, double>& e, double v) { return e.first < v; });
  if (it == c.end() || it == c.begin()) return 0.0;
  const auto& hi = *it;
  const auto& lo = *(it - 1);
  if (hi.first - lo.first > 0.2) return 0.0;  // a gap of more than ~11°: no comparison there
  inside = true;
  const double w = (a - lo.first) / std::max(hi.first - lo.first, 1e-15);
  return lo.second + w * (hi.second - lo.second);
}

/// The largest |ccw − cw| at the counter-clockwise angles the clockwise curve covers; < 0 if none.
double largest_difference(Curve ccw, Curve cw) {
  if (ccw.size() < 2 || cw.size() < 2) return -1.0;
  std::sort(ccw.begin(), ccw.end());
  std::sort(cw.begin(), cw.end());
  double h = -1.0;
  for (const auto& [angle, d] : ccw) {
    bool inside = false;
    const double other = interpolate(cw, angle, inside);
    if (inside) h = std::max(h, std::abs(d - other));
  }
  return h;
}

}  // namespace

double circular_hysteresis_um(const std::vector<double>& ccw_angle, const std::vector<double>& ccw_um,
                              const std::vector<double>& cw_angle, const std::vector<double>& cw_um) {
  Curve ccw, cw;
  for (std::size_t k = 0; k < std::min(ccw_angle.size(), ccw_um.size()); ++k)
    ccw.push_back({wrap(ccw_angle[k]), ccw_um[k]});
  for (std::size_t k = 0; k < std::min(cw_angle.size(), cw_um.size()); ++k) cw.push_back({wrap(cw_angle[k]), cw_um[k]});
  return largest_difference(std::move(ccw), std::move(cw));
}

CircularityFigures iso230_4_circularity(const std::vector<double>& ang, const std::vector<double>& r) {
  CircularityFigures f;
  const std::size_t n = std::min(ang.size(), r.size());
  if (n < 8) {
    f.message = "fewer than 8 points";
    return f;
  }
  double lo = ang[0], hi = ang[0];
  int up = 0, down = 0;
  for (std::size_t k = 0; k < n; ++k) {
    lo = std::min(lo, ang[k]);
    hi = std::max(hi, ang[k]);
    if (k > 0 && ang[k] > ang[k - 1]) ++up;
    if (k > 0 && ang[k] < ang[k - 1]) ++down;
  }
  f.arc_deg = std::min(360.0, (hi - lo) * 180.0 / 3.141592653589793);
  f.direction = up > 0 && down > 0 ? 0 : (down > 0 ? -1 : 1);
  if (f.arc_deg < 90.0) {
    f.message = "the path covers less than 90°: no circle fit";
    return f;
  }
  double a[3][3] = {}, b[3] = {}, x[3] = {};
  for (std::size_t k = 0; k < n; ++k) {
    const double row[3] = {1.0, std::cos(ang[k]), std::sin(ang[k])};
    for (int i = 0; i < 3; ++i) {
      b[i] += row[i] * r[k];
      for (int j = 0; j < 3; ++j) a[i][j] += row[i] * row[j];
    }
  }
  if (!solve3(a, b, x)) {
    f.message = "the angles do not determine a circle";
    return f;
  }
  f.centre_x_um = x[1];
  f.centre_y_um = x[2];
  double dmin = INFINITY, dmax = -INFINITY;
  f.F_max_um = -INFINITY;
  f.F_min_um = INFINITY;
  Curve ccw, cw;
  for (std::size_t k = 0; k < n; ++k) {
    const double d = r[k] - x[1] * std::cos(ang[k]) - x[2] * std::sin(ang[k]);
    dmin = std::min(dmin, d);
    dmax = std::max(dmax, d);
    f.F_max_um = std::max(f.F_max_um, r[k]);
    f.F_min_um = std::min(f.F_min_um, r[k]);
    // the direction of a point: of the move that reaches it (the first point: of the move that leaves it)
    const double step = k > 0 ? ang[k] - ang[k - 1] : ang[1] - ang[0];
    if (step > 0)
      ccw.push_back({wrap(ang[k]), d});
    else if (step < 0)
      cw.push_back({wrap(ang[k]), d});
  }
  f.G_um = dmax - dmin;
  if (f.direction == 0) f.H_um = largest_difference(std::move(ccw), std::move(cw));
  f.ok = true;
  return f;
}

CircularityByDirection iso230_4_by_direction(const std::vector<double>& ang, const std::vector<double>& r) {
  CircularityByDirection out;
  out.both = iso230_4_circularity(ang, r);
  const std::size_t n = std::min(ang.size(), r.size());
  std::vector<double> a_ccw, r_ccw, a_cw, r_cw;
  for (std::size_t k = 0; k < n; ++k) {
    const double step = k > 0 ? ang[k] - ang[k - 1] : (n > 1 ? ang[1] - ang[0] : 0.0);
    if (step > 0)
      a_ccw.push_back(ang[k]), r_ccw.push_back(r[k]);
    else if (step < 0)
      a_cw.push_back(ang[k]), r_cw.push_back(r[k]);
  }
  out.ccw = iso230_4_circularity(a_ccw, r_ccw);
  out.cw = iso230_4_circularity(a_cw, r_cw);
  if (a_ccw.empty()) out.ccw.message = "no counter-clockwise run";
  if (a_cw.empty()) out.cw.message = "no clockwise run";
  return out;
}

}  // namespace ncpost::report
