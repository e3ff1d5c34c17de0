// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/diagnose_screening.hpp"

#include <algorithm>
#include <boost/math/distributions/fisher_f.hpp>
#include <cmath>

namespace ncpost::comp {

/// Upper tail probability of the F distribution.
double f_upper_tail(double f, double k, double dof) {
  if (!(f > 0.0) || k < 1 || dof < 1) return 1.0;
  const boost::math::fisher_f_distribution<double> dist(k, dof);
  return boost::math::cdf(boost::math::complement(dist, f));
}

Eigen::MatrixXd added_basis(const Eigen::MatrixXd& Q, const Eigen::MatrixXd& C, double tol, int& aliased_column) {
  Eigen::MatrixXd B(C.rows(), 0);
  aliased_column = -1;
  for (Eigen::Index j = 0; j < C.cols(); ++j) {
    const double norm = C.col(j).norm();
    Eigen::VectorXd c = C.col(j);
    for (int pass = 0; pass < 2; ++pass) {
      c -= Q * (Q.transpose() * c);
      c -= B * (B.transpose() * c);
    }
    if (!(norm > 0.0) || c.norm() <= tol * norm) {
      aliased_column = static_cast<int>(j);
      return B;
    }
    B.conservativeResize(Eigen::NoChange, B.cols() + 1);
    B.col(B.cols() - 1) = c.normalized();
  }
  return B;
}

bool same_directions(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, double tol) {
  if (a.cols() != b.cols() || a.cols() == 0) return false;
  const Eigen::MatrixXd rest = b - a * (a.transpose() * b);
  return rest.norm() <= tol * std::sqrt(double(b.cols()));
}

DriftScreen screen_drift(const std::string& effect, const Eigen::MatrixXd& Q, const Eigen::VectorXd& lin,
                         const Eigen::VectorXd& r, const Eigen::VectorXd& t, double t_span, double tol,
                         double significance) {
  const Eigen::Index count = lin.size();
  Eigen::VectorXd g = Eigen::VectorXd::Zero(count);
  for (Eigen::Index i = 0; i < count; ++i)
    if (t[i] > 0) g[i] = lin[i] / t[i];
  auto exp_column = [&](double tau) {
    Eigen::VectorXd e(count);
    for (Eigen::Index i = 0; i < count; ++i) e[i] = g[i] * (1.0 - std::exp(-t[i] / tau));
    return e;
  };
  struct Fit {
    double drop = -1.0;
    Eigen::MatrixXd basis;
    double tau = 0.0;
  };
  auto try_columns = [&](const Eigen::MatrixXd& cols, double tau, Fit& best) {
    int a = -1;
    Eigen::MatrixXd B = added_basis(Q, cols, tol, a);
    if (a >= 0) return -1.0;
    const double d = (B.transpose() * r).squaredNorm();
    if (d > best.drop) best = {d, B, tau};
    return d;
  };
  const int grid = 60;
  const double lo = std::log(30.0), hi = std::log(4.0 * t_span);
  auto tau_at = [&](double k) { return std::exp(lo + (hi - lo) * k / grid); };
  Fit lin_only, exp_only, both;
  try_columns(lin, 0.0, lin_only);
  std::vector<double> exp_drop(grid + 1, -1.0), both_drop(grid + 1, -1.0);
  for (int k = 0; k <= grid; ++k) {
    const Eigen::VectorXd e = exp_column(tau_at(k));
    exp_drop[static_cast<std::size_t>(k)] = try_columns(e, tau_at(k), exp_only);
    Eigen::MatrixXd two(count, 2);
    two << lin, e;
    both_drop[static_cast<std::size_t>(k)] = try_columns(two, tau_at(k), both);
  }
  // refine the best tau of each exp variant by a parabola through its grid neighbours
  auto refine = [&](const std::vector<double>& drops, Fit& best, bool with_lin) {
    const auto it = std::max_element(drops.begin(), drops.end());
    const int k = static_cast<int>(it - drops.begin());
    if (k == 0 || k == grid || drops[static_cast<std::size_t>(k - 1)] < 0 || drops[static_cast<std::size_t>(k + 1)] < 0)
      return;
    const double a = drops[static_cast<std::size_t>(k - 1)], b = drops[static_cast<std::size_t>(k)],
                 c = drops[static_cast<std::size_t>(k + 1)];
    const double den = a - 2.0 * b + c;
    if (!(den < 0.0)) return;
    const double shift = 0.5 * (a - c) / den;
    const double tau = tau_at(k + std::clamp(shift, -0.5, 0.5));
    if (with_lin) {
      Eigen::MatrixXd two(count, 2);
      two << lin, exp_column(tau);
      try_columns(two, tau, best);
    } else {
      try_columns(exp_column(tau), tau, best);
    }
  };
  refine(exp_drop, exp_only, false);
  refine(both_drop, both, true);
  const Fit& single = exp_only.drop > lin_only.drop ? exp_only : lin_only;
  DriftScreen out;
  if (single.drop < 0.0 && both.drop < 0.0) return out;
  const Fit* chosen = &single;
  if (both.drop > single.drop) {
    const double dof = double(count - Q.cols() - 2);
    const double f = (both.drop - std::max(single.drop, 0.0)) / (std::max(r.squaredNorm() - both.drop, 1e-300) / dof);
    if (single.drop < 0.0 || f_upper_tail(f, 1.0, dof) < 1e-2 * significance) chosen = &both;
  }
  out.aliased = false;
  out.drop = chosen->drop;
  out.basis = chosen->basis;
  if (chosen == &lin_only || chosen == &both) out.parameters.push_back(effect + ":lin");
  if (chosen != &lin_only) {
    out.parameters.push_back(effect + ":exp");
    out.held.set(effect + ":tau", chosen->tau);
  }
  return out;
}

}  // namespace ncpost::comp
