// SPDX-License-Identifier: Apache-2.0
// The NC programs of `ncpost plan` go through the NC writer (issue 16 item 3): the dialect's
// program start and end, block numbers, comment style and sanitising, word formats, dwell blocks
// and program stop. Reviewed programs for Fanuc and Heidenhain (a laser plan, and a hand-made
// program with every record kind and hostile comment text), the untimed inverse-time move written
// per minute and the timed one refused where the dialect has no inverse time, a timed move to the
// same pose written as a dwell, and `plan --dialect` on the command line.
#include <catch2/catch.hpp>

#include <cctype>
#include <filesystem>
#include <sstream>
#include <string>

#include "cli_run.hpp"
#include "ncpost/compensation/laser_plan.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/write/plan_nc.hpp"
#include "temp_dir.hpp"
#include "test_paths.hpp"

using namespace ncpost;

namespace {

/// The laser plan of axis X, one run on one line, positioning only, 200 mm steps.
comp::PlanProgram laser_x(const Machine& m) {
  comp::LaserPlanOptions o;
  o.axes = "X";
  o.runs = 1;
  o.lines = 1;
  o.straightness = false;
  o.step_mm = 200.0;
  return comp::laser_program(m, comp::plan_laser(m, o), o);
}

AxisPosition pose(double x, double y, double z, double a_deg, double c_deg) {
  return AxisPosition(Vec3d(x, y, z), Eigen::Vector2d(deg_to_rad(a_deg), deg_to_rad(c_deg)));
}

/// Every record kind; a machine name and set text with what would end a comment or the tape.
comp::PlanProgram every_record() {
  comp::PlanProgram p;
  p.name = "probe (test); 1";
  p.header = {"machine my (mill); 100% \"done\"\nM30"};
  p.comment("--- set s: sphere (seed) ---");
  p.rapid(pose(10, 20, 130, 0, 0));
  p.stop("mount the instrument");
  p.feed(pose(10, 20, 100, 0, 0), 1000.0, "approach");
  p.dwell(2.5, "read point 1");
  p.inverse_time(pose(10, 25, 100, 0, 45), 120.0, false);
  p.inverse_time(pose(10, 25, 100, 0, 45), 120.0, false);  // no motion, untimed: nothing
  p.stop("remove the instrument");
  return p;
}

}  // namespace

TEST_CASE("plan programs: a laser plan in Fanuc and Heidenhain words", "[plan][dialect]") {
  const Machine m = load_machine(test::source("machines/vmcl600.toml"));
  const comp::PlanProgram p = laser_x(m);
  CHECK(plan_program_text(m, p, dialect_named("fanuc")) ==
        "%\n"
        "O0001 (NCPOSTPLANLASER)\n"
        "(ncpost plan laser: ISO 230-2 test cycles)\n"
        "(machine vmcl600)\n"
        "G90 G21 G94 G17 G40 G49 G80\n"
        "(--- set X1_pos: laser positioning of axis X, line 1 [ISO 230-2 cycle, 1 runs] ---)\n"
        "(reflector at 0.0, 0.0, 0.0 mm from the tool tip, tool length 100.0 mm, reads X)\n"
        "G0 X-300.0000 Y-105.0000 Z-90.0000\n"
        "M0 (set up the optics on this line, zero the laser at the first target)\n"
        "(run 1 forward pass)\n"
        "G94 G1 X-295.0000 F2000.0\n"
        "G4 P4000 (read 1)\n"
        "X-200.0000\n"
        "G4 P4000 (read 2)\n"
        "X0.0000\n"
        "G4 P4000 (read 3)\n"
        "X200.0000\n"
        "G4 P4000 (read 4)\n"
        "X295.0000\n"
        "G4 P4000 (read 5)\n"
        "(run 1 backward pass)\n"
        "X300.0000\n"
        "X295.0000\n"
        "G4 P4000 (read 6)\n"
        "X200.0000\n"
        "G4 P4000 (read 7)\n"
        "X0.0000\n"
        "G4 P4000 (read 8)\n"
        "X-200.0000\n"
        "G4 P4000 (read 9)\n"
        "X-295.0000\n"
        "G4 P4000 (read 10)\n"
        "M5\n"
        "M9\n"
        "G91 G28 Z0\n"
        "G90\n"
        "M30\n"
        "%\n");
  CHECK(plan_program_text(m, p, dialect_named("heidenhain")) ==
        "0 BEGIN PGM NCPOSTPLANLASER MM\n"
        "1 ; ncpost plan laser: ISO 230-2 test cycles\n"
        "2 ; machine vmcl600\n"
        "3 ; --- set X1_pos: laser positioning of axis X, line 1 (ISO 230-2 cycle, 1 runs) ---\n"
        "4 ; reflector at 0.0, 0.0, 0.0 mm from the tool tip, tool length 100.0 mm, reads X\n"
        "5 L X-300.0000 Y-105.0000 Z-90.0000 FMAX\n"
        "6 M0 ; set up the optics on this line, zero the laser at the first target\n"
        "7 ; run 1 forward pass\n"
        "8 L X-295.0000 F2000\n"
        "9 CYCL DEF 9.0 DWELL TIME\n"
        "10 CYCL DEF 9.1 DWELL 4.000 ; read 1\n"
        "11 L X-200.0000 F2000\n"
        "12 CYCL DEF 9.0 DWELL TIME\n"
        "13 CYCL DEF 9.1 DWELL 4.000 ; read 2\n"
        "14 L X+0.0000 F2000\n"
        "15 CYCL DEF 9.0 DWELL TIME\n"
        "16 CYCL DEF 9.1 DWELL 4.000 ; read 3\n"
        "17 L X+200.0000 F2000\n"
        "18 CYCL DEF 9.0 DWELL TIME\n"
        "19 CYCL DEF 9.1 DWELL 4.000 ; read 4\n"
        "20 L X+295.0000 F2000\n"
        "21 CYCL DEF 9.0 DWELL TIME\n"
        "22 CYCL DEF 9.1 DWELL 4.000 ; read 5\n"
        "23 ; run 1 backward pass\n"
        "24 L X+300.0000 F2000\n"
        "25 L X+295.0000 F2000\n"
        "26 CYCL DEF 9.0 DWELL TIME\n"
        "27 CYCL DEF 9.1 DWELL 4.000 ; read 6\n"
        "28 L X+200.0000 F2000\n"
        "29 CYCL DEF 9.0 DWELL TIME\n"
        "30 CYCL DEF 9.1 DWELL 4.000 ; read 7\n"
        "31 L X+0.0000 F2000\n"
        "32 CYCL DEF 9.0 DWELL TIME\n"
        "33 CYCL DEF 9.1 DWELL 4.000 ; read 8\n"
        "34 L X-200.0000 F2000\n"
        "35 CYCL DEF 9.0 DWELL TIME\n"
        "36 CYCL DEF 9.1 DWELL 4.000 ; read 9\n"
        "37 L X-295.0000 F2000\n"
        "38 CYCL DEF 9.0 DWELL TIME\n"
        "39 CYCL DEF 9.1 DWELL 4.000 ; read 10\n"
        "40 M30\n"
        "41 END PGM NCPOSTPLANLASER MM\n");
}

TEST_CASE("plan programs: every record kind, comments sanitised, Fanuc and Heidenhain", "[plan][dialect]") {
  const Machine m = load_machine(test::source("machines/ac-trunnion.toml"));
  const comp::PlanProgram p = every_record();
  // Fanuc: "()%;" become "[]  ", the newline a space: no comment ends early, no line is "M30" but the end
  CHECK(plan_program_text(m, p, dialect_named("fanuc")) ==
        "%\n"
        "O0001 (PROBETEST1)\n"
        "(machine my [mill]  100  \"done\" M30)\n"
        "G90 G21 G94 G17 G40 G49 G80\n"
        "(--- set s: sphere [seed] ---)\n"
        "G0 X10.0000 Y20.0000 Z130.0000 A0.0000 C0.0000\n"
        "M0 (mount the instrument)\n"
        "G94 G1 Z100.0000 F1000.0 (approach)\n"
        "G4 P2500 (read point 1)\n"
        "G93 Y25.0000 C45.0000 F120.0000\n"
        "M0 (remove the instrument)\n"
        "M5\n"
        "M9\n"
        "G91 G28 Z0\n"
        "G90\n"
        "M30\n"
        "%\n");
  // Heidenhain: ';' and '%' replaced, parentheses kept; no inverse time: the untimed turn per minute
  CHECK(plan_program_text(m, p, dialect_named("heidenhain")) ==
        "0 BEGIN PGM PROBETEST1 MM\n"
        "1 ; machine my (mill)  100  \"done\" M30\n"
        "2 ; --- set s: sphere (seed) ---\n"
        "3 L X+10.0000 Y+20.0000 Z+130.0000 A+0.0000 C+0.0000 FMAX\n"
        "4 M0 ; mount the instrument\n"
        "5 L Z+100.0000 F1000 ; approach\n"
        "6 CYCL DEF 9.0 DWELL TIME\n"
        "7 CYCL DEF 9.1 DWELL 2.500 ; read point 1\n"
        "8 L Y+25.0000 C+45.0000 F500\n"
        "9 M0 ; remove the instrument\n"
        "10 M30\n"
        "11 END PGM PROBETEST1 MM\n");
}

TEST_CASE("plan programs: a timed move needs inverse time; at the same pose it is a dwell", "[plan][dialect]") {
  const Machine m = load_machine(test::source("machines/ac-trunnion.toml"));
  comp::PlanProgram p;
  p.name = "timed";
  p.rapid(pose(0, 0, 250, 0, 0));
  p.inverse_time(pose(0, -10, 250, 10, 20), 120.0, true);
  p.inverse_time(pose(0, -10, 250, 10, 20), 120.0, true);  // the next row at the same pose: 0.5 s
  p.inverse_time(pose(0, -20, 250, 20, 40), 60.0, true);
  CHECK(plan_program_text(m, p, dialect_named("linuxcnc")) ==
        "G90 G21 G94 G17 G40 G49 G80\n"
        "G0 X0.0000 Y0.0000 Z250.0000 A0.0000 C0.0000\n"
        "G93 G1 Y-10.0000 A10.0000 C20.0000 F120.0000\n"
        "G4 P0.500 (the next row at the same pose)\n"
        "Y-20.0000 A20.0000 C40.0000 F60.0000\n"
        "M2\n");
  try {
    plan_program_text(m, p, dialect_named("heidenhain"));
    FAIL("a timed move in a dialect without inverse time was written");
  } catch (const std::invalid_argument& e) {
    CHECK(std::string(e.what()).find("heidenhain dialect") != std::string::npos);
    CHECK(std::string(e.what()).find("no inverse-time feed") != std::string::npos);
  }
}

TEST_CASE("plan --dialect: the program in the dialect, the plan rounded to its decimals", "[plan][dialect][cli]") {
  const std::string d = test::make_temp_dir("ncpost_plan_dialect") + "/";
  const std::string machine = "--machine " + test::source("machines/ac-trunnion.toml");
  REQUIRE(test::run_ncpost("plan " + machine + " sphere --step 90 --levels 0 --dialect heidenhain -o " + d + "h",
                           d + "log") == 0);
  const std::string nc = test::read_text_file(d + "h.nc");
  CHECK(nc.rfind("0 BEGIN PGM NCPOSTPLANSPHERE MM\n", 0) == 0);
  CHECK(nc.find("M0 ; mount the instrument, start recording") != std::string::npos);
  CHECK(nc.find("CYCL DEF 9.1 DWELL 5.000 ; read point 1") != std::string::npos);
  // a dialect file that writes 2 decimals: the rows of the CSV are the values the program writes
  std::string fanuc = test::read_text_file(test::source("postproc/dialects/fanuc.toml"));
  for (const std::string key : {"linear_decimals = 4", "angle_decimals = 4"}) {
    const auto at = fanuc.find(key);
    REQUIRE(at != std::string::npos);
    fanuc.replace(at + key.size() - 1, 1, "2");
  }
  test::write_text_file(d + "two.toml", fanuc);
  REQUIRE(
      test::run_ncpost("plan " + machine + " sphere --step 90 --levels 30 --dialect " + d + "two.toml -o " + d + "f",
                       d + "log") == 0);
  std::istringstream csv(test::read_text_file(d + "f.csv"));
  std::string line;
  int numbers = 0, beyond = 0;  // numbers of the data rows; with a third decimal that is not 0
  while (std::getline(csv, line)) {
    if (line.empty() || !std::isdigit(static_cast<unsigned char>(line[0]))) continue;  // header, comments
    std::istringstream fields(line);
    for (std::string f; std::getline(fields, f, ',');) {
      ++numbers;
      const auto dot = f.find('.');
      if (dot != std::string::npos && f.find_first_not_of('0', dot + 3) != std::string::npos) ++beyond;
    }
  }
  CHECK(numbers > 20);
  CHECK(beyond == 0);
  const std::string program = test::read_text_file(d + "f.nc");
  CHECK(program.find("M0 (mount the instrument, start recording)") != std::string::npos);
  int words = 0, not_two = 0;  // axis words of the program; those not written with 2 decimals
  std::istringstream tokens(program);
  for (std::string t; tokens >> t;)
    if (t.size() > 1 && std::string("XYZAC").find(t[0]) != std::string::npos && t.find('.') != std::string::npos) {
      ++words;
      not_two += t.size() - t.find('.') - 1 != 2;
    }
  CHECK(words > 20);
  CHECK(not_two == 0);
  CHECK(test::run_ncpost("plan " + machine + " sphere --dialect klartext -o " + d + "x", d + "log") == 1);
  std::filesystem::remove_all(d);
}
