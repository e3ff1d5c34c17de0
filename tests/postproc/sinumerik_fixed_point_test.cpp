// SPDX-License-Identifier: Apache-2.0
// Sinumerik G75 FP=n, the fixed point approach (SINUMERIK 840D sl Programming Manual Fundamentals,
// "Fixed-point approach (G75)"): the named machine axes go at rapid traverse to fixed point n of the
// control's machine data (MD30600 $MA_FIX_POINT_POS[n-1]; FP=1 where FP= is not written), the values
// written for the axes are not used, the other axes stay. The machine file gives the points as
// `fixed_point` (tests/data/machines/ac-trunnion-references.toml, made-up values: X -420/250,
// Y 470/-150, Z 580/450, A 0/-45, C none; references X -400, Y 450, Z 550, A 0, C 0). Expected
// positions by hand: on the AC trunnion with W at M's origin and tool length 0, at A0 C0 the tip
// in W is the machine's X Y Z (docs/conventions.md, "Nominal closure").
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

#include "cl_records.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/machine/serial_post_machine.hpp"
#include "ncpost/postproc/post_request.hpp"
#include "ncpost/postproc/read/sinumerik/sinumerik_reader.hpp"
#include "ncpost/postproc/write/dialect.hpp"
#include "shipped_machines.hpp"
#include "sinumerik_reposted.hpp"
#include "test_paths.hpp"

using namespace ncpost;

namespace {

const std::string kMachineFile = test::data("machines/ac-trunnion-references.toml");

const Machine& with_fixed_points() {
  static const Machine m = load_machine(kMachineFile);
  return m;
}

std::vector<cl::Motion> motions(const std::string& text, const Machine& m = with_fixed_points()) {
  std::istringstream in(text);
  sinumerik::SinumerikReader r(in, "t.mpf", m, Setup{});
  return test::only<cl::Motion>(test::all_records(r));
}

InputError error_of(const std::string& text, const Machine& m = with_fixed_points()) {
  try {
    motions(text, m);
  } catch (const InputError& e) {
    return e;
  }
  FAIL("no error for: " << text);
  throw;
}

InputError machine_error(const std::string& axis_x_keys) {
  const std::string text = "[machine]\nname = \"t\"\nchain = \"w b X Y Z t\"\n[axes.X]\ntype = \"linear\"\n" +
                           axis_x_keys + "\n[axes.Y]\ntype = \"linear\"\n[axes.Z]\ntype = \"linear\"\n";
  try {
    parse_machine(text, "t.toml");
  } catch (const InputError& e) {
    return e;
  }
  FAIL("no error for: " << axis_x_keys);
  throw;
}

}  // namespace

TEST_CASE("sinumerik G75: the machine file reads fixed_point per axis, in the axis's unit, and checks it") {
  const Machine& m = with_fixed_points();
  CHECK(m.axes[0].fixed_points == std::vector<double>{-420, 250});
  CHECK(m.axes[2].fixed_points == std::vector<double>{580, 450});
  REQUIRE(m.axes[3].fixed_points.size() == 2);
  CHECK(m.axes[3].fixed_points[1] == Approx(-M_PI / 4));  // A: -45 deg
  CHECK(m.axes[4].fixed_points.empty());
  CHECK_THAT(machine_error("limits = [-500, 500]\nfixed_point = [0, 600]").detail(),
             Catch::Contains("fixed_point[2]: 600 lies outside the axis's limits"));
  CHECK_THAT(machine_error("fixed_point = [1, 2, 3, 4, 5]").detail(), Catch::Contains("an array of 1 to 4 numbers"));
  CHECK_THAT(machine_error("fixed_point = 3").detail(), Catch::Contains("an array of 1 to 4 numbers"));
}

TEST_CASE("sinumerik G75: the named axes go to the machine file's fixed point FP (1 without FP=), the others stay") {
  const std::vector<cl::Motion> ms = motions(
      "N10 G0 G90 G17 G71 X10 Y20 Z30 A0 C0\n"
      "N20 G1 Z5 F300\n"
      "N30 G75 Z0\n"
      "N40 G75 FP=2 X123 Y0\n"
      "N50 X15\n"
      "N60 M30\n");
  REQUIRE(ms.size() == 5);
  CHECK((ms[2].point.tip_mm - Vec3d(10, 20, 580)).norm() < 1e-9);     // Z to fixed point 1; X Y stay
  CHECK((ms[3].point.tip_mm - Vec3d(250, -150, 580)).norm() < 1e-9);  // X Y to fixed point 2, 123 and 0 unused
  CHECK(ms[2].rapid);
  CHECK(ms[3].rapid);
  // G75 does not change the modal G0..G3: N50 feeds again (G1 of N20)
  CHECK_FALSE(ms[4].rapid);
  CHECK((ms[4].point.tip_mm - Vec3d(15, -150, 580)).norm() < 1e-9);
}

TEST_CASE("sinumerik G75: refused without the machine file's fixed point, FP beyond 4, under TRAORI, beside a move") {
  const std::string head = "N10 G0 G90 G71 X10 Y20 Z30 A0 C0\n";
  const InputError none = error_of(head + "N20 G75 Z0\nM30\n", test::ac_trunnion());
  CHECK(none.where().line == 2);
  CHECK_THAT(none.detail(), Catch::Contains("[axes.Z] fixed_point"));
  CHECK_THAT(error_of(head + "N20 G75 FP=3 Z0\nM30\n").detail(), Catch::Contains("fixed point 3 of Z"));
  CHECK_THAT(error_of(head + "N20 G75 FP=5 Z0\nM30\n").detail(), Catch::Contains("1, 2, 3 or 4"));
  CHECK_THAT(error_of(head + "N20 G75 C0\nM30\n").detail(), Catch::Contains("fixed point 1 of C"));
  CHECK_THAT(error_of(head + "TRAORI\nN20 G75 Z0\nM30\n").detail(), Catch::Contains("TRAFOOF"));
  CHECK_THAT(error_of(head + "N20 G75 G1 Z0\nM30\n").detail(), Catch::Contains("a block of its own"));
  CHECK_THAT(error_of(head + "N20 G0 FP=2 Z0\nM30\n").detail(), Catch::Contains("FP= without G75"));
  CHECK_THAT(error_of(head + "N20 G75\nM30\n").detail(), Catch::Contains("without axis words"));
}

TEST_CASE("sinumerik G75 re-posted: executed input (the tests' interpreter) against output, with G53 and SUPA") {
  const std::string text =
      "%_N_FP_MPF\n"
      "N10 G0 G17 G90 G71 X10 Y20 Z30 A0 C0 S3000 M3 D1\n"
      "N20 G1 Z5 F300\n"
      "N30 G2 X30 Y40 CR=20\n"
      "N40 G3 X10 Y20 CR=-20\n"
      "N50 G75 Z0\n"
      "N60 G75 FP=2 X0 Y0 A0\n"
      "N70 G0 A-30 C45\n"
      "N80 G0 G53 Z-20\n"
      "N90 G0 SUPA X5 D0\n"
      "N100 D1\n"
      "N110 TRAORI\n"
      "N120 G1 X0 Y0 Z40 A-20 C10\n"
      "N130 TRAFOOF\n"
      "N140 M30\n";
  PostRequest r;
  r.machine = serial_post_machine(with_fixed_points());
  r.setup.workpiece_origin_mm = Vec3d(0, 0, -400);
  r.dialect = dialect_named("fanuc");
  r.threads = 1;
  r.input_name = "fp.mpf";
  std::istringstream in(text);
  std::ostringstream out;
  post(in, out, r);
  INFO(out.str());
  test::ExecJob job;
  job.workpiece_origin_mm = test::V3(0, 0, -400);
  const test::SinumerikRepostCheck c = test::compare_sinumerik_reposted(text, kMachineFile, job, out.str());
  INFO(c.failure);
  CHECK(c.failure.empty());
  CHECK(c.ends >= 10);       // N10 .. N90 and N120, each end reached
  CHECK(c.samples > 0);      // the feeds N20 .. N40 and N120 sampled between their ends
  CHECK(c.angle_ends == 1);  // N120's A-20 C10 written as the program gives them
  // the tests' interpreter's own ends: N50 at machine Z 580, N60 at X 250 Y -150 and A -45 (fixed point 2),
  // N80 at Z 550 - 20 (G53 counts from the reference), N90 at X -400 + 5
  const test::ExecMachine m = test::ExecMachine::load(kMachineFile);
  const auto ends = test::sinumerik_block_ends(text, m, job);
  const auto end_of = [&](int line) {
    for (const auto& e : ends)
      if (e.line == line) return e;
    FAIL("no end at line " << line);
    throw;
  };
  CHECK((end_of(6).tip_W - test::V3(10, 20, 980)).norm() < 1e-9);
  const test::V3 at_fp2 = test::forward(m, job, test::V3(250, -150, 580), {{'A', -45.0}, {'C', 0.0}}).tip_W;
  CHECK((end_of(7).tip_W - at_fp2).norm() < 1e-9);
  const test::V3 at_g53 = test::forward(m, job, test::V3(250, -150, 530), {{'A', -30.0}, {'C', 45.0}}).tip_W;
  CHECK((end_of(9).tip_W - at_g53).norm() < 1e-9);
  const test::V3 at_supa = test::forward(m, job, test::V3(-395, -150, 530), {{'A', -30.0}, {'C', 45.0}}).tip_W;
  CHECK((end_of(10).tip_W - at_supa).norm() < 1e-9);
}
