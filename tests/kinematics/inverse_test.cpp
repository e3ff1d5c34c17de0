// SPDX-License-Identifier: Apache-2.0
// Property tests of the closed-form inverse kinematics over every shipped machine:
// forward(inverse(x)) = x on thousands of random reachable poses, and the chosen solution
// respects the limits and is the one nearest the previous pose.
#include <catch2/catch.hpp>

#include <random>

#include "ncpost/kinematics/forward.hpp"
#include "ncpost/kinematics/inverse.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "test_paths.hpp"

using namespace ncpost;

namespace {

double draw(std::mt19937& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }

AxisPosition random_pose(const Machine& m, std::mt19937& rng) {
  AxisPosition q = home_of(m);
  for (int i = 0; i < 3; ++i) {
    const auto& l = m.axes[static_cast<std::size_t>(i)].limits;
    q.linear_mm[i] = l ? draw(rng, l->min, l->max) : draw(rng, -300, 300);
  }
  for (int k = 0; k < m.rotary_count(); ++k) {
    const auto& l = m.rotary(k).limits;
    q.rotary_rad[k] = l ? draw(rng, l->min, l->max) : draw(rng, -2 * kPi, 2 * kPi);
  }
  return q;
}

}  // namespace

TEST_CASE("forward(inverse(x)) = x on random reachable poses of every shipped machine") {
  for (const char* name : test::kShippedMachines) {
    INFO(name);
    const Machine m = load_machine(test::source(std::string("machines/") + name + ".toml"));
    std::mt19937 rng(42);
    Setup setup;
    setup.workpiece_origin_mm = Vec3d(12.0, -7.0, 35.0);
    setup.tool_length_mm = 120.0;
    int checked = 0;
    double worst_tip = 0.0, worst_axis = 0.0;
    for (int n = 0; n < 3000; ++n) {
      const AxisPosition truth = random_pose(m, rng);
      const ToolPoseT<double> cl = forward(m, truth, setup);
      // a previous pose near the truth, as along a tool path
      AxisPosition previous = truth;
      previous.rotary_rad += Eigen::Vector2d(draw(rng, -0.05, 0.05), draw(rng, -0.05, 0.05)).head(m.rotary_count());
      const IkOutcome ik = solve(m, {cl.tip_mm, cl.axis}, setup, previous);
      if (!ik.ok()) continue;  // linear limits may exclude the other solution only
      const ToolPoseT<double> back = forward(m, *ik.position, setup);
      worst_tip = std::max(worst_tip, (back.tip_mm - cl.tip_mm).norm());
      worst_axis = std::max(worst_axis, std::atan2(back.axis.cross(cl.axis).norm(), back.axis.dot(cl.axis)));
      for (int k = 0; k < m.rotary_count(); ++k)
        if (m.rotary(k).limits) CHECK(m.rotary(k).limits->contains(ik.position->rotary_rad[k]));
      // the truth is itself a solution, so the chosen one moves the rotary axes no more than it
      const double chosen = (ik.position->rotary_rad - previous.rotary_rad).cwiseAbs().sum();
      const double true_cost = (truth.rotary_rad - previous.rotary_rad).cwiseAbs().sum();
      CHECK(chosen <= true_cost + 1e-9);
      ++checked;
    }
    CHECK(checked > 2500);
    CHECK(worst_tip < 1e-9);
    CHECK(worst_axis < 1e-9);
  }
}

TEST_CASE("both rotary solutions of an AC table reach the same CL point") {
  const Machine m = load_machine(test::source("machines/ac-trunnion.toml"));
  const Vec3d u = Vec3d(0.3, -0.2, 0.9).normalized();
  const auto sols = rotary_solutions(m, u);
  REQUIRE(sols.size() == 2);
  CHECK(std::abs(std::abs(sols[0].rotary_rad[0]) - std::abs(sols[1].rotary_rad[0])) < 1e-12);  // A and -A
  for (const auto& s : sols) {
    AxisPosition q = home_of(m);
    q.rotary_rad = s.rotary_rad;
    q.linear_mm = linear_for(m, s.rotary_rad, Vec3d(10, 20, 30), {});
    const auto pose = forward(m, q, {});
    CHECK((pose.axis - u).norm() < 1e-12);
    CHECK((pose.tip_mm - Vec3d(10, 20, 30)).norm() < 1e-9);
  }
}

TEST_CASE("at the singular orientation the free angle keeps its previous value") {
  const Machine m = load_machine(test::source("machines/ac-trunnion.toml"));
  AxisPosition previous = home_of(m);
  previous.rotary_rad = Eigen::Vector2d(0.3, 1.234);  // A, C
  const IkOutcome ik = solve(m, {Vec3d(5, 6, 7), Vec3d::UnitZ()}, {}, previous);
  REQUIRE(ik.ok());
  CHECK(ik.singular);
  CHECK(ik.position->rotary_rad[1] == Approx(1.234).margin(1e-12));
  CHECK(ik.position->rotary_rad[0] == Approx(0.0).margin(1e-12));
}

TEST_CASE("continuous axes unwind toward the previous angle; limited axes do not") {
  const Machine m = load_machine(test::source("machines/ac-trunnion.toml"));
  AxisPosition previous = home_of(m);
  previous.rotary_rad = Eigen::Vector2d(0.5, deg_to_rad(710.0));
  const Vec3d u = Vec3d(std::sin(0.5) * std::sin(deg_to_rad(-10.0)), 0.0, 0.0);
  AxisPosition truth = home_of(m);
  truth.rotary_rad = Eigen::Vector2d(0.5, deg_to_rad(-10.0 + 720.0));
  const auto cl = forward(m, truth, {});
  const IkOutcome ik = solve(m, {cl.tip_mm, cl.axis}, {}, previous);
  REQUIRE(ik.ok());
  CHECK(rad_to_deg(ik.position->rotary_rad[1]) == Approx(710.0).margin(1e-9));
  CHECK(ik.position->rotary_rad[0] == Approx(0.5).margin(1e-12));
  (void)u;
}

TEST_CASE("an orientation beyond the tilt limit has no solution, and says why") {
  const Machine m = load_machine(test::source("machines/tsutsumi-zxfyac.toml"));  // A in [-30, 120]
  // tilt of 150 deg is out of reach for any sign of A
  const Vec3d u(0.0, std::sin(deg_to_rad(150.0)), std::cos(deg_to_rad(150.0)));
  const IkOutcome ik = solve(m, {Vec3d::Zero(), u}, {}, {});
  CHECK_FALSE(ik.ok());
  CHECK(ik.failure.message.find("limits") != std::string::npos);
}

TEST_CASE("a three-axis machine solves only the vertical tool axis") {
  const Machine m = load_machine(test::source("machines/vmcl600.toml"));
  const IkOutcome ok = solve(m, {Vec3d(1, 2, 3), Vec3d::UnitZ()}, {Vec3d(0, 0, 10), 0.0}, {});
  REQUIRE(ok.ok());
  CHECK((ok.position->linear_mm - Vec3d(1, 2, 13)).norm() < 1e-12);
  CHECK_FALSE(solve(m, {Vec3d(1, 2, 3), Vec3d(0, 0.1, 1).normalized()}, {}, {}).ok());
}
