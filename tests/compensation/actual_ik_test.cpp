// SPDX-License-Identifier: Apache-2.0
// Compensated inverse kinematics: the actual forward kinematics of the solution hits the CL
// point (1e-6 mm, 1e-8 rad) on an AC table, at the singular orientation, with reversal, and on a
// BC head.
#include <catch2/catch.hpp>

#include <cmath>

#include "ncpost/compensation/actual_ik.hpp"
#include "ncpost/compensation/model_json.hpp"
#include "ncpost/kinematics/inverse.hpp"
#include "ncpost/machines/machine_file.hpp"

using namespace ncpost;
using namespace ncpost::comp;

namespace {

/// Checks the solution; returns how far the nominal commands miss on the actual machine (mm).
double check_hits(const MachineModel& model, const ClPoint& cl, const Setup& setup, const ActualIkOptions& o = {}) {
  const IkOutcome nominal = solve(model.machine(), cl, setup, AxisPosition{});
  REQUIRE(nominal.ok());
  const ActualIkOutcome r = solve_actual(model, cl, setup, *nominal.position, o);
  INFO(r.message);
  REQUIRE(r.ok());
  const ToolPoseT<double> p =
      model.tool_pose(*r.position, setup, reversal_state(model, *r.position, o.previous_actual));
  CHECK((p.tip_mm - cl.tip_mm).norm() <= 1e-6);
  CHECK(std::atan2(p.axis.cross(cl.axis).norm(), p.axis.dot(cl.axis)) <= 1e-8);
  const ToolPoseT<double> miss = model.tool_pose(*nominal.position, setup);
  return (miss.tip_mm - cl.tip_mm).norm();
}

}  // namespace

TEST_CASE("solve_actual on the public-clean truth") {
  const std::string dir = std::string(NCPOST_SOURCE_DIR) + "/tests/data/scenarios/public-clean/";
  const Machine m = load_machine(dir + "machine.toml");
  const ModelFile truth = read_model_json(dir + "truth.json", &m);
  const MachineModel model(m, truth.parameters);
  Setup setup;
  setup.workpiece_origin_mm = Vec3d(0, 0, 80);
  unsigned s = 99u;
  auto uniform = [&s](double lo, double hi) {
    s = s * 1664525u + 1013904223u;
    return lo + (hi - lo) * double(s >> 8) / double(1u << 24);
  };
  double largest_miss = 0.0;
  for (int k = 0; k < 200; ++k) {
    ClPoint cl;
    cl.tip_mm = Vec3d(uniform(-100, 100), uniform(-100, 100), uniform(0, 60));
    const double tilt = deg_to_rad(uniform(5, 80)), turn = deg_to_rad(uniform(-180, 180));
    cl.axis = Vec3d(std::sin(tilt) * std::cos(turn), std::sin(tilt) * std::sin(turn), std::cos(tilt));
    largest_miss = std::max(largest_miss, check_hits(model, cl, setup));
  }
  CHECK(largest_miss > 0.03);  // the compensation is not trivial
  SECTION("singular orientation: tool axis along C") {
    ClPoint cl;
    cl.tip_mm = Vec3d(30, -20, 10);
    check_hits(model, cl, setup);
  }
}

TEST_CASE("solve_actual with reversal follows the direction of the command") {
  const Machine m = load_machine(std::string(NCPOST_SOURCE_DIR) + "/machines/ac-trunnion.toml");
  ErrorParameters p;
  p.set("EY0C", -0.02);
  p.set("EB0A", 4e-5);
  p.set("reversal:A", 5e-5);
  p.set("reversal:Y", 0.004);
  const MachineModel model(m, p);
  Setup setup;
  ClPoint cl;
  cl.tip_mm = Vec3d(20, 30, 5);
  cl.axis = Vec3d(0, -std::sin(0.5), std::cos(0.5)).normalized();
  ActualIkOptions from_above;
  AxisPosition high = home_of(m);
  high.linear_mm = Vec3d(0, 400, 0);
  high.rotary_rad = Eigen::Vector2d(1.5, 0.0);
  from_above.previous_actual = high;
  check_hits(model, cl, setup, from_above);
  ActualIkOptions from_below;
  AxisPosition low = home_of(m);
  low.linear_mm = Vec3d(0, -400, 0);
  low.rotary_rad = Eigen::Vector2d(-1.0, 0.0);
  from_below.previous_actual = low;
  check_hits(model, cl, setup, from_below);
  const IkOutcome nominal = solve(m, cl, setup, AxisPosition{});
  const auto a = solve_actual(model, cl, setup, *nominal.position, from_above);
  const auto b = solve_actual(model, cl, setup, *nominal.position, from_below);
  // approached from above the axes stand at command + b: the commands differ by the play
  CHECK(std::abs((b.position->rotary_rad[0] - a.position->rotary_rad[0]) - 5e-5) < 1e-6);
  CHECK(std::abs((b.position->linear_mm[1] - a.position->linear_mm[1]) - 0.004) < 1e-4);
}

TEST_CASE("solve_actual on a BC head") {
  const Machine m = load_machine(std::string(NCPOST_SOURCE_DIR) + "/machines/gantry-bc-head.toml");
  ErrorParameters p;
  for (const auto& [n, v] : std::vector<std::pair<std::string, double>>{{"EX0C", 0.01},
                                                                        {"EY0C", -0.015},
                                                                        {"EA0C", 2e-5},
                                                                        {"EB0C", -3e-5},
                                                                        {"EX0B", 0.02},
                                                                        {"EZ0B", -0.01},
                                                                        {"EA0B", 4e-5},
                                                                        {"EC0B", 2e-5},
                                                                        {"EB0B", 1e-5}})
    p.set(n, v);
  const MachineModel model(m, p);
  Setup setup;
  setup.tool_length_mm = 150;
  for (double tilt : {0.2, 0.6, 1.0})
    for (double turn : {-2.0, 0.3, 1.7}) {
      ClPoint cl;
      cl.tip_mm = Vec3d(100 * std::cos(turn), 50, -30);
      cl.axis = Vec3d(std::sin(tilt) * std::cos(turn), std::sin(tilt) * std::sin(turn), std::cos(tilt));
      check_hits(model, cl, setup);
    }
}
