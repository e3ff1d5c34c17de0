// SPDX-License-Identifier: Apache-2.0
// The fitting core's rank and null space (compensation/fit/scaled_svd.hpp, fit/rank.hpp) on a
// Jacobian built to be rank deficient: column 2 is twice column 1, so after column scaling the
// two are the same unit column and the null direction is (1, −1, 0)/√2, worked out by hand.
#include <catch2/catch.hpp>

#include <cmath>

#include "ncpost/compensation/fit/damped_least_squares.hpp"
#include "ncpost/compensation/fit/rank.hpp"
#include "ncpost/compensation/fit/scaled_svd.hpp"

using namespace ncpost::comp;

namespace {

/// Columns c, 2c, e with c and e orthogonal, |c| = 2, |e| = 3.
Eigen::MatrixXd dependent_columns() {
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(4, 3);
  J.col(0) << 2.0, 0.0, 0.0, 0.0;
  J.col(1) = 2.0 * J.col(0);
  J.col(2) << 0.0, 0.0, 3.0, 0.0;
  return J;
}

}  // namespace

TEST_CASE("fit core: rank and null space of a rank-deficient Jacobian", "[fit]") {
  const ScaledSvd s = scaled_svd(dependent_columns(), 0.0, 1e-9);
  CHECK(s.rank == 2);
  CHECK(s.scale[0] == Approx(2.0));
  CHECK(s.scale[1] == Approx(4.0));
  CHECK(s.scale[2] == Approx(3.0));
  const auto null = s.null_space();
  REQUIRE(null.size() == 1);
  const double r = 1.0 / std::sqrt(2.0);
  CHECK(std::abs(null[0][0]) == Approx(r));
  CHECK(null[0][1] == Approx(-null[0][0]));
  CHECK(std::abs(null[0][2]) < 1e-12);
  // each of the two dependent parameters has half of its unit vector in the null space
  const Eigen::VectorXd share = s.null_share();
  CHECK(share[0] == Approx(0.5));
  CHECK(share[1] == Approx(0.5));
  CHECK(share[2] == Approx(0.0).margin(1e-12));
}

TEST_CASE("fit core: the truncated step is the minimum-norm solution in the scaled parameters", "[fit]") {
  // J·δ = b with b = 3·c + 6·e: δ1 + 2·δ2 = 3 and δ3 = 2. In the scaled parameters s = D·δ
  // (d = 2, 4, 3) the two dependent ones share equally: s1 = s2 = 3, so δ1 = 1.5, δ2 = 0.75
  const Eigen::MatrixXd J = dependent_columns();
  const Eigen::VectorXd b = 3.0 * J.col(0) + 2.0 * J.col(2);
  const Eigen::VectorXd step = scaled_svd(J, 0.0, 1e-9).step(b, 0.0);
  CHECK(step[0] == Approx(1.5));
  CHECK(step[1] == Approx(0.75));
  CHECK(step[2] == Approx(2.0));
  // the solver with that cut reaches the same point and stays there (y off the columns by 0.5
  // in the fourth row, which no column reaches: the minimum keeps that residual)
  Eigen::VectorXd y = b;
  y[3] = 0.5;
  LeastSquaresProblem p;
  p.residuals = [&](const Eigen::VectorXd& x) -> std::optional<Eigen::VectorXd> { return Eigen::VectorXd(J * x - y); };
  p.jacobian = [&](const Eigen::VectorXd&) { return J; };
  DampedOptions o;
  o.initial_damping = 0.0;
  o.relative_cut = 1e-9;
  const DampedSummary sum = levenberg_marquardt(p, Eigen::VectorXd::Zero(3), -y, o);
  REQUIRE(sum.converged);
  CHECK(sum.x[0] == Approx(1.5));
  CHECK(sum.x[1] == Approx(0.75));
  CHECK(sum.r.norm() == Approx(0.5));
}

TEST_CASE("fit core: a column below the unseen share is not seen at all", "[fit]") {
  Eigen::MatrixXd J = dependent_columns();
  J.col(1) << 0.0, 1e-9, 0.0, 0.0;  // independent, but 1e-9 of the largest
  const ScaledSvd s = scaled_svd(J, 1e-7, 1e-6);
  CHECK(s.scale[1] == 1.0);
  CHECK(s.rank == 2);
  REQUIRE(s.null_space().size() == 1);
  CHECK(std::abs(s.null_space()[0][1]) == Approx(1.0));
}

TEST_CASE("fit core: the priority rule pins the later of two dependent columns", "[fit]") {
  const RankAnalysis a = analyse_rank(dependent_columns(), 1e-3);
  CHECK(a.rank == 2);
  REQUIRE(a.pinned == std::vector<int>{1});
  CHECK(a.kept == std::vector<int>{0, 2});
  // e_p − x·e_k with scaled column 1 = scaled column 0 (x = 1), normalised
  REQUIRE(a.null_vectors.size() == 1);
  CHECK(a.null_vectors[0][1] == Approx(1.0 / std::sqrt(2.0)));
  CHECK(a.null_vectors[0][0] == Approx(-1.0 / std::sqrt(2.0)));
  CHECK(std::abs(a.null_vectors[0][2]) < 1e-12);
}
