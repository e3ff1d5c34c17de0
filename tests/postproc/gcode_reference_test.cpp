// SPDX-License-Identifier: Apache-2.0
// Issue 24.1: reference returns (G28, G30, with and without an intermediate point) and G53 placed
// through the machine file's `reference`/`reference2` keys (tests/data/machines/
// ac-trunnion-references.toml: X -400/300, Y 450/-200, Z 550/400, A 0/-90, C 0/none), and the
// refusals without them naming the key. Expected positions by hand: on the AC trunnion with the
// workpiece origin at M's origin the tip in W is Rot(z, -C)·Rot(x, -A)·(X, Y, Z)
// (docs/conventions.md, "Nominal closure").
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

#include "cl_records.hpp"
#include "shipped_machines.hpp"
#include "test_paths.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/read/gcode/gcode_cl_reader.hpp"

using namespace ncpost;
using namespace ncpost::gcode;

namespace {

constexpr double kHalfTurn = 3.14159265358979323846;  // pi

const Machine& with_references() {
  static const Machine m = load_machine(test::data("machines/ac-trunnion-references.toml"));
  return m;
}

struct Read {
  std::vector<cl::Motion> motions;
  std::vector<std::string> notices;
};

Read read(const std::string& text, const Machine& m = with_references()) {
  std::istringstream in(text);
  GcodeClReader r(in, "t.ngc", m, Setup{});
  Read out;
  out.motions = test::only<cl::Motion>(test::all_records(r));
  out.notices = r.take_notices();
  return out;
}

InputError error_of(const std::string& text, const Machine& m) {
  try {
    read(text, m);
  } catch (const InputError& e) {
    return e;
  }
  FAIL("no error for: " << text);
  throw;
}

/// Rot(x, -A) applied to `v` (C = 0).
Vec3d unturn_a(double a_deg, const Vec3d& v) {
  const double a = -a_deg * kHalfTurn / 180.0;
  return {v.x(), std::cos(a) * v.y() - std::sin(a) * v.z(), std::sin(a) * v.y() + std::cos(a) * v.z()};
}

}  // namespace

TEST_CASE("gcode reference: the machine file reads reference and reference2, in the axis's unit") {
  const Machine& m = with_references();
  REQUIRE(m.axes[0].reference);
  CHECK(*m.axes[0].reference == -400.0);
  CHECK(*m.axes[1].reference2 == -200.0);
  REQUIRE(m.axes[3].reference2);
  CHECK(*m.axes[3].reference2 == Approx(-kHalfTurn / 2));  // A: -90 deg
  CHECK_FALSE(m.axes[4].reference2);
  CHECK_FALSE(test::ac_trunnion().axes[0].reference);
  const std::string outside =
      "[machine]\nname = \"m\"\nchain = \"w Y' b X Z t\"\n[axes.X]\ntype = \"linear\"\nlimits = [-500, 500]\n"
      "reference = 700\n[axes.Y]\ntype = \"linear\"\n[axes.Z]\ntype = \"linear\"\n";
  try {
    parse_machine(outside, "m.toml");
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.where().line == 7);
    CHECK_THAT(e.detail(), Catch::Contains("reference: 700 lies outside the axis's limits"));
  }
}

TEST_CASE("gcode reference: G91 G28 Z0 then G28 X0 Y0 go to the reference points; G30 to the second") {
  const Read r = read("G21 G90\nG0 X10 Y10 Z5 A0 C0\nG91 G28 Z0\nG28 X0 Y0\nG90\nM30\n");
  REQUIRE(r.motions.size() == 3);
  CHECK(r.motions[0].point.tip_mm.isApprox(Vec3d(10, 10, 5)));
  CHECK(r.motions[1].point.tip_mm.isApprox(Vec3d(10, 10, 550)));     // Z's reference
  CHECK(r.motions[2].point.tip_mm.isApprox(Vec3d(-400, 450, 550)));  // X's and Y's
  CHECK(r.motions[2].rapid);
  // G90 G30 Z50: the intermediate point (program Z50), then Z to its second reference point, 400
  const Read g30 = read("G21 G90\nG0 X10 Y10 Z5 A0 C0\nG30 Z50\nG0 X0 Y0\nM30\n");
  REQUIRE(g30.motions.size() == 4);
  CHECK(g30.motions[1].point.tip_mm.isApprox(Vec3d(10, 10, 50)));
  CHECK(g30.motions[2].point.tip_mm.isApprox(Vec3d(10, 10, 400)));
  CHECK(g30.motions[3].point.tip_mm.isApprox(Vec3d(0, 0, 400)));
  // after G28 X Y the next motion need not program them: they are known
  const Read next = read("G21 G90\nG0 X10 Y10 Z5 A0 C0\nG91 G28 X0 Y0\nG90 G0 Z20\nM30\n");
  REQUIRE(next.motions.size() == 3);
  CHECK(next.motions[2].point.tip_mm.isApprox(Vec3d(-400, 450, 20)));
}

TEST_CASE("gcode reference: G53 counts from the reference point; a rotary axis returns too") {
  const Read r = read("G21 G90\nG0 X10 Y10 Z5 A0 C0\nG53 G0 X-100 Z-10\nM30\n");
  REQUIRE(r.motions.size() == 2);
  CHECK(r.motions[1].point.tip_mm.isApprox(Vec3d(-500, 10, 540)));  // -400 - 100, 550 - 10
  // G28 A0 with A at 30 deg: A to its reference (0); the machine X Y Z stay (0, 0, 100)
  const Read a = read("G21 G90\nG0 X0 Y0 Z100 A30 C0\nG91 G28 A0\nG90\nM30\n");
  REQUIRE(a.motions.size() == 2);
  CHECK(a.motions[0].point.tip_mm.isApprox(unturn_a(30, Vec3d(0, 0, 100))));
  CHECK(a.motions[1].point.tip_mm.isApprox(Vec3d(0, 0, 100)));
  REQUIRE(a.motions[1].rotary_rad);
  CHECK(std::abs((*a.motions[1].rotary_rad)[0]) < 1e-12);
}

TEST_CASE("gcode reference: a tool-tip program returns through the kinematics") {
  // under G43.4 the tip is at (0, 0, 20) with A30; after G49 and the returns the machine stands at
  // X -400 Y 450 Z 550 with A still 30: the tip in W is Rot(x, -30°)·(-400, 450, 550)
  const Read r = read("G21 G90 G94\nG43.4 H1\nG0 X0 Y0 Z20 A30 C0\nG49\nG91 G28 Z0\nG28 X0 Y0\nG90\nM30\n");
  REQUIRE(r.motions.size() == 3);
  CHECK((r.motions[0].point.tip_mm - Vec3d(0, 0, 20)).norm() < 1e-9);
  CHECK((r.motions[2].point.tip_mm - unturn_a(30, Vec3d(-400, 450, 550))).norm() < 1e-6);
}

TEST_CASE("gcode reference: without the keys the refusals name them") {
  // ac-trunnion gives no references: G30 is refused naming reference2
  const InputError g30 = error_of("G21 G90\nG0 X10 Y10 Z5 A0 C0\nG30 Z50\nM30\n", test::ac_trunnion());
  CHECK(g30.where().line == 3);
  CHECK_THAT(g30.detail(), Catch::Contains("[axes.Z] reference2"));
  // G28 X without a reference: the next motion must program X, the message names the key
  const InputError g28 = error_of("G21 G90\nG0 X10 Y10 Z5 A0 C0\nG91 G28 X0\nG90 G0 Z20\nM30\n", test::ac_trunnion());
  CHECK(g28.where().line == 4);
  CHECK_THAT(g28.detail(), Catch::Contains("[axes.X] reference"));
}

TEST_CASE("gcode reference: a G28/G53 before any position, then a cut that does not place those axes, is refused") {
  // The machine stands at the reference point (or the G53 position) in X and Y when Z plunges: the
  // posted program may not start at X0 Y0 (or anywhere else) instead. Refused at the G28/G53 line,
  // naming the axes and the cut, with or without the machine file's references.
  for (const Machine* m : {&with_references(), &test::ac_trunnion()}) {
    const InputError g28 = error_of(
        "%\nO2\nG21 G90 G17\nT1 M6\nS1000 M3\nG91 G28 X0 Y0\nG90 G0 G43 Z10. H1\nG1 Z-1. F100.\nX20. Y5.\nG0 "
        "Z10.\nM30\n%\n",
        *m);
    CHECK(g28.where().line == 6);
    CHECK_THAT(g28.detail(), Catch::Contains("G28 moves X, Y"));
    CHECK_THAT(g28.detail(), Catch::Contains("the cutting motion at line 8"));
    const InputError g53 =
        error_of("G21 G90\nT1 M6\nG53 G0 G90 X6.6957 Y2.1793\nG0 G43 Z1.35 H1\nZ.1\nG1 Z0. F22.\nM30\n", *m);
    CHECK(g53.where().line == 3);
    CHECK_THAT(g53.detail(), Catch::Contains("G53 moves X, Y"));
  }
  // programmed absolutely again before the cut: read as before (the first values place the start)
  const Read placed = read("G21 G90\nT1 M6\nG91 G28 X0 Y0\nG90 G0 X20 Y5\nG43 Z10 H1\nG1 Z-1 F100\nM30\n");
  REQUIRE(placed.motions.size() == 3);
  CHECK(placed.motions[2].point.tip_mm.isApprox(Vec3d(20, 5, -1)));
  // incremental words after the return do not place the axis
  const InputError incremental =
      error_of("G21 G90\nT1 M6\nG91 G28 X0 Y0\nG91 G0 X20 Y5\nG90 G43 Z10 H1\nG1 Z-1 F100\nM30\n", with_references());
  CHECK(incremental.where().line == 3);
}
