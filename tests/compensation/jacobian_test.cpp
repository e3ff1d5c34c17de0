// SPDX-License-Identifier: Apache-2.0
// The Jacobian of the residuals agrees with central finite differences, and with forward-mode
// automatic differentiation (Eigen's AutoDiffScalar, computed here) to 1e-9, for every kind of
// parameter and every kind of measurement.
#include <catch2/catch.hpp>

#include <cmath>
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include "ncpost/compensation/plans.hpp"
#include "ncpost/compensation/prediction.hpp"
#include "ncpost/compensation/residuals.hpp"
#include "ncpost/compensation/simulate.hpp"
#include "ncpost/machines/machine_file.hpp"

using namespace ncpost;
using namespace ncpost::comp;

namespace {

MeasurementSet laser_run(const Machine& m) {
  MeasurementSet s;
  s.type = MeasurementType::laser;
  s.component = 'X';
  s.tool_point_mm = Vec3d(10, 20, 30);
  s.tool_length_mm = 50;
  for (int k = 0; k < 21; ++k) {
    MeasurementRow r;
    r.time_s = 2.0 * k;
    r.run = k < 11 ? 1 : 2;
    const double x = k < 11 ? -200 + 40 * k : 200 - 40 * (k - 10);
    r.command.linear_mm = Vec3d(x, 30, -40);
    r.command.rotary_rad = Eigen::Vector2d(0.3, 1.1);
    s.rows.push_back(r);
  }
  (void)m;
  return s;
}

Machine trunnion() { return load_machine(std::string(NCPOST_SOURCE_DIR) + "/machines/ac-trunnion.toml"); }

/// A value for a parameter of every kind but tables and coupled terms.
ErrorParameters every_kind() {
  ErrorParameters p;
  const std::vector<std::pair<std::string, double>> values = {{"EY0A", 0.018},
                                                              {"EZ0A", -0.012},
                                                              {"EB0A", 4e-5},
                                                              {"EC0A", -2.5e-5},
                                                              {"EX0C", 0.015},
                                                              {"EY0C", -0.022},
                                                              {"EA0C", 3e-5},
                                                              {"EB0C", -3.5e-5},
                                                              {"EA0A", 1e-5},
                                                              {"EC0C", 2e-5},
                                                              {"EC0Y", 2e-5},
                                                              {"EB0Z", -1e-5},
                                                              {"EA0Z", 3e-5},
                                                              {"ECC:h2:cos", 4e-5},
                                                              {"ECC:h2:sin", -3e-5},
                                                              {"EZC:h1:cos", 0.008},
                                                              {"EXA:h3:sin", 0.002},
                                                              {"EXX:p1", 2e-5},
                                                              {"EZX:p2", 1e-7},
                                                              {"EBY:p1", 1e-7},
                                                              {"reversal:A", 3e-5},
                                                              {"reversal:C", -2e-5},
                                                              {"drift:Z:t:lin", 1e-6},
                                                              {"drift:X:t:exp", 0.004},
                                                              {"drift:X:t:tau", 400},
                                                              {"ballbar:length", 0.002},
                                                              {"sphere:position:y", 0.003}};
  for (const auto& [n, v] : values) p.set(n, v);
  return p;
}

/// A ballbar circle, sphere probing and a laser run of two runs, valued on the nominal machine.
std::vector<MeasurementSet> every_measurement(const Machine& m) {
  std::vector<MeasurementSet> sets;
  BallbarPlanOptions bo;
  bo.heights_mm = {250};
  bo.points = 60;
  sets.push_back(plan_ballbar_4axis(m, bo)[0].set);
  SpherePlanOptions so;
  so.levels_deg = {0, 45, 90};
  so.step_deg = 60;
  sets.push_back(plan_sphere(m, so)[0].set);
  sets.push_back(laser_run(m));
  for (auto& s : sets) s = simulate(m, s, ErrorParameters{}, {});  // values: the nominal machine

  return sets;
}

}  // namespace

TEST_CASE("AD Jacobian matches finite differences") {
  const Machine m = trunnion();
  const ErrorParameters p = every_kind();
  const std::vector<MeasurementSet> sets = every_measurement(m);

  ResidualProblem prob{&m, &sets, ModelLayout(m, p.names())};
  const std::vector<double> x = p.values();
  std::vector<int> cols(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) cols[i] = static_cast<int>(i);
  const Eigen::MatrixXd J = prob.jacobian(x, cols);
  REQUIRE(J.rows() == prob.residual_count());
  for (std::size_t c = 0; c < x.size(); ++c) {
    const double h = std::max(1e-7, 1e-4 * std::abs(x[c]));
    std::vector<double> xp = x, xm = x;
    xp[c] += h;
    xm[c] -= h;
    const Eigen::VectorXd fd = (prob.residuals(xp) - prob.residuals(xm)) / (2.0 * h);
    const double scale = std::max(1e-9, fd.cwiseAbs().maxCoeff());
    const double diff = (J.col(static_cast<Eigen::Index>(c)) - fd).cwiseAbs().maxCoeff();
    INFO(p.names()[c] << ": max |AD - FD| = " << diff << " of " << scale);
    CHECK(diff <= 1e-5 * scale + 2e-6);  // FD rounding: ~1e-13 mm / 1e-7
  }
}

namespace {

/// d predictions / d parameters by forward-mode automatic differentiation, all columns at once.
Eigen::MatrixXd forward_mode_jacobian(const Machine& m, const std::vector<MeasurementSet>& sets,
                                      const ModelLayout& layout, const std::vector<double>& x) {
  using Jet = Eigen::AutoDiffScalar<Eigen::VectorXd>;
  const Eigen::Index n = static_cast<Eigen::Index>(x.size());
  std::vector<Jet> jets;
  for (Eigen::Index i = 0; i < n; ++i) jets.emplace_back(x[static_cast<std::size_t>(i)], n, i);
  std::vector<Eigen::RowVectorXd> rows;
  for (const auto& s : sets)
    for (const Jet& v : predict_set<Jet>(m, s, layout, jets.data())) {
      Eigen::RowVectorXd d = Eigen::RowVectorXd::Zero(n);
      if (v.derivatives().size() == n) d = v.derivatives().transpose();
      rows.push_back(value_unit_mm(s) * d);  // laser µm -> mm, as the residuals
    }
  Eigen::MatrixXd J(static_cast<Eigen::Index>(rows.size()), n);
  for (std::size_t r = 0; r < rows.size(); ++r) J.row(static_cast<Eigen::Index>(r)) = rows[r];
  return J;
}

}  // namespace

TEST_CASE("Reverse-mode Jacobian equals forward-mode automatic differentiation to 1e-9", "[jacobian]") {
  const Machine m = trunnion();
  ErrorParameters p = every_kind();
  // tables of a linear and of a rotary axis, a coupled location term
  for (const auto& [n, v] : std::vector<std::pair<std::string, double>>{{"EYX:t:-200", 0.003},
                                                                        {"EYX:t:0", -0.002},
                                                                        {"EYX:t:150", 0.004},
                                                                        {"ECC:t:0", 2e-5},
                                                                        {"ECC:t:120", -1e-5},
                                                                        {"ECC:t:240", 3e-5},
                                                                        {"EA0C:A:p1", 2e-5}})
    p.set(n, v);
  const std::vector<MeasurementSet> sets = every_measurement(m);
  ResidualProblem prob{&m, &sets, ModelLayout(m, p.names())};
  const std::vector<double> x = p.values();
  const Eigen::MatrixXd reference = forward_mode_jacobian(m, sets, prob.layout, x);
  // every column, in a shuffled order with a repeat; then a few columns only (the others constant)
  std::vector<int> all(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) all[i] = static_cast<int>(x.size() - 1 - i);
  all.push_back(3);
  const std::vector<std::vector<int>> choices{all, {0, 13, static_cast<int>(x.size()) - 1}};
  for (const auto& cols : choices) {
    const Eigen::MatrixXd J = prob.jacobian(x, cols);
    REQUIRE(J.rows() == reference.rows());
    REQUIRE(J.cols() == static_cast<Eigen::Index>(cols.size()));
    for (std::size_t j = 0; j < cols.size(); ++j) {
      const Eigen::VectorXd ref = reference.col(cols[j]);
      const double diff = (J.col(static_cast<Eigen::Index>(j)) - ref).cwiseAbs().maxCoeff();
      INFO(p.names()[static_cast<std::size_t>(cols[j])] << ": max |reverse - forward| = " << diff << " of "
                                                        << ref.cwiseAbs().maxCoeff());
      CHECK(ref.cwiseAbs().maxCoeff() > 0.0);  // every parameter acts on these data
      CHECK(diff <= 1e-9 * ref.cwiseAbs().maxCoeff());
    }
  }
}
