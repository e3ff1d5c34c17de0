// SPDX-License-Identifier: Apache-2.0
// The re-post check of issue 24 itself (tests/support/reposted_tips.hpp, control_interpreter.hpp):
// the tests' control interpreter reads R arcs, full circles, helices, canned cycles, named
// parameters, a leader and G28/G53 as the RS274NGC and Fanuc documentation says (expected values
// worked out by hand from the geometry below), and the input/output comparison passes a right
// program and names the first difference of a wrong one. Input and output are written here; no
// posting.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "reposted_tips.hpp"
#include "test_paths.hpp"

using namespace ncpost::test;

namespace {

ControlSpec xyz_at_zero() {
  ControlSpec spec;
  for (const char* name : {"G54", "G55"})
    for (char a : std::string("XYZ")) spec.offsets[name][a] = 0.0;
  return spec;
}

void check_at(const ControlEnd& e, double x, double y, double z) {
  INFO("line " << e.line);
  CHECK(e.machine.at('X') == Approx(x).margin(1e-9));
  CHECK(e.machine.at('Y') == Approx(y).margin(1e-9));
  CHECK(e.machine.at('Z') == Approx(z).margin(1e-9));
}

// The input of the comparison cases: a tip program in W (vmcl600, workpiece origin 0,0,-100).
const char* const kInput =
    "%\nG21 G90 G17\nG0 X0 Y0 Z5\nG1 Z-1 F200\nG2 X10 Y0 I5 J0\nG1 X10 Y10\nG0 Z5\nG91 G28 Z0\nG90\nM30\n%\n";

/// The written program for kInput with the arc as `arc` and the last feed as `feed`; the words are
/// M = W + (0, 0, -100); G28 Z goes to the top of Z's travel, 50 mm in machine Z (vmcl600.toml).
std::string output(const std::string& arc, const std::string& feed = "G1 X10 Y10", const std::string& home = "G0 Z50") {
  return "%\n(model none [nominal machine], tolerance 0.01 mm [adaptive])\nG90 G21 G94 G17\nG0 X0 Y0 Z-95\n"
         "G1 Z-101 F200\n" +
         arc + "\n" + feed + "\nG0 Z-95\n" + home + "\nM30\n%\n";
}

/// The half circle about (5, 0) from (0, 0) to (10, 0), clockwise (through +Y), as n chords.
std::string chords(int n) {
  std::string s;
  for (int k = 1; k <= n; ++k) {
    const double a = M_PI - k * M_PI / n;
    s += "G1 X" + std::to_string(5 + 5 * std::cos(a)) + " Y" + std::to_string(5 * std::sin(a)) + "\n";
  }
  return s.substr(0, s.size() - 1);
}

RepostCheck compare(const std::string& out) {
  ExecJob job;
  job.workpiece_origin_mm = V3(0, 0, -100);
  return compare_reposted_tips(kInput, xyz_at_zero(), source("machines/vmcl600.toml"), job, out);
}

}  // namespace

TEST_CASE("the tests' control interpreter reads arcs by R and by centre, full circles and helices") {
  const std::string program =
      "(Information listing, a leader)\nG0 X99\n%\nG21 G90 G17\nG0 X0 Y0 Z5\n#<depth> = -2\nG1 Z#<depth> F100\n"
      "G2 X10 Y0 R5\nG3 X20 Y10 R-10\nG3 I-5\nG3 X20 Y10 Z-3 I-5 J0\nM30\n%\n";
  const std::vector<ControlEnd> e = ControlInterpreter(program, xyz_at_zero()).run();
  REQUIRE(e.size() == 6);  // the leader's G0 X99 is not run
  check_at(e[1], 0, 0, -2);
  // R5 between (0,0) and (10,0): the chord is the diameter, the centre its middle
  CHECK(e[2].motion == 2);
  CHECK(e[2].centre.at('X') == Approx(5));
  CHECK(e[2].centre.at('Y') == Approx(0).margin(1e-9));
  // R-10 from (10,0) to (20,10) counter-clockwise: of the two centres (20,0) and (10,10), the one of
  // the arc longer than half a turn: about (20,0) from 180 deg to 90 deg ccw is 270 deg
  CHECK(e[3].centre.at('X') == Approx(20));
  CHECK(e[3].centre.at('Y') == Approx(0).margin(1e-9));
  // I-5 alone: a full circle about (15,10) ending where it starts
  check_at(e[4], 20, 10, -2);
  CHECK(e[4].centre.at('X') == Approx(15));
  // a helix: the same circle, Z from -2 to -3
  check_at(e[5], 20, 10, -3);
  CHECK(e[5].motion == 3);
}

TEST_CASE("the tests' control interpreter runs canned cycles and machine-coordinate moves") {
  ControlSpec spec = xyz_at_zero();
  spec.reference['Z'] = 50.0;  // machine coordinates = words here (no tip reading)
  const std::string program =
      "G21 G90 G17\nG0 X0 Y0 Z5\nG98 G81 X30 Y0 Z-3 R2 F50\nG99 X40\nG80\nG0 Z10\n"
      "G91 G28 Z0\nG90 G53 Z-10\nG28 X0\nG0 X1 Y1 Z1\nM30\n";
  const std::vector<ControlEnd> e = ControlInterpreter(program, spec).run();
  REQUIRE(e.size() == 16);
  // G98: over the hole at the initial Z 5, R plane, bottom (fed), back to the initial Z
  check_at(e[1], 30, 0, 5);
  check_at(e[2], 30, 0, 2);
  check_at(e[3], 30, 0, -3);
  CHECK_FALSE(e[3].rapid);
  check_at(e[4], 30, 0, 5);
  CHECK(e[4].rapid);
  // G99: back to the R plane
  check_at(e[8], 40, 0, 2);
  check_at(e[9], 40, 0, 10);  // G80, then G0 Z10
  // G91 G28 Z0: the intermediate point is where the tool is, then Z to its reference 50
  check_at(e[10], 40, 0, 10);
  check_at(e[11], 40, 0, 50);
  // G53 Z-10: 10 below the reference in machine coordinates
  check_at(e[12], 40, 0, 40);
  // G28 X0 (absolute): the intermediate point X0, then X to a reference nobody gave: unknown
  check_at(e[13], 0, 0, 40);
  CHECK(e[14].unknown == "X");
  CHECK_FALSE(e[14].complete);
  CHECK(e[15].unknown == "");  // G0 X1 Y1 Z1 programs X again
  check_at(e[15], 1, 1, 1);
}

TEST_CASE("the re-post comparison passes a right program and names the first difference of a wrong one") {
  const RepostCheck right = compare(output("G2 X10 Y0 I5 J0"));
  INFO(right.failure);
  CHECK(right.failure.empty());
  CHECK(right.ends == 7);  // X0 Y0 Z5, Z-1, the arc, X10 Y10, Z5, G28's intermediate point (no move), Z to 150 in W
  CHECK(right.samples == 2 + 16 + 2);  // straight blocks at their two ends, the arc at 16 points

  // the arc as chords: 32 chords of a 5 mm radius stray 5 (1 - cos(pi/64)) = 6 um from it, within
  // 0.01 mm; 8 chords stray 96 um
  CHECK(compare(output(chords(32))).failure.empty());
  CHECK_THAT(compare(output(chords(8))).failure, Catch::Contains("from the input's path"));

  // the arc the other way round: through -Y
  CHECK_THAT(compare(output("G3 X10 Y0 I5 J0")).failure, Catch::Contains("input line 5"));
  // an end 2 um off
  CHECK_THAT(compare(output("G2 X10 Y0 I5 J0", "G1 X10 Y10.002")).failure,
             Catch::Contains("no output block ends there"));
  // a feed written as a rapid
  CHECK_THAT(compare(output("G2 X10 Y0 I5 J0", "G0 X10 Y10\nG1")).failure,
             Catch::Contains("is a rapid where the input feeds"));
  // G28 Z0 left out of the output: the tool never reaches Z's reference
  CHECK_THAT(compare(output("G2 X10 Y0 I5 J0", "G1 X10 Y10", "")).failure, Catch::Contains("input line 8"));
}
