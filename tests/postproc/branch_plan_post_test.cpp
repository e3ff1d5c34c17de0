// SPDX-License-Identifier: Apache-2.0
// Branch planning in the post (PostOptions::branch_choice, branch_plan.hpp) on the gantry BC head
// (C within +-360 deg): a cone whose tool axis turns 500 deg about Z after a rapid, and the
// hemisphere sample's spiral. Planned, the rapid takes the solution that lets the cone run
// through (no change; greedy: one, or a failure with no retract allowed); on the spiral the plan
// has 2 changes where greedy has 10. One and two threads write the same planned program.
#include <catch2/catch.hpp>

#include <cmath>
#include <fmt/format.h>
#include <sstream>

#include "ncpost/machines/input_error.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/read/apt/apt_reader.hpp"
#include "ncpost/postproc/write/atomic_file.hpp"
#include "ncpost/postproc/write/dialect.hpp"
#include "ncpost/postproc/solve/motion_solver.hpp"
#include "ncpost/postproc/write/nc_writer.hpp"
#include "ncpost/postproc/post.hpp"
#include "temp_dir.hpp"
#include "test_paths.hpp"
#include "text_file.hpp"

using namespace ncpost;

namespace {

struct Posted {
  std::string program;
  PostSummary summary;
};

Posted post_bc(const std::string& cl, PostOptions::BranchChoice choice, int threads, double retract_mm) {
  static const std::string dir = test::make_temp_dir("branch_plan_post_test");
  const Machine m = load_machine(test::source("machines/gantry-bc-head.toml"));
  Setup setup;
  setup.workpiece_origin_mm = Vec3d(0, 0, -300);
  setup.tool_length_mm = 120;
  const NominalSolver solver(m, setup);
  PostOptions options;
  options.branch_choice = choice;
  options.threads = threads;
  options.retract_mm = retract_mm;
  options.verify = true;
  std::istringstream in(cl);
  cl::AptReader reader(in, "bc.cls");
  const std::string path = dir + "/bc.nc";
  Posted p;
  {
    AtomicFile out(path);
    NcWriter writer(out, dialect_named("fanuc"), "XYZBC");
    p.summary = post_program(reader, "bc.cls", solver, writer, options);
    out.commit();
  }
  p.program = test::read_text_file(path);
  return p;
}

/// A rapid, then feed motions on a cone: tip on a circle of radius 50 mm, tool axis tilted 30 deg
/// from Z towards the tip's azimuth, which runs from 0 to 500 deg in 5 deg steps.
std::string cone_500deg() {
  std::string cl = "PARTNO/CONE\nUNITS/MM\nMULTAX/ON\nLOADTL/1\nFEDRAT/MMPM,1000\nRAPID\n";
  const double tilt = 30.0 * kPi / 180.0;
  for (int deg = 0; deg <= 500; deg += 5) {
    const double a = deg * kPi / 180.0;
    cl += fmt::format("GOTO/{:.4f},{:.4f},0.0000,{:.6f},{:.6f},{:.6f}\n", 50 * std::cos(a), 50 * std::sin(a),
                      std::sin(tilt) * std::cos(a), std::sin(tilt) * std::sin(a), std::cos(tilt));
  }
  return cl + "END\n";
}

}  // namespace

TEST_CASE("branch plan in the post: the rapid takes the solution that avoids every retract", "[post][branch]") {
  const std::string cl = cone_500deg();
  using Choice = PostOptions::BranchChoice;
  const Posted greedy = post_bc(cl, Choice::greedy, 1, 40);
  CHECK(greedy.summary.retracts == 1);  // C reaches +360 deg at 360 deg of azimuth
  CHECK(greedy.summary.planned_runs == 0);
  const Posted planned = post_bc(cl, Choice::lookahead, 1, 40);
  CHECK(planned.summary.retracts == 0);
  CHECK(planned.summary.planned_runs == 1);
  // the rapid to the other branch (B -30, C -180: less travel than C -360), the cone runs up to C 320
  CHECK_THAT(greedy.program, Catch::Contains("B30.0000 C0.0000"));
  CHECK_THAT(planned.program, Catch::Contains("B-30.0000 C-180.0000"));
  CHECK_THAT(planned.program, Catch::Contains("C320.0000"));
  CHECK(planned.summary.verify.max_contour_mm < 1.0);  // no block swings through the part
  // no retract allowed: greedy fails at azimuth 365 deg (line 80), the plan needs none
  CHECK_THROWS_AS(post_bc(cl, Choice::greedy, 1, 0), Infeasible);
  CHECK(post_bc(cl, Choice::lookahead, 1, 0).program == planned.program);
  CHECK(post_bc(cl, Choice::lookahead, 2, 40).program == planned.program);
}

TEST_CASE("branch plan in the post: the hemisphere on the BC head, 2 retracts instead of 10, both threads",
          "[post][branch]") {
  const std::string cl = test::read_text_file(test::source("samples/hemisphere_5axis.cls"));
  using Choice = PostOptions::BranchChoice;
  const Posted greedy = post_bc(cl, Choice::greedy, 1, 40);
  const Posted planned = post_bc(cl, Choice::lookahead, 1, 40);
  CHECK(greedy.summary.retracts == 10);
  CHECK(planned.summary.retracts == 2);
  CHECK(planned.summary.verify.max_contour_mm == Approx(greedy.summary.verify.max_contour_mm).margin(1e-4));
  CHECK(planned.summary.verify.max_contour_mm < 1.0);  // no block swings through the part
  CHECK(post_bc(cl, Choice::lookahead, 2, 40).program == planned.program);
  CHECK(post_bc(cl, Choice::greedy, 2, 40).program == greedy.program);
}
