// SPDX-License-Identifier: Apache-2.0
// The Sinumerik reader (sinumerik_reader.hpp): each construct read into CL records on the AC
// trunnion (Setup{}: W at the table's centre, tool length 0, so that at A0 C0 the machine words
// are the tool tip). Expected positions are worked out here from the SINUMERIK 840D sl
// programming manual's rules (variables, IC/AC, frames, program flow), never taken from the reader.
#include <catch2/catch.hpp>

#include <cmath>
#include <optional>
#include <sstream>

#include "cl_records.hpp"
#include "shipped_machines.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/postproc/read/sinumerik/sinumerik_reader.hpp"

using namespace ncpost;
using test::only;

namespace {

struct Read {
  std::vector<cl::Record> records;
  std::vector<std::string> notices;
};

Read read(const std::string& text) {
  std::istringstream in(text);
  sinumerik::ReaderOptions o;
  o.gcode.circles = true;  // single-turn planar arcs as cl::Circle, as the post asks for
  sinumerik::SinumerikReader r(in, "t.mpf", test::ac_trunnion(), Setup{}, o);
  Read out;
  out.records = test::all_records(r);
  out.notices = r.take_notices();
  return out;
}

std::vector<cl::Motion> motions(const std::string& text) { return only<cl::Motion>(read(text).records); }

std::string error_of(const std::string& text) {
  try {
    read(text);
  } catch (const InputError& e) {
    return e.what();
  }
  FAIL("no input error for: " << text);
  return {};
}

void check_tip(const cl::Motion& m, double x, double y, double z) {
  INFO("line " << m.where.line);
  CHECK(m.point.tip_mm.x() == Approx(x).margin(1e-9));
  CHECK(m.point.tip_mm.y() == Approx(y).margin(1e-9));
  CHECK(m.point.tip_mm.z() == Approx(z).margin(1e-9));
}

}  // namespace

TEST_CASE("sinumerik: DEF, R parameters, expressions, X=IC()/AC(), G91, comments and block numbers") {
  const std::string text =
      "%_N_VARS_MPF\n"
      ";$PATH=/_N_MPF_DIR\n"
      "N10 DEF REAL _DEPTH=-2.5, _W\n"
      "N20 DEF INT COUNT=2.6\n"  // INT rounds: 3
      "N30 R1=10 R2=R1*2+SIN(30)*2 ; R2 = 21\n"
      "N40 _W=(R2-R1)/2\n"  // 5.5
      "N50 G17 G90 G71 G94 T1 M6\n"
      "N60 G0 X=R1 Y=R2 Z=50 A0 C0 S1000 M3\n"
      "N70 G1 Z=_DEPTH F=100*COUNT\n"
      "N80 X=IC(_W) Y=AC(0)\n"
      "N90 G91 X-1 Y2\n"
      "N100 G90 X=COUNT*10 MSG(\"DONE\")\n"
      "N110 M30\n";
  const Read r = read(text);
  const auto m = only<cl::Motion>(r.records);
  REQUIRE(m.size() == 5);
  check_tip(m[0], 10, 21, 50);
  check_tip(m[1], 10, 21, -2.5);
  check_tip(m[2], 15.5, 0, -2.5);
  check_tip(m[3], 14.5, 2, -2.5);
  check_tip(m[4], 30, 2, -2.5);
  CHECK(m[0].where.line == 8);
  CHECK(m[4].where.line == 12);
  const auto feeds = only<cl::Feed>(r.records);
  REQUIRE(!feeds.empty());
  CHECK(feeds.front().value == Approx(300.0));
  bool comment = false;
  for (const auto& c : only<cl::Comment>(r.records)) comment = comment || c.text.find("R2 = 21") != std::string::npos;
  CHECK(comment);
  CHECK(only<cl::ToolChange>(r.records).at(0).number == 1);
}

TEST_CASE("sinumerik: IF/ELSE, FOR, WHILE, REPEAT, LOOP with GOTOF, GOTOB and labels") {
  const std::string text =
      "DEF INT II, KK\n"
      "G0 G90 X0 Y0 Z10 A0 C0\n"
      "FOR II=1 TO 3\n"
      "  G1 X=II*10 F200\n"
      "ENDFOR\n"
      "IF II>=3\n"
      "  Y5\n"
      "ELSE\n"
      "  Y-5\n"
      "ENDIF\n"
      "KK=0\n"
      "WHILE KK<2\n"
      "  KK=KK+1\n"
      "  Z=10-KK\n"
      "ENDWHILE\n"
      "REPEAT\n"
      "  KK=KK+1\n"
      "UNTIL KK>=4\n"
      "X=KK\n"
      "LOOP\n"
      "  KK=KK+1\n"
      "  IF KK>5 GOTOF OUT\n"
      "ENDLOOP\n"
      "OUT: Y=KK\n"
      "R5=0\n"
      "BACK: R5=R5+1\n"
      "IF R5<3 GOTOB BACK\n"
      "X=R5*100\n"
      "M30\n";
  const auto m = motions(text);
  std::vector<std::array<double, 3>> expected;
  expected.push_back({0, 0, 10});
  for (int i = 1; i <= 3; ++i) expected.push_back({10.0 * i, 0, 10});
  expected.push_back({30, 5, 10});
  expected.push_back({30, 5, 9});
  expected.push_back({30, 5, 8});
  expected.push_back({4, 5, 8});  // REPEAT until K reaches 4
  expected.push_back({4, 6, 8});  // LOOP leaves at K = 6
  expected.push_back({300, 6, 8});
  REQUIRE(m.size() == expected.size());
  for (std::size_t i = 0; i < m.size(); ++i) check_tip(m[i], expected[i][0], expected[i][1], expected[i][2]);
}

TEST_CASE(
    "sinumerik: subprograms in the same file: L<n>, PROC with parameters, CALL, RET, M17; the chain in messages") {
  const std::string text =
      "%_N_MAIN_MPF\n"
      "G0 G90 X0 Y0 Z5 A0 C0\n"
      "R1=2\n"
      "L100\n"
      "SQUARE(20, 3)\n"
      "CALL \"SQUARE\"\n"
      "X=R1\n"
      "M30\n"
      "%_N_L100_SPF\n"
      "G1 X7 F100\n"
      "R1=R1+1\n"
      "M17\n"
      "%_N_SQUARE_SPF\n"
      "PROC SQUARE(REAL SIDE, INT TIMES)\n"
      "Y=SIDE+TIMES\n"
      "RET\n";
  const auto m = motions(text);
  REQUIRE(m.size() == 5);
  check_tip(m[0], 0, 0, 5);
  check_tip(m[1], 7, 0, 5);
  check_tip(m[2], 7, 23, 5);
  check_tip(m[3], 7, 0, 5);  // CALL without arguments: SIDE and TIMES are 0
  check_tip(m[4], 3, 0, 5);  // R1 set in L100 stays (R parameters are global)
  CHECK(m[1].where.line == 10);

  const std::string deep =
      "G0 X0 Y0 Z5 A0 C0\n"
      "SUBA\n"
      "M30\n"
      "PROC SUBA\n"
      "G1 X=UNKNOWN F100\n"
      "RET\n";
  const std::string e = error_of(deep);
  CHECK_THAT(e, Catch::Contains("t.mpf:5:"));
  CHECK_THAT(e, Catch::Contains("UNKNOWN"));
  CHECK_THAT(e, Catch::Contains("in SUBA called at line 2"));

  const std::string endless = "G0 X0 Y0 Z5 A0 C0\nREC\nM30\nPROC REC\nREC\nRET\n";
  CHECK_THAT(error_of(endless), Catch::Contains("more than 16 subprogram levels"));
}

TEST_CASE("sinumerik: TRANS, ATRANS, ROT, AROT and SCALE frames place the program in W") {
  const std::string text =
      "G0 G90 X0 Y0 Z20 A0 C0\n"
      "TRANS X10 Y5\n"
      "G1 X1 Y1 F100\n"  // (11, 6)
      "AROT Z90\n"       // rotated about Z by 90 deg around (10, 5)
      "X2 Y0\n"          // (10, 7)
      "ATRANS X1\n"      // shift along the rotated X: (10, 6) is the new origin
      "X0 Y0\n"          // (10, 6)
      "ROT Z-90\n"       // replaces the frame: only the rotation
      "X0 Y3\n"          // (3, 0)
      "SCALE X2 Y2 Z2\n"
      "X1 Y1 Z5\n"  // (2, 2, 10)
      "TRANS\n"
      "X0 Y0\n"  // no frame: (0, 0, 10)
      "M30\n";
  const auto m = motions(text);
  REQUIRE(m.size() == 7);
  check_tip(m[1], 11, 6, 20);
  check_tip(m[2], 10, 7, 20);
  check_tip(m[3], 10, 6, 20);
  check_tip(m[4], 3, 0, 20);
  check_tip(m[5], 2, 2, 10);
  check_tip(m[6], 0, 0, 10);
}

TEST_CASE("sinumerik: G2/G3 with I J, AC() centres and CR=, in a frame rotated about the plane's normal") {
  const std::string text =
      "G0 G90 G17 X10 Y0 Z0 A0 C0\n"
      "G3 X0 Y10 I-10 J0 F100\n"
      "G2 X10 Y0 I=AC(0) J=AC(0)\n"
      "G3 X0 Y10 CR=10\n"
      "ROT Z90\n"
      "G1 X10 Y0\n"         // (0, 10) in W
      "G2 X0 Y-10 CR=10\n"  // in W: to (10, 0) clockwise about (0, 0)
      "M30\n";
  const Read r = read(text);
  const auto m = only<cl::Motion>(r.records);
  const auto circles = only<cl::Circle>(r.records);
  REQUIRE(circles.size() == 4);
  for (const auto& c : circles) {
    CHECK(c.center_mm.norm() == Approx(0.0).margin(1e-9));
    CHECK(c.radius_mm == Approx(10.0));
  }
  CHECK(circles[0].axis.z() > 0.5);
  CHECK(circles[1].axis.z() < -0.5);
  check_tip(m.back(), 10, 0, 0);
}

TEST_CASE("sinumerik: an arc in a frame tilted out of its plane becomes points on the circle in W") {
  // ROT X90: the program's (x, y, z) is (x, -z, y) in W, so the quarter circle in the program's
  // X Y plane about (0, 0) runs from (10, 0, 0) to (0, 0, 10) in W's X Z plane
  const std::string text =
      "G0 G90 G17 X10 Y0 Z0 A0 C0\n"
      "ROT X90\n"
      "G3 X0 Y10 I-10 J0 F100\n"
      "M30\n";
  const Read r = read(text);
  CHECK(only<cl::Circle>(r.records).empty());
  const auto m = only<cl::Motion>(r.records);
  REQUIRE(m.size() > 10);
  for (std::size_t i = 1; i < m.size(); ++i) {
    INFO("point " << i);
    CHECK(m[i].point.tip_mm.norm() == Approx(10.0).margin(1e-9));
    CHECK(m[i].point.tip_mm.y() == Approx(0.0).margin(1e-9));
    CHECK(m[i].where.line == 3);
  }
  check_tip(m.back(), 0, 0, 10);
}

TEST_CASE(
    "sinumerik: D0 (no tool offset) before a cut is refused; the G-code reader's messages name the Sinumerik line") {
  const std::string e = error_of("R1=5\nG0 X0 Y0 Z10 A0 C0\nD0\nR2=1\nG1 X=R1 F100\nM30\n");
  CHECK_THAT(e, Catch::Contains("t.mpf:5:"));
  CHECK_THAT(e, Catch::Contains("D0"));
  // beyond X's travel (500 mm): found by the G-code reader on its own block, named at line 4 here
  std::string limit;
  try {
    read("G0 X0 Y0 Z10 A0 C0\nR1=2\nDEF REAL _UNUSED\nG1 X=600*R1 F100\nM30\n");
  } catch (const Infeasible& x) {
    limit = x.what();
  }
  CHECK_THAT(limit, Catch::StartsWith("t.mpf:4:"));
}

TEST_CASE("sinumerik: TRAORI with A3= B3= C3= gives the tool axis in W and the rotary angles that reach it") {
  const double s = std::sqrt(0.5);
  const std::string text =
      "G0 G90 X0 Y0 Z50 A0 C0\n"
      "TRAORI\n"
      "G1 X10 Y0 Z20 A3=0 B3=-0.5 C3=0.5 F500\n"
      "X20 A3=1 B3=0 C3=1\n"
      "TRAFOOF\n"
      "M30\n";
  const auto m = motions(text);
  REQUIRE(m.size() == 3);
  check_tip(m[1], 10, 0, 20);
  CHECK(m[1].point.axis.isApprox(Vec3d(0, -s, s), 1e-12));
  check_tip(m[2], 20, 0, 20);
  CHECK(m[2].point.axis.isApprox(Vec3d(s, 0, s), 1e-12));
  // the angles: the AC table tilts the part, so the axis (0, -s, s) in W is A = +-45 deg, C = 0 or 180
  REQUIRE(m[1].rotary_rad);
  REQUIRE(m[1].rotary_rad->size() == 2);
  CHECK(std::abs((*m[1].rotary_rad)[0]) * 180 / M_PI == Approx(45.0));
}

TEST_CASE("sinumerik: CYCLE81 and MCALL CYCLE82 drill where the tool stands, as cycles or as their motions") {
  // RTP 20, RFP 0, SDIS 2: rapid to Z2, feed to the depth (DP -5; DPR 3: -3), dwell DTB, rapid to Z20
  const std::string text =
      "G0 G90 X0 Y0 Z20 A0 C0 F100\n"
      "CYCLE81(20, 0, 2, -5)\n"
      "MCALL CYCLE82(20, 0, 2, , 3, 0.5)\n"
      "X10\n"
      "Y10\n"
      "MCALL\n"
      "X0 Y0\n"
      "G0 Z50\n"
      "CYCLE81(20, 0, 2, -5)\n"  // the tool above RTP: straight down to Z2, not to RTP first
      "M30\n";
  const Read r = read(text);
  struct Hole {
    double x, y, bottom, top, dwell;
  };
  std::vector<Hole> holes;
  std::optional<cl::Cycle> cycle;
  for (const auto& rec : r.records) {
    if (const auto* c = std::get_if<cl::Cycle>(&rec))
      cycle = c->kind == cl::Cycle::Kind::off ? std::nullopt : std::optional(*c);
    const auto* m = std::get_if<cl::Motion>(&rec);
    if (!m || !cycle) continue;
    const Vec3d& p = m->point.tip_mm;
    holes.push_back({p.x(), p.y(), p.z() - cycle->depth_mm, p.z() + cycle->retract_mm.value_or(cycle->rapid_to_mm),
                     cycle->dwell_s});
    cycle.reset();
  }
  const std::vector<Hole> expected = {{0, 0, -5, 20, 0}, {10, 0, -3, 20, 0.5}, {10, 10, -3, 20, 0.5}};
  REQUIRE(holes.size() == expected.size());
  for (std::size_t i = 0; i < holes.size(); ++i) {
    INFO("hole " << i);
    CHECK(holes[i].x == Approx(expected[i].x).margin(1e-9));
    CHECK(holes[i].y == Approx(expected[i].y).margin(1e-9));
    CHECK(holes[i].bottom == Approx(expected[i].bottom).margin(1e-9));
    CHECK(holes[i].top == Approx(expected[i].top).margin(1e-9));
    CHECK(holes[i].dwell == Approx(expected[i].dwell));
  }
  const auto m = only<cl::Motion>(r.records);
  REQUIRE(m.size() >= 4);
  const std::size_t n = m.size();
  check_tip(m[n - 4], 0, 0, 50);
  check_tip(m[n - 3], 0, 0, 2);
  check_tip(m[n - 2], 0, 0, -5);
  check_tip(m[n - 1], 0, 0, 20);
  CHECK(m[n - 3].rapid);
  CHECK_FALSE(m[n - 2].rapid);
  CHECK(m[n - 1].rapid);
}

TEST_CASE("sinumerik: what is not read is refused by name with its line, never a character-level error") {
  struct Case {
    std::string text;
    std::string expected;
    int line;
  };
  const std::vector<Case> cases = {
      {"G0 X0 Y0 Z0\nT=\"\" M6\nM30\n", "expected a tool name between quotes", 2},
      {"G0 X0 Y0 Z0\nMIRROR X0\nM30\n", "MIRROR is not read", 2},
      {"G0 X0 Y0 Z0\nCYCLE84(10,0,2,-5)\nM30\n", "CYCLE84: SDAC=0 (the spindle after the cycle", 2},
      {"G0 X0 Y0 Z0\nG505\nM30\n", "G505: a settable work offset beyond G57 is not read", 2},
      {"G0 X0 Y0 Z0\nR1=$AA_IM[X]\nM30\n", "$AA_IM is a system variable", 2},
      {"DEF REAL AA\nIF AA==1 AND AA==2\nENDIF\nM30\n", "Sinumerik binds comparisons last", 2},
      {"G0 X0 Y0 Z0\nCIP X1 Y1 I1=0 J1=1\nM30\n", "CIP (a circle through an intermediate point) is not read", 2},
      {"G0 X0 Y0 Z0\nWHILE 1\nM30\n", "WHILE without its ENDWHILE", 2},
      {"G0 X0 Y0 Z0\nGOTOF NOWHERE\nM30\n", "no label NOWHERE", 2},
      {"G0 X0 Y0 Z0\nCYCLE800(0,\"TC\",0,64,0,0,0,10,20,30,0,0,0,1)\nM30\n", "CYCLE800 _MODE=64", 2},
      {"G0 X0 Y0 Z0\nCYCLE800(0,\"TC\",0,24,0,0,0,10,20,30,0,0,0,1)\nM30\n", "axis 1 of the sequence is not set", 2},
      {"G0 X0 Y0 Z0\nG1 X=FOO F1\nM30\n", "FOO is not a defined variable", 2},
      {"G0 X0 Y0 Z0\nH5\nM30\n", "H (an auxiliary function", 2},
      {"DEF INT K\nM30\n", "DEF K: a name starts with two letters", 1},
      {"G0 X0 Y0 Z9 F100\nCYCLE86(10,0,2,-5,,0,3,0.2,0,0,0)\nM30\n", "CYCLE86 with a lift-off", 2},
      {"G0 X0 Y0 Z9 F100\nCYCLE83(10,0,2,-20,,-5,,-0.8,0,0,1,1)\nM30\n",
       "CYCLE83 DAM=-0.8: a negative degression is not read", 2},
      {"G0 X0 Y0 Z9 F100\nCYCLE83(10,0,2,-20,,-5,,1,0,0,1,2)\nM30\n", "CYCLE83 VARI=2", 2},
      {"G0 X0 Y0 Z9 F100\nCYCLE83(10,0,2,-20,,-25,,1,0,0,1,1)\nM30\n", "first depth -25 lies below", 2},
      {"G0 X0 Y0 Z9\nCYCLE85(10,0,2,-5,,0,100,200)\nM30\n", "CYCLE85 before any F", 2},
      {"G0 X0 Y0 Z9 F100\nCYCLE85(10,0,2,-5,,0,0,200)\nM30\n", "CYCLE85: FFR=0", 2},
      {"G0 X0 Y0 Z9 F100\nG18\nCYCLE81(10,0,2,-5)\nM30\n", "CYCLE81 under G18", 3},
      {"G0 X0 Y0 Z9 F100\nMCALL CYCLE87(10,0,2,-5)\nM30\n", "other than CYCLE81, 82, 83, 84, 840, 85 or 86", 2},
  };
  for (const Case& c : cases) {
    INFO(c.text);
    const std::string e = error_of(c.text);
    CHECK_THAT(e, Catch::Contains(c.expected));
    CHECK_THAT(e, Catch::Contains("t.mpf:" + std::to_string(c.line) + ":"));
    CHECK_THAT(e, !Catch::Contains("expected a number"));
  }
}

TEST_CASE("sinumerik: SOFT, FFWON, COMPCAD, CYCLE832, G642, WORKPIECE are noted and not refused") {
  const Read r = read(
      "SOFT FFWON COMPCAD G642\nCYCLE832(0.01,_FINISH,1)\nWORKPIECE(,,,\"BOX\",112,102,0,-80,0,0,102,102)\n"
      "G0 X0 Y0 Z0 A0 C0\nM30\n");
  CHECK(only<cl::Motion>(r.records).size() == 1);
  std::string all;
  for (const auto& n : r.notices) all += n + "\n";
  for (const char* w : {"SOFT", "FFWON", "COMPCAD", "G642", "CYCLE832", "WORKPIECE"})
    CHECK_THAT(all, Catch::Contains(w));
}

TEST_CASE("sinumerik: detection by the language's own constructs, not by ISO words") {
  CHECK(sinumerik::looks_like_sinumerik("%_N_PART_MPF\nG0 X0\n"));
  CHECK(sinumerik::looks_like_sinumerik("N10 DEF REAL _CAMTOL\nN20 G0 X0\n"));
  CHECK(sinumerik::looks_like_sinumerik("G17 G90\nCYCLE800(0,\"TC\",0,57,0,0,0,0,0,0,0,0,0,1)\n"));
  CHECK(sinumerik::looks_like_sinumerik("G0 X=R1+5\n"));
  CHECK(sinumerik::looks_like_sinumerik("T=\"MILL\" M6\n"));
  CHECK_FALSE(sinumerik::looks_like_sinumerik("G90 G71 G94 G17\nT1 M6 D1\nTRAORI\nG0 X20 Y0 Z50 A0 C0\nM30\n"));
  CHECK_FALSE(sinumerik::looks_like_sinumerik("%\nO1000\nG0 X0 Y0 (DEF REAL IN A COMMENT)\n; CYCLE800(\nM30\n%\n"));
  CHECK_FALSE(sinumerik::looks_like_sinumerik("#1 = 5\nG1 X#1 F100\nM2\n"));
}
