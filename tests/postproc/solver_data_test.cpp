// SPDX-License-Identifier: Apache-2.0
// Solvers are immutable and keep their working state in the SolverData the caller passes (issue
// 16 item 1): the same solver object solves on two threads at once, each thread with its own data,
// and gives what one thread gives, bit for bit; solving through a const reference twice with
// fresh data gives the same commands, figures and poses. The nominal chain, the chain with an
// error model (ActualSolver) and the TRR-XY machine (TrrSolver).
#include <catch2/catch.hpp>

#include <fstream>
#include <thread>
#include <variant>
#include <vector>

#include "ncpost/compensation/model_json.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/machines/trr_xy_file.hpp"
#include "ncpost/postproc/solve/actual_solver.hpp"
#include "ncpost/postproc/read/apt/apt_reader.hpp"
#include "ncpost/postproc/solve/trr_solver.hpp"
#include "test_paths.hpp"

using namespace ncpost;

namespace {

/// The first `limit` CL points of an APT file.
std::vector<ClPoint> cl_points(const std::string& path, std::size_t limit) {
  std::ifstream in(path);
  REQUIRE(in);
  cl::AptReader reader(in, path);
  std::vector<ClPoint> points;
  while (auto r = reader.next()) {
    if (const auto* m = std::get_if<cl::Motion>(&*r)) points.push_back(m->point);
    if (points.size() == limit) break;
  }
  return points;
}

/// What a run of the solver along the points gives: each point's commands (from the previous
/// point's, as the post chains them), the pose they execute to, and the figures recorded.
struct Run {
  std::vector<AxisPosition> commands;
  std::vector<ToolPoseT<double>> poses;
  SolverData data;
};

Run run(const KinematicModel& solver, const std::vector<ClPoint>& points) {
  Run r;
  AxisPosition previous{};
  for (const ClPoint& p : points) {
    const IkOutcome ik = solver.solve(p, previous, r.data);
    REQUIRE(ik.ok());
    previous = *ik.position;
    r.commands.push_back(previous);
    r.poses.push_back(solver.execute(previous, r.data));
    post_hooks_of(solver).advance(previous, r.data);
  }
  return r;
}

bool same(const AxisPosition& a, const AxisPosition& b) { return a == b; }

/// Bit-for-bit equal commands, poses and figures.
void require_same(const Run& a, const Run& b) {
  REQUIRE(a.commands.size() == b.commands.size());
  for (std::size_t i = 0; i < a.commands.size(); ++i) {
    INFO("point " << i);
    REQUIRE(same(a.commands[i], b.commands[i]));
    REQUIRE(a.poses[i].tip_mm == b.poses[i].tip_mm);
    REQUIRE(a.poses[i].axis == b.poses[i].axis);
  }
  CHECK(a.data.uncompensated.count == b.data.uncompensated.count);
  CHECK(a.data.uncompensated.max_mm == b.data.uncompensated.max_mm);
  CHECK(a.data.uncompensated.sum_sq_mm2 == b.data.uncompensated.sum_sq_mm2);
  CHECK(a.data.max_residual_mm == b.data.max_residual_mm);
}

/// The solver on one thread, then on two threads at once (each its own data): all three agree.
void check_two_threads(const KinematicModel& solver, const std::vector<ClPoint>& points) {
  const Run one = run(solver, points);
  Run first, second;
  std::thread a([&] { first = run(solver, points); });
  std::thread b([&] { second = run(solver, points); });
  a.join();
  b.join();
  require_same(first, one);
  require_same(second, one);
  // figures of the workers merged by the caller: both threads' points counted
  SolverData merged;
  merged.merge_figures(first.data);
  merged.merge_figures(second.data);
  CHECK(merged.uncompensated.count == 2 * one.data.uncompensated.count);
  CHECK(merged.uncompensated.max_mm == one.data.uncompensated.max_mm);
  CHECK(merged.max_residual_mm == one.data.max_residual_mm);
}

struct PublicClean {
  Machine machine = load_machine(test::data("scenarios/public-clean/machine.toml"));
  Setup setup{Vec3d(0, 0, 80), 0.0};
  std::vector<ClPoint> points = cl_points(test::data("scenarios/public-clean/path.cls"), 400);
  comp::ErrorParameters truth() const {
    return comp::read_model_json(test::data("scenarios/public-clean/truth.json"), &machine).parameters;
  }
};

}  // namespace

TEST_CASE("solver data: the nominal chain solves on two threads as on one", "[solver][threads]") {
  const PublicClean job;
  REQUIRE(job.points.size() == 400);
  check_two_threads(NominalSolver(job.machine, job.setup), job.points);
}

TEST_CASE("solver data: the chain with an error model solves on two threads as on one", "[solver][threads]") {
  const PublicClean job;
  const comp::MachineModel model(job.machine, job.truth());
  const ActualSolver solver(model, job.setup);
  REQUIRE(solver.concurrent());
  const Run one = run(solver, job.points);
  CHECK(one.data.uncompensated.count == job.points.size());  // every point measured once
  CHECK(one.data.uncompensated.max_mm > 0.01);               // the truth's errors: tens of µm
  CHECK(one.data.max_residual_mm < ActualSolver::kPostTipToleranceMm);
  check_two_threads(solver, job.points);
}

TEST_CASE("solver data: a model with reversal keeps where the axes stand in the data", "[solver][threads]") {
  const PublicClean job;
  comp::ErrorParameters p = job.truth();
  p.set("reversal:C", 5e-5);
  const comp::MachineModel model(job.machine, p);
  const ActualSolver solver(model, job.setup);
  REQUIRE_FALSE(solver.concurrent());
  // each thread follows its own program: the reversal state is the data's, not the solver's
  check_two_threads(solver, job.points);
  const Run one = run(solver, job.points);
  REQUIRE(one.data.stands.has_value());       // the data followed the program
  const Run again = run(solver, job.points);  // fresh data: the same program, not one that continues
  require_same(again, one);
}

TEST_CASE("solver data: the TRR-XY machine solves on two threads as on one", "[solver][threads][trr]") {
  const trr::Kinematics k(load_trr_xy_machine(test::source("machines/trr-xy.toml")));
  const TrrSolver solver(k, k, Vec3d(0.0, 0.0, -300.0));
  const std::vector<ClPoint> points = cl_points(test::source("samples/hemisphere_5axis.cls"), 200);
  REQUIRE(points.size() == 200);
  check_two_threads(solver, points);
}

TEST_CASE("solver data: solving through a const reference twice with fresh data gives the same", "[solver][const]") {
  const PublicClean job;
  const comp::MachineModel model(job.machine, job.truth());
  const ActualSolver actual(model, job.setup);
  const NominalSolver nominal(job.machine, job.setup);
  for (const KinematicModel* s :
       {static_cast<const KinematicModel*>(&nominal), static_cast<const KinematicModel*>(&actual)}) {
    const KinematicModel& solver = *s;
    const Run first = run(solver, job.points);
    const Run again = run(solver, job.points);
    require_same(again, first);
    // a used data object does not leak into a fresh one: the same single solve from scratch
    SolverData fresh_a, fresh_b;
    const IkOutcome a = solver.solve(job.points.back(), AxisPosition{}, fresh_a);
    const IkOutcome b = solver.solve(job.points.back(), AxisPosition{}, fresh_b);
    REQUIRE(a.ok());
    REQUIRE(b.ok());
    CHECK(same(*a.position, *b.position));
  }
  // the compensated commands differ from the nominal ones (the model is in use)
  const Run n = run(nominal, job.points);
  const Run c = run(actual, job.points);
  CHECK((n.commands.back().linear_mm - c.commands.back().linear_mm).norm() > 1e-3);
}
