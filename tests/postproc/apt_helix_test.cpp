// SPDX-License-Identifier: Apache-2.0
// NX helices (CIRCLE/...,TIMES,n, issue 24.7): n turns in all, the last the arc to the next GOTO,
// clockwise about (i,j,k), one pitch. The written program is executed with the tests' executor
// and every point held against the helix computed here from the record.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "cli_run.hpp"
#include "nc_executor.hpp"
#include "temp_dir.hpp"
#include "test_paths.hpp"
#include "text_file.hpp"

using namespace ncpost::test;

TEST_CASE("an NX helix of 3 turns is posted as 2 turns and the 270 deg arc to the GOTO, at one pitch", "[apt][helix]") {
  // start (5, 0, 10); centre (0, 0, 4) at the end's level; axis +Z, NX: clockwise about it; the end
  // (0, 5, 4) is 270 deg clockwise from the start: 2 x 360 + 270 = 990 deg for 6 mm of depth
  const std::string cl =
      "TOOL PATH/HELIX,TOOL,MILL\nUNITS/MM\nLOADTL/1\nRAPID\nGOTO/5,0,10\nFEDRAT/MMPM,400\n"
      "CIRCLE/0,0,4,0,0,1,5,0.01,0.5,6,0,TIMES,3\nGOTO/0,5,4\nFINI\n";
  const std::string dir = make_temp_dir("apt_helix");
  const std::string in = write_text_file(dir + "/h.cls", cl), out = dir + "/h.nc", log = dir + "/h.log";
  REQUIRE(run_ncpost("post --machine " + source("machines/vmcl600.toml") + " -o " + out + " " + in, log) == 0);
  const Executor ex(source("machines/vmcl600.toml"), ExecJob{}, read_text_file(out));
  double turned_deg = 0.0, last_angle = 0.0, worst_radius = 0.0, worst_pitch = 0.0;
  bool started = false;
  for (const ExecBlock& b : ex.blocks) {
    if (b.kind == ExecBlock::Kind::rapid) continue;
    for (int i = 0; i <= 10; ++i) {
      const V3 p = ex.at(b, i / 10.0).tip_W;
      if (!started && (p - V3(5, 0, 10)).norm() > 1e-3) continue;  // the helix starts at (5, 0, 10)
      const double angle = std::atan2(p.y(), p.x()) * 180.0 / M_PI;
      if (started) {
        double step = last_angle - angle;  // clockwise positive
        step -= 360.0 * std::round(step / 360.0);
        turned_deg += step;
      }
      started = true;
      last_angle = angle;
      worst_radius = std::max(worst_radius, std::abs(std::hypot(p.x(), p.y()) - 5.0));
      worst_pitch = std::max(worst_pitch, std::abs(p.z() - (10.0 - 6.0 * turned_deg / 990.0)));
    }
  }
  CHECK(turned_deg == Approx(990.0).margin(0.05));
  CHECK(worst_radius < 0.011);  // within the post's tolerance (0.01 mm) of the cylinder
  CHECK(worst_pitch < 0.011);   // on the one pitch (6 mm / 990 deg)
}
