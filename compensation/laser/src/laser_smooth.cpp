// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/laser_smooth.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

namespace ncpost::comp {
namespace {

/// Second derivatives of the not-a-knot cubic spline through (x, y), at least 4 points.
Eigen::VectorXd spline_moments(const std::vector<double>& x, const std::vector<double>& y) {
  const auto n = static_cast<Eigen::Index>(x.size());
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(n);
  auto h = [&](Eigen::Index i) { return x[static_cast<std::size_t>(i + 1)] - x[static_cast<std::size_t>(i)]; };
  auto d = [&](Eigen::Index i) { return (y[static_cast<std::size_t>(i + 1)] - y[static_cast<std::size_t>(i)]) / h(i); };
  for (Eigen::Index i = 1; i + 1 < n; ++i) {  // first derivative continuous at the interior nodes
    A(i, i - 1) = h(i - 1);
    A(i, i) = 2.0 * (h(i - 1) + h(i));
    A(i, i + 1) = h(i);
    b[i] = 6.0 * (d(i) - d(i - 1));
  }
  // not-a-knot: the third derivative continuous at the second and the last but one node
  A(0, 0) = -h(1);
  A(0, 1) = h(0) + h(1);
  A(0, 2) = -h(0);
  A(n - 1, n - 3) = -h(n - 2);
  A(n - 1, n - 2) = h(n - 3) + h(n - 2);
  A(n - 1, n - 1) = -h(n - 3);
  return A.fullPivLu().solve(b);
}

double spline_eval(const std::vector<double>& x, const std::vector<double>& y, const Eigen::VectorXd& m, double at) {
  std::size_t i = 0;
  while (i + 2 < x.size() && at > x[i + 1]) ++i;
  const double h = x[i + 1] - x[i], a = x[i + 1] - at, c = at - x[i];
  const auto ii = static_cast<Eigen::Index>(i);
  return m[ii] * a * a * a / (6.0 * h) + m[ii + 1] * c * c * c / (6.0 * h) + (y[i] / h - m[ii] * h / 6.0) * a +
         (y[i + 1] / h - m[ii + 1] * h / 6.0) * c;
}

/// The candidates in order of complexity: linear (−1), legendre 1..3, spline (0), legendre 4...
std::vector<int> candidate_order(std::size_t points, int max_degree) {
  const int top = std::min(max_degree, static_cast<int>(points) - 3);
  std::vector<int> order{-1};
  for (int d = 1; d <= std::min(3, top); ++d) order.push_back(d);
  if (points >= 5) order.push_back(0);
  for (int d = 4; d <= top; ++d) order.push_back(d);
  return order;
}

/// The candidate's value at `at` fitted to (x, y): −1 linear, 0 spline, d > 0 legendre d.
std::vector<double> candidate_at(int which, const std::vector<double>& x, const std::vector<double>& y,
                                 const std::vector<double>& at) {
  if (which > 0) return legendre_fit_at(x, y, which, at);
  std::vector<double> out;
  out.reserve(at.size());
  if (which == 0) {
    if (x.size() < 4) return legendre_fit_at(x, y, static_cast<int>(x.size()) - 1, at);
    const Eigen::VectorXd m = spline_moments(x, y);
    for (double t : at) out.push_back(spline_eval(x, y, m, t));
    return out;
  }
  for (double t : at) {  // linear, held at the ends
    std::size_t i = 1;
    while (i + 1 < x.size() && x[i] < t) ++i;
    const double w = std::clamp((t - x[i - 1]) / (x[i] - x[i - 1]), 0.0, 1.0);
    out.push_back(y[i - 1] + w * (y[i] - y[i - 1]));
  }
  return out;
}

/// Leave-one-out rms over the interior nodes.
double leave_one_out_rms(int which, const std::vector<double>& x, const std::vector<double>& y) {
  double sum = 0.0;
  for (std::size_t i = 1; i + 1 < x.size(); ++i) {
    std::vector<double> xs, ys;
    for (std::size_t k = 0; k < x.size(); ++k)
      if (k != i) xs.push_back(x[k]), ys.push_back(y[k]);
    const double e = candidate_at(which, xs, ys, {x[i]})[0] - y[i];
    sum += e * e;
  }
  return std::sqrt(sum / double(x.size() - 2));
}

}  // namespace

std::string LaserCurve::label() const {
  switch (basis) {
    case LaserBasis::linear:
      return "linear";
    case LaserBasis::spline:
      return "spline";
    case LaserBasis::legendre:
      return fmt::format("legendre {}", degree);
  }
  return "?";
}

double spline_at(const std::vector<double>& x, const std::vector<double>& y, double at) {
  return candidate_at(x.size() < 3 ? -1 : 0, x, y, {at})[0];
}

std::vector<double> legendre_fit_at(const std::vector<double>& x, const std::vector<double>& y, int degree,
                                    const std::vector<double>& at) {
  const double centre = 0.5 * (x.front() + x.back());
  const double half = std::max(1e-9, 0.5 * (x.back() - x.front()));
  auto basis = [&](double t) {
    const double u = (t - centre) / half;
    Eigen::RowVectorXd p(degree + 1);
    p[0] = 1.0;
    if (degree >= 1) p[1] = u;
    for (int k = 2; k <= degree; ++k) p[k] = ((2.0 * k - 1.0) * u * p[k - 1] - (k - 1.0) * p[k - 2]) / k;
    return p;
  };
  Eigen::MatrixXd A(static_cast<Eigen::Index>(x.size()), degree + 1);
  Eigen::VectorXd b(static_cast<Eigen::Index>(x.size()));
  for (std::size_t i = 0; i < x.size(); ++i) {
    A.row(static_cast<Eigen::Index>(i)) = basis(x[i]);
    b[static_cast<Eigen::Index>(i)] = y[i];
  }
  const Eigen::VectorXd c = A.colPivHouseholderQr().solve(b);
  std::vector<double> out;
  out.reserve(at.size());
  for (double t : at) out.push_back(basis(t).dot(c));
  return out;
}

LaserCurve choose_laser_curve(const std::vector<double>& x, const std::vector<double>& y, double step_mm,
                              int max_degree) {
  LaserCurve curve;
  curve.nodes_mm = x;
  curve.values = y;
  if (x.size() < 4) return curve;  // nothing to leave out and still compare
  std::vector<std::pair<int, double>> scored;
  for (int which : candidate_order(x.size(), max_degree)) scored.emplace_back(which, leave_one_out_rms(which, x, y));
  double best = std::numeric_limits<double>::infinity();
  for (const auto& s : scored) best = std::min(best, s.second);
  curve.cv_linear_rms = scored.front().second;
  const auto chosen = std::find_if(scored.begin(), scored.end(),
                                   [&](const std::pair<int, double>& s) { return s.second <= best * (1.0 + kCvTie); });
  curve.cv_rms = chosen->second;
  if (chosen->first < 0) return curve;
  curve.basis = chosen->first == 0 ? LaserBasis::spline : LaserBasis::legendre;
  curve.degree = std::max(0, chosen->first);
  std::vector<double> at = x;
  for (double t = x.front() + step_mm; t < x.back() - 1e-9; t += step_mm) at.push_back(t);
  at.push_back(0.0);
  std::sort(at.begin(), at.end());
  at.erase(std::unique(at.begin(), at.end(), [](double a, double b) { return std::abs(a - b) < 1e-6; }), at.end());
  std::vector<double> v = candidate_at(chosen->first, x, y, at);
  const double home = candidate_at(chosen->first, x, y, {0.0})[0];
  for (double& e : v) e -= home;
  curve.nodes_mm = at;
  curve.values = v;
  return curve;
}

}  // namespace ncpost::comp
