// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/laser_function.hpp"

#include <fmt/format.h>

#include <Eigen/QR>
#include <algorithm>
#include <cmath>

namespace ncpost::comp {

bool LaserFunction::fully_seen() const {
  return std::all_of(seen.begin(), seen.end(), [](bool b) { return b; });
}

bool LaserFunction::partly_seen() const {
  int n = 0;
  for (std::size_t i = 0; i < seen.size(); ++i) n += seen[i] && std::abs(nodes_mm[i]) > 1e-9;
  return n > 0;
}

std::string LaserFunction::kind() const {
  if (component == axis) return "positioning";
  if (component >= 'X') return fmt::format("straightness in {}", component);
  const int rot = component - 'A', ax = axis - 'X';
  if (rot == ax) return "roll";
  // ISO 230-1 words on a machine with Z vertical: rotation about the vertical is yaw for X and Y
  if (ax < 2) return rot == 2 ? "yaw" : "pitch";
  return rot == 0 ? "pitch" : "yaw";  // Z: about X pitch, about Y yaw (a common usage)
}

double LaserFunction::at(double x) const {
  const bool dense = !curve.nodes_mm.empty();
  const std::vector<double>& n = dense ? curve.nodes_mm : nodes_mm;
  const std::vector<double>& v = dense ? curve.values : values;
  if (n.empty()) return 0.0;
  if (x <= n.front()) return v.front();
  if (x >= n.back()) return v.back();
  std::size_t i = 1;
  while (n[i] < x) ++i;
  const double w = (x - n[i - 1]) / (n[i] - n[i - 1]);
  return v[i - 1] + w * (v[i] - v[i - 1]);
}

double least_squares_slope(const std::vector<double>& x, const std::vector<double>& y, double& range_about) {
  const double n = double(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sx += x[i];
    sy += y[i];
    sxx += x[i] * x[i];
    sxy += x[i] * y[i];
  }
  const double den = n * sxx - sx * sx;
  const double s = den > 0 ? (n * sxy - sx * sy) / den : 0.0;
  const double a = (sy - s * sx) / n;
  double lo = 1e300, hi = -1e300;
  for (std::size_t i = 0; i < x.size(); ++i) {
    lo = std::min(lo, y[i] - a - s * x[i]);
    hi = std::max(hi, y[i] - a - s * x[i]);
  }
  range_about = x.empty() ? 0.0 : hi - lo;
  return s;
}

double fit_polynomial_through_home(const std::vector<double>& x, const std::vector<double>& y,
                                   std::array<double, 3>& p) {
  const double scale = std::max(1.0, std::max(std::abs(x.front()), std::abs(x.back())));
  Eigen::MatrixXd A(static_cast<Eigen::Index>(x.size()), 3);
  Eigen::VectorXd b(static_cast<Eigen::Index>(x.size()));
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double u = x[i] / scale;
    A.row(static_cast<Eigen::Index>(i)) << u, u * u, u * u * u;
    b[static_cast<Eigen::Index>(i)] = y[i];
  }
  const Eigen::Index cols = std::min<Eigen::Index>(3, A.rows() - 1);
  p = {0.0, 0.0, 0.0};
  if (cols < 1) return 0.0;
  const Eigen::VectorXd c = A.leftCols(cols).colPivHouseholderQr().solve(b);
  for (Eigen::Index k = 0; k < cols; ++k) p[static_cast<std::size_t>(k)] = c[k] / std::pow(scale, double(k + 1));
  return std::sqrt((A.leftCols(cols) * c - b).squaredNorm() / double(x.size()));
}

}  // namespace ncpost::comp
