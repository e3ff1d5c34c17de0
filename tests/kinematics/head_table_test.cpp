// SPDX-License-Identifier: Apache-2.0
// The head-table machine files (machines/head-table-bc.toml, machines/nutating-head-bc.toml): the
// product's inverse kinematics checked against the tests' own forward kinematics
// (tests/support/nc_executor.hpp, its own reading of the machine file), and the nutating head's
// tool axis against a hand computation (Rodrigues' formula about d = (0, 1, 1)/√2):
//   B = 180: e_z ↦ 2 (d·e_z) d − e_z = (0, 1, 0), the spindle horizontal along +Y;
//   B = 90:  e_z ↦ (d·e_z) d + d × e_z = (0, 1/2, 1/2) + (1/√2, 0, 0), 60° from +Z.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "nc_executor.hpp"
#include "ncpost/kinematics/forward.hpp"
#include "ncpost/kinematics/inverse.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "test_paths.hpp"

using namespace ncpost;

namespace {

constexpr const char* kHeadTable[] = {"head-table-bc", "nutating-head-bc"};

test::ExecPose independent(const test::ExecMachine& m, const Setup& s, const AxisPosition& q, const Machine& product) {
  test::ExecJob job;
  job.workpiece_origin_mm = s.workpiece_origin_mm;
  job.tool_length_mm = s.tool_length_mm;
  std::map<char, double> deg;
  for (int k = 0; k < product.rotary_count(); ++k) deg[product.rotary(k).letter] = q.rotary_rad[k] * 180.0 / M_PI;
  return test::forward(m, job, q.linear_mm, deg);
}

}  // namespace

TEST_CASE("head-table machines: the inverse kinematics reaches the CL point by the tests' own forward kinematics") {
  for (const char* name : kHeadTable) {
    INFO(name);
    const std::string path = test::source(std::string("machines/") + name + ".toml");
    const Machine m = load_machine(path);
    const test::ExecMachine exec = test::ExecMachine::load(path);
    REQUIRE(m.rotary_count() == 2);
    Setup setup;
    setup.workpiece_origin_mm = Vec3d(20.0, -15.0, -350.0);
    setup.tool_length_mm = 110.0;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int checked = 0;
    for (int n = 0; n < 2000; ++n) {
      AxisPosition truth = AxisPosition::zero(2);
      for (int i = 0; i < 3; ++i) truth.linear_mm[i] = -200.0 + 400.0 * unit(rng);
      const auto& lb = m.rotary(0).limits;  // B
      truth.rotary_rad[0] = lb->min + (lb->max - lb->min) * unit(rng);
      truth.rotary_rad[1] = -M_PI + 2 * M_PI * unit(rng);  // C
      const test::ExecPose cl = independent(exec, setup, truth, m);
      const IkOutcome ik = solve(m, {cl.tip_W, cl.axis_W}, setup, truth);
      if (!ik.ok()) continue;  // the other branch beyond a linear limit
      const test::ExecPose back = independent(exec, setup, *ik.position, m);
      CHECK((back.tip_W - cl.tip_W).norm() < 1e-9);
      CHECK((back.axis_W - cl.axis_W).norm() < 1e-9);
      ++checked;
    }
    CHECK(checked > 1900);
  }
}

TEST_CASE("nutating head: B = 180 turns the spindle to +Y, B = 90 to 60 degrees from +Z (by hand)") {
  const std::string path = test::source("machines/nutating-head-bc.toml");
  const Machine m = load_machine(path);
  const test::ExecMachine exec = test::ExecMachine::load(path);
  Setup setup;
  setup.tool_length_mm = 100.0;
  AxisPosition q = AxisPosition::zero(2);
  q.rotary_rad[0] = M_PI;
  CHECK((forward(m, q, setup).axis - Vec3d(0, 1, 0)).norm() < 1e-12);
  CHECK((independent(exec, setup, q, m).axis_W - Vec3d(0, 1, 0)).norm() < 1e-12);
  q.rotary_rad[0] = M_PI / 2;
  const Vec3d at_90(std::sqrt(0.5), 0.5, 0.5);
  CHECK((forward(m, q, setup).axis - at_90).norm() < 1e-12);
  CHECK((independent(exec, setup, q, m).axis_W - at_90).norm() < 1e-12);
  // the C table turns the tool axis seen from the workpiece: at C = 90 the W axis is Rz(-90) of it
  q.rotary_rad[1] = M_PI / 2;
  CHECK((forward(m, q, setup).axis - Vec3d(0.5, -std::sqrt(0.5), 0.5)).norm() < 1e-12);
}
