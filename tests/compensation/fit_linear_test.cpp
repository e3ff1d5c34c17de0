// SPDX-License-Identifier: Apache-2.0
// The fitting core (compensation/fit/damped_least_squares.hpp) on problems whose answer is known
// without it: a polynomial through exact data, the least-squares line of noisy data (the normal
// equations solved by hand), an exponential decay (nonlinear), a step the model cannot evaluate,
// and a robust loss that leaves an outlier out.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "ncpost/compensation/fit/damped_least_squares.hpp"

using namespace ncpost::comp;

namespace {

/// The linear problem r(x) = A·x − y.
LeastSquaresProblem linear_problem(const Eigen::MatrixXd& A, const Eigen::VectorXd& y) {
  LeastSquaresProblem p;
  p.residuals = [A, y](const Eigen::VectorXd& x) -> std::optional<Eigen::VectorXd> {
    return Eigen::VectorXd(A * x - y);
  };
  p.jacobian = [A](const Eigen::VectorXd&) { return A; };
  return p;
}

/// Columns 1, t, t² at t = 0, 1, ..., n − 1.
Eigen::MatrixXd quadratic_design(int n) {
  Eigen::MatrixXd A(n, 3);
  for (int i = 0; i < n; ++i) A.row(i) << 1.0, double(i), double(i) * double(i);
  return A;
}

/// Samples of the exponential decay (test below).
constexpr int kDecaySamples = 12;

DampedSummary solve(const LeastSquaresProblem& p, const Eigen::VectorXd& x0, const DampedOptions& o = {}) {
  return levenberg_marquardt(p, x0, *p.residuals(x0), o);
}

/// Alternating ±size: data that no smooth model meets exactly (a residual left at the minimum,
/// so that the stop rules meet a real minimum rather than rounding at zero).
Eigen::VectorXd ripple(Eigen::Index n, double size) {
  Eigen::VectorXd v(n);
  for (Eigen::Index i = 0; i < n; ++i) v[i] = i % 2 ? size : -size;
  return v;
}

}  // namespace

TEST_CASE("fit core: a quadratic is recovered, the solution of the normal equations", "[fit]") {
  const Eigen::MatrixXd A = quadratic_design(7);
  const Eigen::Vector3d truth(0.25, -1.5, 0.125);
  const Eigen::VectorXd y = A * truth + ripple(7, 1e-4);
  // the least-squares solution by another route: AᵀA x = Aᵀy
  const Eigen::VectorXd expected = (A.transpose() * A).inverse() * (A.transpose() * y);
  const DampedSummary s = solve(linear_problem(A, y), Eigen::VectorXd::Zero(3));
  REQUIRE(s.converged);
  CHECK((s.x - expected).cwiseAbs().maxCoeff() < 1e-9);
  CHECK((s.x - truth).cwiseAbs().maxCoeff() < 1e-3);
  CHECK(s.r.norm() == Approx((A * expected - y).norm()).epsilon(1e-9));
  CHECK(s.iterations >= 1);
}

TEST_CASE("fit core: the least-squares line of noisy data is the normal equations' solution", "[fit]") {
  // y = a + b·t at t = 0..4 with residuals ±; the closed form: b = Σ(t−t̄)(y−ȳ) / Σ(t−t̄)², a = ȳ − b·t̄
  const std::vector<double> t{0, 1, 2, 3, 4}, y{1.1, 2.9, 5.2, 6.8, 9.1};
  Eigen::MatrixXd A(5, 2);
  Eigen::VectorXd yv(5);
  double tm = 0, ym = 0;
  for (int i = 0; i < 5; ++i) {
    A.row(i) << 1.0, t[i];
    yv[i] = y[i];
    tm += t[i] / 5.0;
    ym += y[i] / 5.0;
  }
  double stt = 0, sty = 0;
  for (int i = 0; i < 5; ++i) stt += (t[i] - tm) * (t[i] - tm), sty += (t[i] - tm) * (y[i] - ym);
  const double b = sty / stt, a = ym - b * tm;
  const DampedSummary s = solve(linear_problem(A, yv), Eigen::VectorXd::Zero(2));
  REQUIRE(s.converged);
  CHECK(s.x[0] == Approx(a).epsilon(1e-10));
  CHECK(s.x[1] == Approx(b).epsilon(1e-10));
}

TEST_CASE("fit core: an exponential decay is found from far away (nonlinear)", "[fit]") {
  // y = 3·exp(−0.7·t), exact; start at (1, 0.1)
  LeastSquaresProblem p;
  p.residuals = [](const Eigen::VectorXd& x) -> std::optional<Eigen::VectorXd> {
    Eigen::VectorXd r(kDecaySamples);
    for (int i = 0; i < kDecaySamples; ++i)
      r[i] = x[0] * std::exp(-x[1] * 0.5 * i) - 3.0 * std::exp(-0.7 * 0.5 * i) + (i % 2 ? 1e-7 : -1e-7);
    return r;
  };
  p.jacobian = [](const Eigen::VectorXd& x) {
    Eigen::MatrixXd J(kDecaySamples, 2);
    for (int i = 0; i < kDecaySamples; ++i) {
      const double e = std::exp(-x[1] * 0.5 * i);
      J.row(i) << e, -x[0] * 0.5 * i * e;
    }
    return J;
  };
  const DampedSummary s = solve(p, Eigen::Vector2d(1.0, 0.1));
  REQUIRE(s.converged);
  CHECK(s.x[0] == Approx(3.0).epsilon(1e-5));  // the ripple of 1e-7 moves them by about as much
  CHECK(s.x[1] == Approx(0.7).epsilon(1e-5));
  CHECK(s.r.norm() < 1e-6);
}

TEST_CASE("fit core: a step where the model cannot be evaluated is rejected, the fit damps and goes on", "[fit]") {
  // r = x − 8, but the model cannot be evaluated beyond x = 6: from −10 the Gauss–Newton step
  // lands at 8, outside; the fit must damp its steps and end inside, close to the border
  LeastSquaresProblem p;
  p.residuals = [](const Eigen::VectorXd& x) -> std::optional<Eigen::VectorXd> {
    if (x[0] > 6.0) return std::nullopt;
    return Eigen::VectorXd::Constant(1, x[0] - 8.0);
  };
  p.jacobian = [](const Eigen::VectorXd&) { return Eigen::MatrixXd::Ones(1, 1); };
  DampedOptions o;
  o.initial_damping = 0.0;  // Gauss–Newton first: its full step to 8 is not evaluable
  o.max_iterations = 200;
  const DampedSummary s = solve(p, Eigen::VectorXd::Constant(1, -10.0), o);
  CHECK(s.x[0] <= 6.0);
  CHECK(s.x[0] > 5.0);  // damped steps creep towards the border
  CHECK(s.cost < 0.5 * 18.0 * 18.0);
}

TEST_CASE("fit core: a Huber loss leaves an outlier out where squares follow it", "[fit]") {
  // the mean of {1, 1, 1, 1, 101}: 21 with squares; with Huber (k = 1) the minimum of
  // Σρ(x − y_i) has 4·(x − 1) = k (the outlier's constant pull), x = 1.25
  Eigen::MatrixXd A = Eigen::MatrixXd::Ones(5, 1);
  Eigen::VectorXd y(5);
  y << 1, 1, 1, 1, 101;
  const LeastSquaresProblem p = linear_problem(A, y);
  CHECK(solve(p, Eigen::VectorXd::Zero(1)).x[0] == Approx(21.0).epsilon(1e-10));
  DampedOptions o;
  o.loss = {Loss::huber, 1.0};
  const DampedSummary s = solve(p, Eigen::VectorXd::Zero(1), o);
  REQUIRE(s.converged);
  CHECK(s.x[0] == Approx(1.25).epsilon(1e-6));
}

TEST_CASE("fit core: a per-variable step tolerance stops the fit and options are validated", "[fit]") {
  const Eigen::MatrixXd A = quadratic_design(5);
  const Eigen::Vector3d truth(1.0, 2.0, 3.0);
  DampedOptions o;
  o.initial_damping = 0.0;
  o.step_tolerance = Eigen::Vector3d::Constant(1e-9);
  const DampedSummary s = solve(linear_problem(A, A * truth + ripple(5, 1e-6)), Eigen::VectorXd::Zero(3), o);
  REQUIRE(s.converged);
  CHECK(s.iterations <= 2);  // the Gauss–Newton step lands, a second one moves nothing
  CHECK((s.x - truth).cwiseAbs().maxCoeff() < 1e-5);
  CHECK(o.validate().empty());
  o.max_iterations = 0;
  CHECK_FALSE(o.validate().empty());
  o.max_iterations = 1;
  o.relative_cut = 1.0;
  CHECK_FALSE(o.validate().empty());
}
