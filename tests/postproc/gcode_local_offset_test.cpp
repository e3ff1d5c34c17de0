// SPDX-License-Identifier: Apache-2.0
// Issue 24: local coordinate shifts G52 (the shift is the words) and G92 (the shift that makes the
// current position read the words), added in every work offset. Each posting case executes the
// INPUT with the tests' own control interpreter (tests/support/control_interpreter.hpp, its own
// G52/G92) and the written OUTPUT with tests/support/nc_executor.hpp, and compares the tool tip at
// every input block end (1 µm); one expected coordinate per case is worked out by hand from the rule.
#include <catch2/catch.hpp>

#include <string>

#include "cli_run.hpp"
#include "input_output_tips.hpp"
#include "temp_dir.hpp"
#include "test_paths.hpp"
#include "text_file.hpp"

using namespace ncpost::test;

namespace {

PostRun post_local(const std::string& input, const std::string& dialect) {
  const std::string dir = make_temp_dir("local_offsets");
  const std::string in = write_text_file(dir + "/in.nc", input);
  return run_post("--machine " + source("machines/vmcl600.toml") + " --tolerance none --dialect " + dialect, in,
                  dir + "/out.nc", dir + "/log");
}

ControlSpec g54_only(bool linuxcnc) {
  ControlSpec s;
  s.offsets = {{"G54", {{'X', -250.0}, {'Y', -120.0}, {'Z', -310.0}}}};
  s.linuxcnc = linuxcnc;
  return s;
}

}  // namespace

TEST_CASE("local offsets: G92 X0 between tiles, each tile cut by one subprogram (pcb2gcode's Mach4 tiling)") {
  // the subprogram cuts X0..X10 at Y0..Y5 in its tile; between calls the tool goes 30 mm on in X
  // and G92 X0 makes that point the tile's X0: the second tile lies at X30..X40, the third at X60..X70
  const std::string input =
      "%\nO1000\nG21 G90 G17 G94\nG54 G0 X-5 Y-5 Z10\nM98 P200\nG0 X30\nG92 X0\nM98 P200\nG0 X30\nG92 X0\n"
      "M98 P200\nM30\nO200\nG0 X0 Y0 Z3\nG1 Z-1 F200\nX10\nY5\nX0\nG0 Z5\nM99\n%\n";
  const PostRun p = post_local(input, "fanuc");
  INFO(p.log);
  REQUIRE(p.exit_code == 0);
  CHECK_THAT(p.log, Catch::Contains("G92 X0: the coordinates after it are shifted by X+30.0000"));
  CHECK(compare_tips(input, g54_only(false), "G54", "vmcl600.toml", p.program) == 21);
  CHECK_THAT(p.program, Catch::Contains("X70."));  // the third tile's far edge: 30 + 30 + 10
  CHECK_THAT(p.program, !Catch::Contains("G92"));
}

TEST_CASE("local offsets: Fanuc G52 shifts the work offset in force and G52 X0 Y0 cancels it") {
  const std::string input =
      "G21 G90 G17 G94\nG54 G0 X0 Y0 Z5\nG1 Z0 F100\nX10\nG52 X100 Y-20\nG0 X0 Y0\nG1 X10\n"
      "Y10\nG52 X0 Y0\nG0 X5 Y5\nM30\n";
  const PostRun p = post_local(input, "fanuc");
  INFO(p.log);
  REQUIRE(p.exit_code == 0);
  CHECK(compare_tips(input, g54_only(false), "G54", "vmcl600.toml", p.program) == 7);
  CHECK_THAT(p.program, Catch::Contains("X110."));  // X10 in the shifted frame: 100 + 10
  CHECK_THAT(p.program, Catch::Contains("Y-10."));  // Y10 there: -20 + 10
}

TEST_CASE("local offsets: LinuxCNC G92 on two axes after moves, in G91 moves too") {
  const std::string input = "G21 G90 G17 G94\nG0 X12 Y7 Z5\nG92 X0 Y0\nG1 Z-1 F100\nX20\nG91 Y4\nG90 X0\nM2\n";
  const PostRun p = post_local(input, "linuxcnc");
  INFO(p.log);
  REQUIRE(p.exit_code == 0);
  CHECK(compare_tips(input, g54_only(true), "G54", "vmcl600.toml", p.program) == 5);
  CHECK_THAT(p.program, Catch::Contains("X32."));  // X20 read from X12: 12 + 20
}

TEST_CASE("local offsets: LinuxCNC G92 X[#5420 - d] reads the current position (pcb2gcode's LinuxCNC tiling)") {
  // the tool stands at X10 Y5 (inch); G92 X[#5420-3] makes it read X7: later words lie 3 inch
  // (76.2 mm) further in X, so X0 is posted at X76.2 mm, and #5421 reads Y5 there
  const std::string input = "G20 G90 G17 G94\nG0 X10 Y5 Z1\nG92 X[#5420-3]\nG1 Z-0.1 F10\nX0\nY[#5421+1]\nM2\n";
  const PostRun p = post_local(input, "linuxcnc");
  INFO(p.log);
  REQUIRE(p.exit_code == 0);
  CHECK_THAT(p.log, Catch::Contains("G92 X7: the coordinates after it are shifted by X+76.2000"));
  CHECK_THAT(p.program, Catch::Contains("X76.2000"));
  CHECK_THAT(p.program, Catch::Contains("Y152.4000"));  // Y6 inch
  // on Fanuc #5420 is no position: refused by its number
  const PostRun fanuc = post_local(input, "fanuc");
  CHECK(fanuc.exit_code == 2);
  CHECK_THAT(fanuc.log, Catch::Contains("#5420 is a system variable"));
  // a position variable is read, never set; one not programmed yet has no value
  CHECK_THAT(post_local("G21 G90\nG0 X1 Y1 Z1\n#5420 = 3\nM2\n", "linuxcnc").log, Catch::Contains("cannot be set"));
  CHECK(post_local("G21 G90\nG0 X1 Z1\nG0 Y[#5421 + 1]\nM2\n", "linuxcnc").exit_code == 2);
}

TEST_CASE("local offsets: refused where the shift is not known or the controls differ") {
  struct Case {
    const char* input;
    const char* message;
  };
  const Case cases[] = {
      {"G21 G90\nG92 X0 Y0\nG0 X10 Y10 Z5\nM30\n", "in.nc:2:"},                    // the position is not known yet
      {"G21 G90\nG0 X0 Y0 Z5\nG91 G52 X10\nM30\n", "under G91"},                   // incremental values differ
      {"G21 G90\nG0 X0 Y0 Z5\nG52 X10\nG92 X0\nM30\n", "while the shift of G52"},  // Fanuc keeps them apart
      {"G21 G90\nG0 X0 Y0 Z5\nG92.1\nM30\n", "G92.1"},                             // cancel/restore: not read
      {"G21 G90\nG0 X0 Y0 Z5\nG52\nM30\n", "G52 without axis words"},
      {"G21 G90\nG0 X0 Y0 Z5\nG91 G10 L2 P2 X10\nM30\n", "G10 under G91"},  // G91 in the same block
  };
  for (const Case& c : cases) {
    const PostRun p = post_local(c.input, "fanuc");
    INFO(c.input << "\n" << p.log);
    CHECK(p.exit_code == 2);
    CHECK_THAT(p.log, Catch::Contains(c.message));
    CHECK(p.program.empty());
  }
}
