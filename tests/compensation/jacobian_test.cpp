// SPDX-License-Identifier: Apache-2.0
// The automatic-differentiation Jacobian of the residuals agrees with central finite
// differences for every kind of parameter and every kind of measurement.
#include <catch2/catch.hpp>

#include <cmath>

#include "ncpost/compensation/plans.hpp"
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

}  // namespace

TEST_CASE("AD Jacobian matches finite differences") {
  const Machine m = load_machine(std::string(NCPOST_SOURCE_DIR) + "/machines/ac-trunnion.toml");
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
