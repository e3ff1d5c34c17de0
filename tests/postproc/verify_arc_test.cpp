// SPDX-License-Identifier: Apache-2.0
// `post --verify` re-executes native arcs too (verify_arc.hpp): the circle the control runs from
// the written words, through the machine, against the CL circle. A right arc measures 0; a centre
// off by 0.1 mm, a wrong direction or a wrong end are seen at their size.
#include <catch2/catch.hpp>

#include <cmath>

#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/solve/motion_solver.hpp"
#include "ncpost/postproc/verify/verify_arc.hpp"
#include "test_paths.hpp"

using namespace ncpost;

namespace {

struct Case {
  Machine machine = load_machine(test::source("machines/vmcl600.toml"));
  Setup setup;
  NominalSolver solver{machine, setup};
  SolverData data;
  // the CL: a half circle of radius 10 about (0, 0, -2), counter-clockwise about +Z, (10,0) -> (-10,0)
  ClArc cl{Vec3d(10, 0, -2), Vec3d(0, 0, -2), Vec3d(-10, 0, -2), Vec3d::UnitZ(), Vec3d::UnitZ(), kPi};

  double run(const FrameArc& arc, VerifyReport& report) {
    const auto at = [&](const Vec3d& x) {
      AxisPosition q = home_of(machine);
      q.linear_mm = x;  // a three-axis machine at home offsets: the tool tip is at the linear axes
      return q;
    };
    return verify_arc(solver, data, arc, at, cl, 7, report);
  }
};

}  // namespace

TEST_CASE("verify_arc: the control's circle from the words, against the CL circle") {
  Case c;
  VerifyReport report;
  FrameArc right{Vec3d(10, 0, -2), Vec3d(0, 0, -2), Vec3d(-10, 0, -2), Vec3d::UnitZ(), kPi};
  CHECK(c.run(right, report) == Approx(0.0).margin(1e-9));
  CHECK(report.blocks == 1);
  CHECK(report.max_endpoint_mm == Approx(0.0).margin(1e-9));

  // the centre 0.1 mm off in Y (I J wrong): the radius is sqrt(100.01) at the start, and the
  // middle of the arc bulges 0.1 mm beyond the CL circle
  FrameArc shifted{Vec3d(10, 0, -2), Vec3d(0, 0.1, -2), Vec3d(-10, 0, -2), Vec3d::UnitZ(), kPi};
  VerifyReport r2;
  const double e = c.run(shifted, r2);
  CHECK(e == Approx(0.1 + std::sqrt(100.01) - 10.0).epsilon(0.02));
  CHECK(r2.worst_line == 7);

  // the wrong direction (G2 for G3): the executed half circle runs through y < 0, 20 mm away at its middle
  FrameArc reversed{Vec3d(10, 0, -2), Vec3d(0, 0, -2), Vec3d(-10, 0, -2), -Vec3d::UnitZ(), kPi};
  VerifyReport r3;
  CHECK(c.run(reversed, r3) == Approx(2.0 * 10.0 * std::sin(kPi / 4.0)).epsilon(0.01));  // nearest CL end: 14.14 mm

  // a helix that rises 1 mm where the CL is planar: 1 mm at the end
  FrameArc helix{Vec3d(10, 0, -2), Vec3d(0, 0, -2), Vec3d(-10, 0, -1), Vec3d::UnitZ(), kPi};
  VerifyReport r4;
  CHECK(c.run(helix, r4) == Approx(1.0).epsilon(1e-6));
  CHECK(r4.max_endpoint_mm == Approx(1.0).epsilon(1e-6));
}

TEST_CASE("ClArc::distance: on, inside, beyond the sweep") {
  const ClArc cl{Vec3d(10, 0, 0), Vec3d::Zero(), Vec3d(0, 10, 0), Vec3d::UnitZ(), Vec3d::UnitZ(), kPi / 2.0};
  CHECK(cl.distance(Vec3d(10 * std::cos(0.3), 10 * std::sin(0.3), 0)) == Approx(0.0).margin(1e-12));
  CHECK(cl.distance(Vec3d(5 * std::cos(0.3), 5 * std::sin(0.3), 0)) == Approx(5.0));
  CHECK(cl.distance(Vec3d(0, -10, 0)) == Approx((Vec3d(0, -10, 0) - Vec3d(10, 0, 0)).norm()));      // nearer: the start
  CHECK(cl.distance(Vec3d(-10, 0.5, 0)) == Approx((Vec3d(-10, 0.5, 0) - Vec3d(0, 10, 0)).norm()));  // nearer: the end
}

TEST_CASE("ClArc::distance: a full-circle helix ends one pitch below its start") {
  const ClArc cl{Vec3d(0.1, 0, 0), Vec3d::Zero(), Vec3d(0.1, 0, -0.2), Vec3d::UnitZ(), Vec3d::UnitZ(), 2.0 * kPi};
  CHECK(cl.distance(Vec3d(0.1, 0, -0.2)) == Approx(0.0).margin(1e-12));   // the end, not the start
  CHECK(cl.distance(Vec3d(-0.1, 0, -0.1)) == Approx(0.0).margin(1e-12));  // half way down
}
