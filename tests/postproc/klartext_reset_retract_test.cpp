// SPDX-License-Identifier: Apache-2.0
// Klartext statements met in hyperMILL programs (issue 28): CYCL DEF 19 that tilts nothing (19.0
// and a 19.1 without angles, the cycle switched off, or with all angles 0, the tilt reset: TNC
// user's manual, "WORKING PLANE (Cycle 19)", resetting) and M140 MB MAX|d on a machine whose head
// tilts (the retract runs along the tool axis until the first linear axis meets its travel's
// end). The expected positions come from the tests' own forward kinematics
// (tests/support/nc_executor.hpp) of machines/head-table-bc.toml (B head about Y, C table; X
// -800 .. 800, Z -700 .. 500), Setup{}: W at M's origin, tool length 0.
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

#include "cl_records.hpp"
#include "nc_executor.hpp"
#include "shipped_machines.hpp"
#include "test_paths.hpp"
#include "ncpost/postproc/read/klartext/klartext_reader.hpp"

using namespace ncpost;

namespace {

using Read = test::MotionsAndNotices;

Read read(const std::string& body, const Machine& machine) {
  std::istringstream in("0 BEGIN PGM T MM\n" + body + "99 END PGM T MM\n");
  klartext::KlartextReader r(in, "t.h", machine, Setup{});
  return test::motions_and_notices(r);
}

std::string error_of(const std::string& body, const Machine& machine) {
  const std::string e = test::input_error_of([&] { read(body, machine); });
  if (e.empty()) FAIL("no input error for: " << body);
  return e;
}

void check_tip(const cl::Motion& m, const Vec3d& expected) {
  INFO("line " << m.where.line << ": tip " << m.point.tip_mm.transpose() << ", expected " << expected.transpose());
  CHECK((m.point.tip_mm - expected).norm() < 1e-9);
}

}  // namespace

TEST_CASE("klartext CYCL DEF 19 without angles or with all 0 tilts nothing; other angles stay refused") {
  const std::string path = "5 L X+10 Y+0 Z+20 R0 FMAX\n6 L X+30 F500\n";
  const Read plain = read("1 TOOL CALL 1 Z S1000\n2 L X+0 Y+0 Z+50 A+0 C+0 R0 FMAX\n" + path, test::ac_trunnion());
  for (const char* reset : {"3 CYCL DEF 19.0 WORKING PLANE\n4 CYCL DEF 19.1\n",
                            "3 CYCL DEF 19.0 PLAN D'USINAGE\n4 CYCL DEF 19.1 A+0 C+0\n"}) {
    INFO(reset);
    const Read r = read("1 TOOL CALL 1 Z S1000\n2 L X+0 Y+0 Z+50 A+0 C+0 R0 FMAX\n" + std::string(reset) + path,
                        test::ac_trunnion());
    REQUIRE(r.motions.size() == plain.motions.size());
    REQUIRE(r.motions.size() == 3);
    for (std::size_t i = 0; i < r.motions.size(); ++i) check_tip(r.motions[i], plain.motions[i].point.tip_mm);
    check_tip(r.motions[2], Vec3d(30, 0, 20));  // A0 C0: the machine words are the tip
    CHECK_THAT(r.notices, Catch::Contains("t.h:5:") && Catch::Contains("CYCL DEF 19.1 with no angles or all 0"));
  }
  const std::string start = "1 L X+0 Y+0 Z+50 A+0 C+0 R0 FMAX\n2 CYCL DEF 19.0 WORKING PLANE\n";
  CHECK_THAT(error_of(start + "3 CYCL DEF 19.1 A-90\n", test::ac_trunnion()),
             Catch::StartsWith("t.h:4:") && Catch::Contains("axis or spatial angles"));
  CHECK_THAT(error_of(start + "3 CYCL DEF 19.1 A+0 F1000\n", test::ac_trunnion()),
             Catch::StartsWith("t.h:4:") && Catch::Contains("positions the rotary axes"));
}

TEST_CASE("klartext M140 MB MAX on a head that tilts: along the tool axis to the first end of travel") {
  const test::ExecMachine em = test::ExecMachine::load(test::source("machines/head-table-bc.toml"));
  const test::ExecJob job;  // W at M's origin, tool length 0
  const std::map<char, double> angles = {{'B', 30.0}, {'C', 0.0}};
  const test::V3 start(0, 0, 100);
  const test::V3 axis = test::forward(em, job, start, angles).axis_W;  // C0: W's axis is M's
  // X may go to +-800, Z to 500: Z meets its end first where |axis.x| / 800 < axis.z / 400
  REQUIRE(std::abs(axis.x()) > 0.4);
  const double along_mm = (500.0 - start.z()) / axis.z();
  REQUIRE(std::abs(start.x() + along_mm * axis.x()) < 800.0);
  const test::V3 top = start + along_mm * axis;
  const test::V3 by_50 = start + 50.0 * axis;

  const std::string head = "1 TOOL CALL 1 Z S1000\n2 L X+0 Y+0 Z+100 B+30 C+0 R0 FMAX\n";
  const Read r = read(head + "3 M140 MB MAX\n", test::head_table_bc());
  REQUIRE(r.motions.size() == 2);
  check_tip(r.motions[1], test::forward(em, job, top, angles).tip_W);
  CHECK(r.motions[1].rapid);
  CHECK((r.motions[1].point.axis - Vec3d(axis)).norm() < 1e-12);
  const Read d = read(head + "3 M140 MB+50\n", test::head_table_bc());
  REQUIRE(d.motions.size() == 2);
  check_tip(d.motions[1], test::forward(em, job, by_50, angles).tip_W);

  // before any position: nothing to retract from (a notice); before B is programmed: refused
  const Read first = read("1 M140 MB MAX\n2 L X+0 Y+0 Z+100 B+0 C+0 R0 FMAX\n", test::head_table_bc());
  CHECK(first.motions.size() == 1);
  CHECK_THAT(first.notices, Catch::Contains("M140 before the first programmed position moves nothing"));
  CHECK_THAT(error_of("1 L X+0 Y+0 Z+100 R0 FMAX\n2 M140 MB MAX\n", test::head_table_bc()),
             Catch::StartsWith("t.h:3:") && Catch::Contains("M140 before B is programmed"));
}
