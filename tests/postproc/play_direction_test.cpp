// SPDX-License-Identifier: Apache-2.0
// Play take-up inside compensated blocks (play_subdivision.hpp, issue 17): the axes stand at the
// written, rounded commands, so an axis that barely moves over a block (Y along a 50 mm X move of
// the VMCL600, a few µm of compensation, rising) can see its first targets a fraction of a word
// step below where it stands. That is rounding, not a way: its play must not be taken up toward
// the falling edge (the command 3 µm down, then the whole play crossed while the tool moves).
#include <catch2/catch.hpp>

#include "ncpost/compensation/model_json.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/solve/actual_solver.hpp"
#include "ncpost/postproc/solve/play_subdivision.hpp"
#include "test_paths.hpp"

using namespace ncpost;

TEST_CASE("play take-up: a move within one word step of where the axis stands shows no way", "[reversal][play]") {
  const Machine m = load_machine(test::source("machines/vmcl600.toml"));
  const comp::MachineModel model(
      m, comp::read_model_json(test::source("samples/measurements/vmcl600/model.json"), &m).parameters);
  REQUIRE(model.has_reversal());
  Setup setup;
  setup.workpiece_origin_mm = Vec3d(0, 0, -450);
  setup.tool_length_mm = 150;
  const ActualSolver actual(model, setup);
  SolverData data;  // where the axes stand, as the post follows them
  ClPoint a, b;
  a.tip_mm = Vec3d(150, 175, 0);
  b.tip_mm = Vec3d(100, 175, 0);
  // X and Y came rising to the start (actual = command); the program wrote Y rounded up by 0.04 µm
  const IkOutcome start = actual.solve_quiet(a, AxisPosition{}, data, nullptr);
  REQUIRE(start.ok());
  const AxisPosition q0 = *start.position;
  AxisPosition below = q0;
  below.linear_mm -= Vec3d(1, 1, 1);
  actual.advance(below, data);
  AxisPosition written = q0;
  written.linear_mm.y() += 4e-5;
  actual.advance(written, data);
  const IkOutcome end = actual.solve_quiet(b, q0, data, nullptr);
  REQUIRE(end.ok());
  const double rise_mm = end.position->linear_mm.y() - q0.linear_mm.y();
  REQUIRE(rise_mm > 1e-3);  // Y rises by a few µm over the block (the compensation)
  nonlinear::CompensationOptions options;
  options.tolerance_mm = 0.002;
  std::string failure;
  const std::vector<SolvedPoint> points = subdivide_with_play(
      m, setup, actual, data, SolvedPoint{a, q0}, SolvedPoint{b, *end.position}, options, WordSteps{}, failure);
  INFO(failure);
  REQUIRE(!points.empty());
  // Y is never taken toward the falling edge of its play (3 µm below): it rises through the block
  double y = q0.linear_mm.y();
  for (const SolvedPoint& p : points) {
    CHECK(p.q.linear_mm.y() >= y - 1e-9);
    y = p.q.linear_mm.y();
  }
  // X falls over the block and was standing on its rising edge: its play is taken up (tool still)
  CHECK(points.front().cl.tip_mm == a.tip_mm);
  CHECK(points.front().q.linear_mm.x() < q0.linear_mm.x() - 3e-3);
  // with a word step finer than that rounding the 0.03 µm dip counts as a way, and Y is taken up
  // to its falling edge (what the rounded program did before)
  WordSteps fine;
  fine.linear_mm = 1e-6;
  const std::vector<SolvedPoint> fine_points = subdivide_with_play(
      m, setup, actual, data, SolvedPoint{a, q0}, SolvedPoint{b, *end.position}, options, fine, failure);
  REQUIRE(!fine_points.empty());
  CHECK(fine_points.front().q.linear_mm.y() < q0.linear_mm.y() - 2e-3);
}
