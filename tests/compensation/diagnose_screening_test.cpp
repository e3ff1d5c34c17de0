// SPDX-License-Identifier: Apache-2.0
// The linearised screening of residual analysis (diagnose_screening.hpp) on synthetic columns:
// the drop it reports is the least-squares drop, aliased and equivalent candidates are told, and
// the drift law (lin, exp with its time constant, or both) is chosen as the data say.
#include <catch2/catch.hpp>

#include <Eigen/QR>
#include <cmath>
#include <random>

#include "ncpost/compensation/diagnose_screening.hpp"

using namespace ncpost::comp;

namespace {

Eigen::MatrixXd orthonormal(const Eigen::MatrixXd& A) {
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(A);
  return qr.householderQ() * Eigen::MatrixXd::Identity(A.rows(), A.cols());
}

}  // namespace

TEST_CASE("added_basis: drop equals the least-squares drop; aliasing and equivalence", "[diagnose][screening]") {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> n(0.0, 1.0);
  const int m = 400;
  Eigen::MatrixXd model(m, 3), cand(m, 2);
  Eigen::VectorXd r(m);
  for (int i = 0; i < m; ++i) {
    for (int c = 0; c < 3; ++c) model(i, c) = n(rng);
    for (int c = 0; c < 2; ++c) cand(i, c) = n(rng);
    r[i] = n(rng);
  }
  const Eigen::MatrixXd Q = orthonormal(model);
  int aliased = 0;
  const Eigen::MatrixXd B = added_basis(Q, cand, 1e-3, aliased);
  REQUIRE(aliased == -1);
  REQUIRE(B.cols() == 2);
  // least squares with and without the candidate
  Eigen::MatrixXd both(m, 5);
  both << model, cand;
  const double s0 = (r - model * model.colPivHouseholderQr().solve(r)).squaredNorm();
  const double s1 = (r - both * both.colPivHouseholderQr().solve(r)).squaredNorm();
  CHECK((B.transpose() * r).squaredNorm() == Approx(s0 - s1).epsilon(1e-9));

  // a column in the span of the model is aliased
  Eigen::MatrixXd in_span(m, 1);
  in_span.col(0) = model * Eigen::Vector3d(0.3, -1.0, 2.0);
  added_basis(Q, in_span, 1e-3, aliased);
  CHECK(aliased == 0);

  // two candidates differing by a model column add the same directions
  Eigen::MatrixXd other = cand;
  other.col(0) += 5.0 * model.col(1);
  const Eigen::MatrixXd B2 = added_basis(Q, other, 1e-3, aliased);
  CHECK(same_directions(B, B2, 1e-6));
  Eigen::MatrixXd different = cand;
  different.col(1) = Eigen::VectorXd::Random(m);
  CHECK_FALSE(same_directions(B, added_basis(Q, different, 1e-3, aliased), 1e-2));
}

TEST_CASE("screen_drift chooses the law the data follow", "[diagnose][screening]") {
  std::mt19937_64 rng(9);
  std::normal_distribution<double> noise(0.0, 5e-4);
  const int m = 600;
  Eigen::VectorXd t(m), g(m);
  for (int i = 0; i < m; ++i) {
    t[i] = 2.0 * i;                                         // 0 .. 1198 s
    g[i] = std::cos(0.01 * i) + 0.3 * std::sin(0.037 * i);  // d r / d drift of each value
  }
  Eigen::MatrixXd model(m, 1);
  model.col(0) = Eigen::VectorXd::Ones(m);
  const Eigen::MatrixXd Q = orthonormal(model);
  const Eigen::VectorXd lin = g.cwiseProduct(t);
  auto data = [&](double rate, double amplitude, double tau) {
    Eigen::VectorXd r(m);
    for (int i = 0; i < m; ++i) r[i] = g[i] * (rate * t[i] + amplitude * (1.0 - std::exp(-t[i] / tau))) + noise(rng);
    return r;
  };
  SECTION("exponential warm-up") {
    const DriftScreen s = screen_drift("drift:Z:t", Q, lin, data(0.0, 0.012, 300.0), t, 1198.0, 1e-3, 1e-3);
    REQUIRE_FALSE(s.aliased);
    CHECK(s.parameters == std::vector<std::string>{"drift:Z:t:exp"});
    CHECK(*s.held.get("drift:Z:t:tau") == Approx(300.0).epsilon(0.1));
  }
  SECTION("linear") {
    const DriftScreen s = screen_drift("drift:Z:t", Q, lin, data(1e-5, 0.0, 300.0), t, 1198.0, 1e-3, 1e-3);
    REQUIRE_FALSE(s.aliased);
    CHECK(s.parameters.front() == "drift:Z:t:lin");
  }
  SECTION("both") {
    const DriftScreen s = screen_drift("drift:Z:t", Q, lin, data(1e-5, 0.012, 150.0), t, 1198.0, 1e-3, 1e-3);
    REQUIRE_FALSE(s.aliased);
    CHECK(s.parameters == std::vector<std::string>{"drift:Z:t:lin", "drift:Z:t:exp"});
    CHECK(*s.held.get("drift:Z:t:tau") == Approx(150.0).epsilon(0.15));
  }
  SECTION("no time stamps: aliased") {
    const DriftScreen s = screen_drift("drift:Z:t", Q, Eigen::VectorXd::Zero(m), data(0, 0, 1),
                                       Eigen::VectorXd::Zero(m), 60.0, 1e-3, 1e-3);
    CHECK(s.aliased);
  }
}
