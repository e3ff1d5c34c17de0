// SPDX-License-Identifier: Apache-2.0
// The fitting core's covariance (compensation/fit/scaled_svd.hpp) against the textbook formulas
// of the straight line y = a + b·t (s² the residual variance, S_tt = Σ(t − t̄)²):
//   var b = s² / S_tt,  var a = s² (1/n + t̄² / S_tt),  cov(a, b) = −s² t̄ / S_tt,
// independent of the units of the columns (the scaling must not leak into the result), and with
// a dependent column the undetermined parameters are the ones with a null-space share.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "ncpost/compensation/fit/scaled_svd.hpp"

using namespace ncpost::comp;

TEST_CASE("fit core: covariance of a straight line equals the hand formula", "[fit]") {
  const std::vector<double> t{1.0, 2.0, 4.0, 7.0, 11.0, 16.0};
  const double n = double(t.size());
  double tm = 0.0;
  for (double v : t) tm += v / n;
  double stt = 0.0;
  for (double v : t) stt += (v - tm) * (v - tm);
  const double s2 = 0.04;
  // the column of b in a large unit (×1000): the covariance in the parameters as given
  for (double unit : {1.0, 1000.0}) {
    Eigen::MatrixXd J(static_cast<Eigen::Index>(t.size()), 2);
    for (std::size_t i = 0; i < t.size(); ++i) J.row(static_cast<Eigen::Index>(i)) << 1.0, unit * t[i];
    const Eigen::MatrixXd c = scaled_svd(J).covariance(s2);
    const double u2 = unit * unit;
    CHECK(c(1, 1) == Approx(s2 / stt / u2).epsilon(1e-10));
    CHECK(c(0, 0) == Approx(s2 * (1.0 / n + tm * tm / stt)).epsilon(1e-10));
    CHECK(c(0, 1) == Approx(-s2 * tm / stt / unit).epsilon(1e-10));
    CHECK(c(1, 0) == Approx(c(0, 1)).epsilon(1e-12));
  }
}

TEST_CASE("fit core: covariance of a rank-deficient Jacobian lives in the seen directions", "[fit]") {
  // columns c, c, e (|c| = |e| = 1): seen are (1, 1, 0)/√2 with σ = √2 and (0, 0, 1) with σ = 1;
  // (JᵀJ)⁺ = v vᵀ/2 + e3 e3ᵀ: ¼ in the 2×2 block, 1 for the third
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(3, 3);
  J(0, 0) = J(0, 1) = 1.0;
  J(1, 2) = 1.0;
  const ScaledSvd s = scaled_svd(J, 0.0, 1e-9);
  const Eigen::MatrixXd c = s.covariance(1.0);
  CHECK(c(0, 0) == Approx(0.25));
  CHECK(c(0, 1) == Approx(0.25));
  CHECK(c(1, 1) == Approx(0.25));
  CHECK(c(2, 2) == Approx(1.0));
  CHECK(std::abs(c(0, 2)) < 1e-12);
}
