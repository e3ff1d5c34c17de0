// SPDX-License-Identifier: Apache-2.0
// Issue 24.4: subprograms expanded with a call stack: Fanuc/Haas M98 P L / M99 (O blocks after
// M30), Fanuc's M98 P<count><program>, Haas M97 P L, LinuxCNC o-word sub/call/return with #1..#30
// and if/elseif/else/endif, while, do/while, repeat, break, continue; repeat counts, a depth
// limit, recursion refused, messages naming the call chain. Every posting case executes the INPUT
// with the tests' own control interpreter (tests/support/control_interpreter.hpp) and the written
// OUTPUT with nc_executor.hpp and compares the tool tip at every input block end (1 µm).
#include <catch2/catch.hpp>

#include <sstream>
#include <string>

#include "cl_records.hpp"
#include "cli_run.hpp"
#include "input_output_tips.hpp"
#include "shipped_machines.hpp"
#include "temp_dir.hpp"
#include "test_paths.hpp"
#include "text_file.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/read/gcode/gcode_cl_reader.hpp"

using namespace ncpost;
using namespace ncpost::test;

namespace {

/// Posts `input` on the VMCL600 (--tolerance none) and checks it block end by block end; returns
/// the number of input block ends compared (0 when the post failed).
int posted_and_compared(const std::string& input, bool linuxcnc = false) {
  const std::string dir = make_temp_dir("subprograms");
  const std::string in = write_text_file(dir + "/in.nc", input);
  const int rc = run_ncpost("post --machine " + source("machines/vmcl600.toml") + " --tolerance none --dialect " +
                                (linuxcnc ? "linuxcnc" : "fanuc") + " -o " + dir + "/out.nc " + in,
                            dir + "/log");
  INFO(read_text_file(dir + "/log"));
  CHECK(rc == 0);
  if (rc != 0) return 0;
  ControlSpec spec;
  spec.linuxcnc = linuxcnc;
  spec.offsets["G54"] = {{'X', 0.0}, {'Y', 0.0}, {'Z', 0.0}};
  return compare_tips(input, spec, "G54", "vmcl600.toml", read_text_file(dir + "/out.nc"));
}

InputError error_of(const std::string& text) {
  std::istringstream in(text);
  gcode::GcodeClReader r(in, "t.nc", vmcl600(), Setup{});
  try {
    while (r.next()) {
    }
  } catch (const InputError& e) {
    return e;
  }
  FAIL("no error for: " << text);
  throw;
}

}  // namespace

TEST_CASE("subprograms: Fanuc M98 P1000 L3 runs O1000 (after M30) three times, incrementally") {
  const std::string input =
      "%\nO0001\nG21 G90 G17 G94\nG0 X0 Y0 Z10\nG1 Z0 F200\nM98 P1000 L3\nG90 G0 Z10\nM98 P2000\nG0 X0 Y0\nM30\n"
      "O1000 (STEP)\nG91 G1 X10\nY5\nG90\nM99\n"
      "O2000 (NESTED)\nG0 X50 Y50\nM98 P1000\nG90 G1 Z5\nM99\n%\n";
  // ends: 2 + 3 x 2 + 1 + (1 + 2 + 1) + 1
  CHECK(posted_and_compared(input) == 14);
}

TEST_CASE("subprograms: Fanuc M98 P21000 is O1000 twice; Haas M97 P<n> L<k> runs from block N<n>") {
  CHECK(posted_and_compared("G21 G90\nG0 X0 Y0 Z10\nM98 P21000\nM30\nO1000\nG91 G0 X7 Y-3\nG90\nM99\n") == 3);
  CHECK(posted_and_compared("G21 G90\nG0 X0 Y0 Z10\nM97 P100 L2\nG0 X1\nM30\nN100 G91 G1 X2 F100\nY2\nG90 M99\n") == 6);
}

TEST_CASE("subprograms: LinuxCNC o<name> sub with parameters #1 #2, called twice; numbered o100 sub") {
  const std::string input =
      "o<square> sub\n  G0 X#1 Y#2\n  G1 Z0 F100\n  X[#1 + 10]\n  Y[#2 + 10]\n  G0 Z10\no<square> endsub\n"
      "o100 sub\n  G1 X#1\no100 endsub\n"
      "G21 G90 G17\nG0 X0 Y0 Z10\n#1 = 77\no<square> call [5] [6]\no<square> call [30] [-4.5]\n"
      "o100 call [#1]\nM2\n";
  CHECK(posted_and_compared(input, true) == 12);
}

TEST_CASE("subprograms: LinuxCNC if/elseif/else, while, do/while, repeat, break, continue and return") {
  const std::string input =
      "o<pick> sub\n"
      "  o1 if [#1 LT 0]\n    G1 X-5\n  o1 elseif [#1 EQ 0]\n    G1 X0\n  o1 else\n    G1 X5\n  o1 endif\n"
      "  o2 if [#1 GT 1]\n    o<pick> return\n  o2 endif\n  G1 Y#1\n"
      "o<pick> endsub\n"
      "G21 G90\nG0 X0 Y0 Z10\nG1 Z0 F100\n"
      "o<pick> call [-1]\no<pick> call [0]\no<pick> call [3]\n"
      "#5 = 0\no10 while [#5 LT 3]\n  G1 Z[-#5 - 1]\n  #5 = [#5 + 1]\no10 endwhile\n"
      "o11 do\n  G1 Y[#5 * 2]\n  #5 = [#5 - 1]\no11 while [#5 GT 0]\n"
      "o12 repeat [4]\n  G91 G1 X1\n  G90\no12 endrepeat\n"
      "#6 = 0\no13 while [1]\n  #6 = [#6 + 1]\n  o14 if [#6 EQ 2]\n    o13 continue\n  o14 endif\n"
      "  G1 Y[#6 * 10]\n  o15 if [#6 GE 4]\n    o13 break\n  o15 endif\no13 endwhile\n"
      "G0 Z10\nM2\n";
  // pick: 2 + 2 + 1 ends; while 3; do 3; repeat 4; the last loop Y10, Y30, Y40; G0 Z10; + 2 at the start
  CHECK(posted_and_compared(input, true) == 21);
}

TEST_CASE("subprograms: recursion, depth, missing targets and M99 in the main program are refused") {
  const InputError self = error_of("G21 G90\nG0 X0 Y0 Z10\nM98 P1000\nM30\nO1000\nG0 X1\nM98 P1000\nM99\n");
  CHECK(self.where().line == 7);
  CHECK_THAT(self.detail(), Catch::Contains("O1000 calls itself (recursion)"));
  CHECK_THAT(self.detail(), Catch::Contains("via O1000 call at t.nc:3"));
  // O1 .. O12 each calling the next: the eleventh call is refused
  std::string deep = "G21 G90\nG0 X0 Y0 Z10\nM98 P1\nM30\n";
  for (int i = 1; i <= 12; ++i) deep += "O" + std::to_string(i) + "\nM98 P" + std::to_string(i + 1) + "\nM99\n";
  CHECK_THAT(error_of(deep).detail(), Catch::Contains("more than 10 calls deep"));
  CHECK_THAT(error_of("G21 G90\nG0 X0 Y0 Z10\nM98 P77\nM30\n").detail(),
             Catch::Contains("M98 P77: the file holds no program O77"));
  CHECK_THAT(error_of("G21 G90\nG0 X0 Y0 Z10\nM99\n").detail(), Catch::Contains("M99 in the main program"));
  CHECK_THAT(error_of("G21 G90\nG0 X0 Y0 Z10\no<nope> call\nM2\n").detail(),
             Catch::Contains("o<nope> call: the file holds no o<nope> sub"));
  CHECK_THAT(error_of("G21 G90\nG0 X0 Y0 Z10\no1 if [1]\nG0 X1\no1 else\nG0 X2\nM2\n").detail(),
             Catch::Contains("o1 else without its endif"));
  CHECK_THAT(error_of("%\nG21 G90\nG0 X0 Y0 Z10\nM98 P5\nM30\nO5\nG0 X1\n%\n").detail(),
             Catch::Contains("O5 ends at the '%' without M99"));
}

TEST_CASE("subprograms: an error inside a subprogram names the call chain") {
  // the o<inner> sub's line 2 has an axis the machine lacks; called from o<outer> at line 4, from line 8
  const InputError e = error_of(
      "o<inner> sub\n  G0 B5\no<inner> endsub\no<outer> sub\n  o<inner> call\no<outer> endsub\n"
      "G21 G90\nG0 X0 Y0 Z10\no<outer> call\nM2\n");
  CHECK(e.where().line == 2);
  CHECK_THAT(e.detail(), Catch::Contains("no B axis"));
  CHECK_THAT(e.detail(), Catch::EndsWith("via o<inner> call at t.nc:5 via o<outer> call at t.nc:9"));
}

TEST_CASE("subprograms: M98 P L under a modal canned cycle: P and L are the call's, the holes the subprogram's") {
  // Peter Smid's pattern: the cycle is set in the main program, the hole positions are a subprogram
  const std::string text =
      "G21 G90 G94\nG0 X0 Y0 Z20\nG99 G82 R2 Z-5 P500 F100\nM98 P1002 L2\nG80\nG0 Z20\nM30\n"
      "O1002\nX10 Y10\nX20 Y10\nM99\n";
  std::istringstream in(text);
  gcode::GcodeClReader r(in, "t.nc", vmcl600(), Setup{});
  const std::vector<cl::Record> records = all_records(r);
  std::vector<cl::Cycle> holes;
  for (const cl::Cycle& c : only<cl::Cycle>(records))
    if (c.kind != cl::Cycle::Kind::off) holes.push_back(c);
  REQUIRE(holes.size() == 5);  // the cycle's own block at X0 Y0 (its Z is an axis word), then two holes, twice
  for (const cl::Cycle& c : holes) {
    CHECK(c.dwell_s == Approx(0.5));  // G82's own P500, not the call's P1002
    CHECK(c.depth_mm == Approx(7.0));
  }
  CHECK(holes[0].where.line == 3);
  CHECK(holes[4].where.line == 10);
}
