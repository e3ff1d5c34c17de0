// SPDX-License-Identifier: Apache-2.0
// Four-axis machines (one rotary axis): the number of axes is the machine's (AxisPosition holds
// as many rotary angles as the model has). The HMC with a B table (machines/hmc-b-table.toml)
// turns the tool axis in the table's XZ plane only; a tool axis with a Y component is out of
// reach (refused, exit 2). Expected values worked by hand: R_Y(B)·u = +Z on the table.
#include <catch2/catch.hpp>

#include "nc_executor.hpp"

#include "cli_run.hpp"
#include "ncpost/kinematics/inverse.hpp"
#include "ncpost/kinematics/command_words.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "temp_dir.hpp"
#include "test_paths.hpp"
#include "text_edit.hpp"

using namespace ncpost;

namespace {

const Machine& hmc() {
  static const Machine m = load_machine(test::source("machines/hmc-b-table.toml"));
  return m;
}

}  // namespace

TEST_CASE("a four-axis machine has X Y Z and one rotary axis: positions, words and home are sized by it",
          "[four-axis]") {
  const Machine& m = hmc();
  REQUIRE(m.rotary_count() == 1);
  CHECK(m.rotary(0).letter == 'B');
  CHECK(m.rotary(0).side == Side::workpiece);
  CHECK(m.rotary(0).continuous());
  const CommandWords w = CommandWords::of(m);
  CHECK(w.count == 4);
  CHECK(w.letters == std::vector<char>{'X', 'Y', 'Z', 'B'});
  CHECK(w.angle == std::vector<bool>{false, false, false, true});
  // a serial chain's words: every capability of the post (command_words.hpp)
  CHECK((w.angles_are_programmed && w.cutter_comp_supported && w.tilted_plane_capable && w.branches_chosen &&
         w.limits_name_the_axis));
  CHECK(home_of(m).size() == 4);
  CHECK(home_of(load_machine(test::source("machines/vmcl600.toml"))).size() == 3);
  CHECK(home_of(load_machine(test::source("machines/ac-trunnion.toml"))).size() == 5);
}

TEST_CASE("four-axis inverse: the B angle that turns the tool axis onto the spindle, by hand", "[four-axis]") {
  const Machine& m = hmc();
  const Setup setup;  // workpiece origin at the table centre, tool length 0
  // tool along +X of the part (its side face at x = 50): R_Y(B)(1,0,0) = (cos B, 0, -sin B) = +Z: B = -90 deg;
  // the tip (50, 10, 0) turns to (0, 10, 50): X 0, Y 10, and the Z slide brings it to the spindle: Z 50
  const IkOutcome side = solve(m, ClPoint{Vec3d(50, 10, 0), Vec3d::UnitX()}, setup, home_of(m));
  REQUIRE(side.ok());
  REQUIRE(side.position->size() == 4);
  CHECK(rad_to_deg(side.position->rotary_rad[0]) == Approx(-90.0).margin(1e-9));
  CHECK((side.position->linear_mm - Vec3d(0, 10, 50)).norm() < 1e-9);
  // tilted 30 deg in XZ: B = -30 deg; forward gives the CL point back
  const ClPoint tilted{Vec3d(5, -2, 20), Vec3d(0.5, 0.0, std::sqrt(3.0) / 2.0)};
  const IkOutcome t = solve(m, tilted, setup, home_of(m));
  REQUIRE(t.ok());
  CHECK(rad_to_deg(t.position->rotary_rad[0]) == Approx(-30.0).margin(1e-9));
  const ToolPoseT<double> back = forward(m, *t.position, setup);
  CHECK((back.tip_mm - tilted.tip_mm).norm() < 1e-9);
  CHECK((back.axis - tilted.axis).norm() < 1e-12);
  // +Z: B keeps the angle it had (0 from home), and the continuous B unwinds near the previous angle
  AxisPosition previous = home_of(m);
  previous.rotary_rad[0] = deg_to_rad(710.0);
  const IkOutcome unwound = solve(m, ClPoint{Vec3d::Zero(), Vec3d::UnitX()}, setup, previous);
  REQUIRE(unwound.ok());
  CHECK(rad_to_deg(unwound.position->rotary_rad[0]) == Approx(630.0).margin(1e-9));
  // a tool axis with a Y component: no B reaches it
  const IkOutcome out = solve(m, ClPoint{Vec3d::Zero(), Vec3d(0.0, 0.6, 0.8)}, setup, home_of(m));
  CHECK_FALSE(out.ok());
  CHECK_THAT(out.failure.message, Catch::Contains("out of the reach"));
}

TEST_CASE("ncpost post on a four-axis HMC writes X Y Z B, re-executes within the tolerance, refuses a Y tilt (exit 3)",
          "[four-axis][cli]") {
  const std::string dir = test::make_temp_dir("four_axis_cli");
  const std::string machine = "--machine '" + test::source("machines/hmc-b-table.toml") + "' ";
  const std::string apt =
      test::write_text_file(dir + "/index.apt",
                            "UNITS/MM\nLOADTL/1\nSPINDL/3000,CLW\nRAPID\nGOTO/0,0,50,0,0,1\n"
                            "RAPID\nGOTO/80,10,0,1,0,0\nFEDRAT/500\nGOTO/50,10,0,1,0,0\nGOTO/50,-10,0,1,0,0\n"
                            "GOTO/40,-10,10,0.5,0,0.8660254038\nFINI\n");
  REQUIRE(test::run_ncpost("post " + machine + "--verify -o '" + dir + "/index.nc' '" + apt + "'", dir + "/log.txt") ==
          0);
  const std::string nc = test::read_text_file(dir + "/index.nc");
  // the rapid to (80, 10, 0) along +X: Z first (away from the part), then Y and B (R_Y(-90) turns
  // the point to (0, 10, 80)); the cut to x = 50 is Z50, then Y-10; the last point (40, -10, 10)
  // tilted 30 deg turns to (40 cos30 - 10 sin30, -10, 40 sin30 + 10 cos30) = (29.6410, -10, 28.6603)
  CHECK_THAT(nc, Catch::Contains("G0 X0.0000 Y0.0000 Z50.0000 B0.0000\nZ80.0000\nY10.0000 B-90.0000\n"
                                 "G94 G1 Z50.0000 F500.0\nY-10.0000\nG93 X3.4550 Z49.0522 B-85.0000"));
  CHECK_THAT(nc, Catch::Contains("X29.6410 Z28.6603 B-30.0000 F"));
  // every G93 block by the rule of inverse time: F = CL feed / executed tip path (the tests' own
  // executor: nc_executor.hpp), 1/min; the path is about 10 sqrt(2) mm in 12 blocks of 5 deg
  const test::Executor ex(test::source("machines/hmc-b-table.toml"), test::ExecJob{}, nc);
  int g93 = 0;
  double path_mm = 0.0;
  for (const test::ExecBlock& b : ex.blocks) {
    if (b.kind == test::ExecBlock::Kind::rapid || !b.inverse_time) continue;
    ++g93;
    path_mm += ex.tip_path_mm(b);
    CHECK(b.feed * ex.tip_path_mm(b) == Approx(500.0).epsilon(2e-4));
  }
  CHECK(g93 == 12);
  CHECK(path_mm == Approx(10.0 * std::sqrt(2.0)).epsilon(1e-3));
  for (const char* other : {" A", " C"}) CHECK(nc.find(other) == std::string::npos);  // no other rotary word
  const std::string log = test::read_text_file(dir + "/log.txt");
  CHECK_THAT(log, Catch::Contains("after  (the written program re-executed"));
  const std::string tilted_y =
      test::write_text_file(dir + "/tilt_y.apt", "UNITS/MM\nLOADTL/1\nRAPID\nGOTO/0,0,50,0,0.6,0.8\nFINI\n");
  CHECK(test::run_ncpost("post " + machine + "-o '" + dir + "/tilt_y.nc' '" + tilted_y + "'", dir + "/log2.txt") == 3);
  CHECK_THAT(
      test::read_text_file(dir + "/log2.txt"),
      Catch::Contains("tilt_y.apt:4: tool orientation is out of the reach of the rotary axes (tip 0.0000, 0.0000, "
                      "50.0000 mm, axis 0.000000, 0.600000, 0.800000)"));
}
