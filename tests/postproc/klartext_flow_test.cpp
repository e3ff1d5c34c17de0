// SPDX-License-Identifier: Apache-2.0
// The Klartext reader's Q parameters, FN functions, labels, calls and jumps (klartext_q.hpp,
// klartext_flow.hpp), and its refusals by statement. Expected values are worked out by hand from
// the TNC 640 manual's rules (formula precedence, FN 9 jumps, CALL LBL ... REP m runs the section
// m more times, LBL 0 returns from a subprogram).
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

#include "cl_records.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/postproc/read/klartext/klartext_reader.hpp"
#include "shipped_machines.hpp"

using namespace ncpost;
using test::only;

namespace {

std::vector<cl::Motion> motions(const std::string& body) {
  std::istringstream in("0 BEGIN PGM T MM\n" + body + "99 END PGM T MM\n");
  klartext::KlartextReader r(in, "t.h", test::ac_trunnion(), Setup{}, {});
  return only<cl::Motion>(test::all_records(r));
}

std::string error_of(const std::string& body) {
  try {
    motions(body);
  } catch (const InputError& e) {
    return e.what();
  }
  FAIL("no input error for: " << body);
  return {};
}

double x_of(const std::string& assignments) {
  const auto ms = motions("1 L X+0 Y+0 Z+50 A+0 C+0 R0 FMAX\n" + assignments + "50 L X+Q9 FMAX\n");
  REQUIRE(ms.size() == 2);
  return ms[1].point.tip_mm.x();
}

}  // namespace

TEST_CASE("klartext Q formulas: precedence, brackets, functions in degrees, FN 0 .. 8") {
  CHECK(x_of("2 Q9 = 2 + 3 * 4\n") == Approx(14));
  CHECK(x_of("2 Q9 = (2 + 3) * 4\n") == Approx(20));
  CHECK(x_of("2 Q1 = 3\n3 Q2 = 4\n4 Q9 = SQRT(SQ Q1 + SQ Q2) * 2 + SIN(30)\n") == Approx(10.5));
  CHECK(x_of("2 Q9 = 2 ^ 3 - NEG 1 + ABS(-2) + COS 60 + PI\n") == Approx(8 + 1 + 2 + 0.5 + M_PI));
  CHECK(x_of("2 QL5 = 7\n3 Q9 = QL5 / 2\n") == Approx(3.5));
  CHECK(x_of("2 FN 0: Q9 = -12.5\n") == Approx(-12.5));
  CHECK(x_of("2 FN 0: Q1 = +7\n3 FN 1: Q9 = +Q1 + +3\n") == Approx(10));
  CHECK(x_of("2 FN 2: Q9 = +3 - +10\n") == Approx(-7));
  CHECK(x_of("2 FN 3: Q9 = +3 * -4\n") == Approx(-12));
  CHECK(x_of("2 FN 4: Q9 = +9 DIV +4\n") == Approx(2.25));
  CHECK(x_of("2 FN 5: Q9 = SQRT +16\n") == Approx(4));
  CHECK(x_of("2 FN 6: Q9 = SIN +90\n") == Approx(1));
  CHECK(x_of("2 FN 7: Q9 = COS +180\n") == Approx(-1));
  CHECK(x_of("2 FN 8: Q9 = +6 LEN +8\n") == Approx(10));
}

TEST_CASE("klartext FN 9 .. 12 jump to a label; CALL LBL runs a subprogram to LBL 0 and returns") {
  // a loop by FN 12: X = 0, 5, 10, 15 (Q1 < 20 jumps back while Q1 is 5, 10, 15)
  const auto loop = motions(
      "1 L X+0 Y+0 Z+50 A+0 C+0 R0 FMAX\n"
      "2 Q1 = 0\n"
      "3 LBL \"LOOP\"\n"
      "4 Q1 = Q1 + 5\n"
      "5 L X+Q1 F100\n"
      "6 FN 12: IF +Q1 LT +20 GOTO LBL \"LOOP\"\n"
      "7 FN 9: IF +Q1 EQU +20 GOTO LBL 3\n"
      "8 L Y+99\n"  // jumped over
      "9 LBL 3\n"
      "10 CALL LBL 7\n"
      "11 L Y+1\n"
      "12 M30\n"
      "13 LBL 7\n"
      "14 L Z+10\n"
      "15 LBL 0\n");
  std::vector<double> xs;
  for (const auto& m : loop) xs.push_back(m.point.tip_mm.x());
  REQUIRE(loop.size() == 7);
  CHECK(xs == std::vector<double>{0, 5, 10, 15, 20, 20, 20});
  CHECK(loop[5].point.tip_mm.z() == Approx(10));  // the subprogram
  CHECK(loop[5].where.line == 15);                // (its line: block 14 is line 15)
  CHECK(loop[6].point.tip_mm.y() == Approx(1));   // back after the call, Y+99 never run
  // nested section repeats: the inner runs 1 + 1 times per outer pass, the outer 1 + 2 times
  const auto nested = motions(
      "1 L X+0 Y+0 Z+50 A+0 C+0 R0 FMAX\n"
      "2 LBL 1\n"
      "3 LBL 2\n"
      "4 L IX+1 F100\n"
      "5 CALL LBL 2 REP 1\n"
      "6 L IY+1\n"
      "7 CALL LBL 1 REP 2\n");
  REQUIRE(nested.size() == 1 + 3 * 3);
  CHECK(nested.back().point.tip_mm.x() == Approx(6));
  CHECK(nested.back().point.tip_mm.y() == Approx(3));
}

TEST_CASE("klartext program flow refusals name the statement and the chain of calls") {
  const std::string deep = [] {
    std::string s = "1 L X+0 Y+0 Z+50 R0 FMAX\n2 CALL LBL 1\n3 M30\n4 LBL 1\n5 CALL LBL 1\n6 LBL 0\n";
    return s;
  }();
  const std::string e = error_of(deep);
  CHECK_THAT(e, Catch::Contains("CALL LBL 1: subprograms nested deeper than 19"));
  CHECK_THAT(e, Catch::Contains("CALL LBL 1 (line 3) > CALL LBL 1 (line 6)"));
  CHECK_THAT(error_of("1 LBL 5\n2 FN 9: IF +0 EQU +0 GOTO LBL 5\n"),
             Catch::Contains("GOTO LBL 5: more than 1000000 jumps"));
  CHECK_THAT(error_of("1 LBL 5\n2 LBL 5\n"), Catch::Contains("LBL 5 is defined twice (lines 2 and 3)"));
  CHECK_THAT(error_of("1 FN 9: IF +1 EQU +1 GOTO LBL 8\n"),
             Catch::Contains("t.h:2: GOTO LBL 8: LBL 8 is not in the program"));
  CHECK_THAT(error_of("1 L X+0 Y+0 Z+5 R0 FMAX\n2 Q1 = 1 / 0\n"), Catch::Contains("Q1 = 1 / 0"));
  CHECK_THAT(error_of("1 Q1 = (2 + 3\n"), Catch::Contains("a '(' without its ')'"));
  CHECK_THAT(error_of("1 L X+0 Y+0 Z+5 R0 FMAX\n2 L X+Q121 FMAX\n"), Catch::Contains("Q121 is not set"));
}

TEST_CASE("klartext PLANE: the angles of the plane in Q120 .. Q122, refusals by statement") {
  // on the AC trunnion PLANE SPATIAL SPA+30 SPB+0 SPC+0 tilts the tool axis to (0, -1/2, √3/2) =
  // (sin a sin c, sin a cos c, cos a): SEQ+ A = 30, C = 180; SEQ- A = -30, C = 0
  const auto ms = motions(
      "1 L X+0 Y+0 Z+50 A+0 C+0 R0 FMAX\n"
      "2 PLANE SPATIAL SPA+30 SPB+0 SPC+0 STAY SEQ-\n"
      "3 L A+Q120 C+Q122 FMAX\n"
      "4 L X+Q120 Y+Q122 Z+10 FMAX\n");
  REQUIRE(ms.size() == 3);
  REQUIRE(ms[1].rotary_rad);
  CHECK((*ms[1].rotary_rad)[0] == Approx(-30 * M_PI / 180));
  CHECK(std::abs(std::remainder((*ms[1].rotary_rad)[1], 2 * M_PI)) < 1e-9);
  // the tip of line 4 is (-30, 0, 10) in the plane: in W Rx(30) (x, y, z)
  const double y = 0.0, a = 30 * M_PI / 180;
  CHECK(
      (ms[2].point.tip_mm - Vec3d(-30, y * std::cos(a) - 10 * std::sin(a), y * std::sin(a) + 10 * std::cos(a))).norm() <
      1e-9);
  CHECK((ms[2].point.axis - Vec3d(0, -std::sin(a), std::cos(a))).norm() < 1e-12);
  CHECK_THAT(error_of("1 L X+0 Y+0 Z+50 A+0 C+0 R0 FMAX\n2 PLANE SPATIAL SPA+30 SPB+0 SPC+0 STAY\n3 L X+5 F100\n"),
             Catch::Contains("L in a tilted plane (PLANE ...) with the rotary axes not at the plane's angles"));
  CHECK_THAT(error_of("1 L X+0 Y+0 Z+50 R0 FMAX\n2 PLANE SPATIAL SPA+0 SPB+30 SPC+0 MOVE DIST50 F1000\n"),
             Catch::Contains("PLANE SPATIAL MOVE DIST"));
  CHECK_THAT(error_of("1 L X+0 Y+0 Z+50 R0 FMAX\n2 PLANE SPATIAL SPA+0 SPB+130 SPC+0 STAY\n"),
             Catch::Contains("PLANE SPATIAL: no solution for the plane within the rotary travel"));
  CHECK_THAT(error_of("1 L X+0 Y+0 Z+50 R0 FMAX\n2 M128\n3 PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY\n"),
             Catch::Contains("PLANE SPATIAL under M128"));
  // TABLE ROT with the tool axis along C: the table takes SPC. R_w = Rz(c) and the tool frame R_wᵀ = Rz(-c)
  // must be Rz(30): C = -30. COORD ROT leaves C where it is (here 10) and rotates the coordinates.
  for (const char* rot : {"TABLE ROT", "COORD ROT"}) {
    const auto turned =
        motions(std::string("1 L X+0 Y+0 Z+50 A+0 C+10 R0 FMAX\n2 PLANE SPATIAL SPA+0 SPB+0 SPC+30 STAY ") + rot +
                "\n3 L A+Q120 C+Q122 FMAX\n4 L X+10 Y+0 Z+5 FMAX\n");
    REQUIRE(turned.size() == 3);
    CHECK((*turned[1].rotary_rad)[1] == Approx((std::string(rot) == "TABLE ROT" ? -30 : 10) * M_PI / 180));
    // either way X of the plane is Rz(30) e_x in W
    CHECK((turned[2].point.tip_mm - Vec3d(10 * std::cos(M_PI / 6), 10 * std::sin(M_PI / 6), 5)).norm() < 1e-9);
  }
}

TEST_CASE(
    "klartext in a tilted plane: CYCL DEF 200 drills along the plane's Z; a datum shift there holds every motion") {
  // PLANE SPATIAL SPA+0 SPB+0 SPC+90: the plane's X is W's Y; the hole at X+10 Y+0 of the plane is at
  // W (0, 10), its top at the plane's Z+1 = W Z+1 (Q203); Q206=Q7 takes the feed from Q7
  const auto ms = motions(
      "1 L X+0 Y+0 Z+50 A+0 C+0 R0 FMAX\n"
      "2 Q7 = 150\n"
      "3 PLANE SPATIAL SPA+0 SPB+0 SPC+90 STAY\n"
      "4 L A+Q120 C+Q122 FMAX\n"
      "5 L X+10 Y+0 Z+20 FMAX\n"
      "6 CYCL DEF 200 DRILLING ~\n"
      "  Q200=+2 ;SET-UP CLEARANCE ~\n"
      "  Q201=-15 ;DEPTH ~\n"
      "  Q206=Q7 ;FEED RATE FOR PLNGNG ~\n"
      "  Q202=+5 ;PLUNGING DEPTH ~\n"
      "  Q210=+0 ;DWELL TIME AT TOP ~\n"
      "  Q203=+1 ;SURFACE COORDINATE ~\n"
      "  Q204=+20 ;2ND SET-UP CLEARANCE ~\n"
      "  Q211=+0 ;DWELL TIME AT DEPTH ~\n"
      "  Q395=+0 ;DEPTH REFERENCE\n"
      "7 CYCL CALL\n");
  REQUIRE(ms.size() == 4);
  CHECK((ms[3].point.tip_mm - Vec3d(0, 10, 1)).norm() < 1e-9);
  CHECK((ms[3].point.axis - Vec3d(0, 0, 1)).norm() < 1e-12);
  // CYCL DEF 7 inside the plane (as CAM systems reset the datum before PLANE RESET): nothing may move
  // until PLANE RESET; then the shift applies to the machine's X Y Z words again
  const std::string shifted =
      "1 L X+0 Y+0 Z+50 A+0 C+0 R0 FMAX\n"
      "2 PLANE SPATIAL SPA+0 SPB+0 SPC+0 STAY\n"
      "3 CYCL DEF 7.0 DATUM SHIFT\n"
      "4 CYCL DEF 7.1 X+5\n";
  CHECK_THAT(error_of(shifted + "5 L X+1 FMAX\n"),
             Catch::Contains("a motion after CYCL DEF 7 changed the datum shift inside"));
  const auto after = motions(shifted + "5 PLANE RESET STAY\n6 L X+1 Y+0 Z+50 FMAX\n");
  REQUIRE(after.size() == 2);
  CHECK((after[1].point.tip_mm - Vec3d(6, 0, 50)).norm() < 1e-9);
}
