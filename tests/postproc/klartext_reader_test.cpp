// SPDX-License-Identifier: Apache-2.0
// Heidenhain Klartext -> CL records (klartext_reader.hpp): program frame, tool calls, L blocks
// (absolute, incremental, FMAX only for its block, FAUTO), M functions, the held start, M128 /
// FUNCTION TCPM tool-tip programs, M140 and the refusals by name. Expected tool tips are computed by
// hand from the TNC's rules and the AC trunnion's geometry (machines/ac-trunnion.toml: pivots at the
// origin, the table turned by Rx(A) Rz(C), so the tool axis in W is (sin A sin C, sin A cos C, cos A)
// and a machine-axis point X Y Z is seen from the table at Rz(-C) Rx(-A) (X, Y, Z)).
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

#include "cl_records.hpp"
#include "shipped_machines.hpp"
#include "test_paths.hpp"
#include "ncpost/kinematics/pose.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/read/klartext/klartext_block.hpp"
#include "ncpost/postproc/read/klartext/klartext_reader.hpp"

using namespace ncpost;
using test::only;

namespace {

struct Read {
  std::vector<cl::Record> records;
  std::vector<std::string> notices;
};

Read read(const std::string& text, klartext::ReaderOptions o = {}) {
  std::istringstream in(text);
  klartext::KlartextReader r(in, "t.h", test::ac_trunnion(), Setup{}, o);
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

std::string program(const std::string& body) { return "0 BEGIN PGM T MM\n" + body + "99 END PGM T MM\n"; }

void check_tip(const cl::Motion& m, double x, double y, double z) {
  INFO("line " << m.where.line);
  CHECK(m.point.tip_mm.x() == Approx(x).margin(1e-9));
  CHECK(m.point.tip_mm.y() == Approx(y).margin(1e-9));
  CHECK(m.point.tip_mm.z() == Approx(z).margin(1e-9));
}

/// The tool axis in W on the AC trunnion at A, C (deg), by hand (see the file comment).
Vec3d ac_axis(double a_deg, double c_deg) {
  const double a = deg_to_rad(a_deg), c = deg_to_rad(c_deg);
  return {std::sin(a) * std::sin(c), std::sin(a) * std::cos(c), std::cos(a)};
}

bool any_contains(const std::vector<std::string>& list, const std::string& what) {
  for (const auto& s : list)
    if (s.find(what) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST_CASE("klartext block: words, signs, FMAX, strings, comments, structure blocks") {
  const auto b = klartext::parse_block("12 L IX-5.5 Y+.25 Z10 R0 F MAX M3 ; to the top", "t.h", 1);
  CHECK(b.number == 12);
  CHECK(b.statement == "L");
  CHECK(b.column == 4);
  REQUIRE(b.words.size() == 6);
  CHECK(b.words[0].name == "IX");
  CHECK(*b.words[0].value == -5.5);
  CHECK(*b.words[1].value == 0.25);
  CHECK(*b.words[2].value == 10.0);
  CHECK(b.words[3].name == "R");
  CHECK(b.words[4].name == "FMAX");
  CHECK(b.words[5].name == "M");
  CHECK(b.comment == "to the top");
  const auto t = klartext::parse_block("3 TOOL CALL \"D10 MILL\" Z S5000 DL+0 DR2-0.1", "t.h", 3);
  CHECK(t.statement == "TOOL CALL");
  REQUIRE(t.words.size() == 5);
  CHECK(t.words[0].text == "D10 MILL");
  CHECK(t.words[4].name == "DR2");
  CHECK(*t.words[4].value == -0.1);
  const auto s = klartext::parse_block("4 * - ROUGHING", "t.h", 4);
  CHECK(s.statement == "*");
  CHECK(s.comment == "ROUGHING");
  const auto dr = klartext::parse_block("C X+1 Y+2 DR-", "t.h", 5);
  REQUIRE(dr.words.size() == 3);
  CHECK(dr.words[2].sign == '-');
  CHECK_FALSE(dr.words[2].value);
  CHECK(klartext::parse_block("L X+Q12", "t.h", 6).words[0].q_parameter);
  const auto q = klartext::parse_block("  Q200=+2 ;SET-UP CLEARANCE ~ ", "t.h", 7);
  CHECK(q.continued);
  CHECK(q.comment == "SET-UP CLEARANCE");
  CHECK(klartext::looks_like_klartext("0 BEGIN PGM 1 MM\n1 L X+0"));
  CHECK(klartext::looks_like_klartext("\xEF\xBB\xBF; header\r\nBEGIN  PGM PART mm\r\n"));
  CHECK_FALSE(klartext::looks_like_klartext("G0 X0\n0 BEGIN PGM 1 MM\n"));
  CHECK_FALSE(klartext::looks_like_klartext("BEGINPGM 1 MM\n"));
}

TEST_CASE("klartext: tool call, held start, FMAX per block, FAUTO, incremental words, M functions") {
  const Read r = read(
      "0 BEGIN PGM T1 MM\n"
      "1 BLK FORM 0.1 Z X+0 Y+0 Z-20\n"
      "2 BLK FORM 0.2 X+100 Y+100 Z+0\n"
      "3 TOOL CALL 5 Z S8000 F600\n"
      "4 L Z+50 R0 FMAX M3\n"
      "5 L X+10 Y+20 R0 FMAX M8 ; above the hole\n"
      "6 L Z-2 F200\n"
      "7 L IX+5 IY-3 FAUTO\n"
      "8 L X+0 FMAX\n"
      "9 L Y+0\n"
      "10 L Z+50 FMAX M5 M9\n"
      "11 M30\n"
      "12 END PGM T1 MM\n");
  const auto ms = only<cl::Motion>(r.records);
  REQUIRE(ms.size() == 7);
  // block 4 (line 5) moves only Z: held until X and Y are known, it takes their first values (block 5)
  check_tip(ms[0], 10, 20, 50);
  CHECK(ms[0].where.line == 5);
  CHECK(ms[0].rapid);
  check_tip(ms[1], 10, 20, 50);
  check_tip(ms[2], 10, 20, -2);
  CHECK_FALSE(ms[2].rapid);
  REQUIRE(ms[2].feed);
  CHECK(*ms[2].feed == 200);
  check_tip(ms[3], 15, 17, -2);
  CHECK(*ms[3].feed == 600);  // FAUTO: the TOOL CALL's F
  check_tip(ms[4], 0, 17, -2);
  CHECK(ms[4].rapid);  // FMAX acts in its block only:
  check_tip(ms[5], 0, 0, -2);
  CHECK_FALSE(ms[5].rapid);  // the next block cuts at the feed in force
  CHECK(ms[0].point.axis.isApprox(Vec3d::UnitZ()));
  REQUIRE(ms[0].rotary_rad);
  CHECK(ms[0].rotary_rad->norm() == 0.0);
  const auto tools = only<cl::ToolChange>(r.records);
  REQUIRE(tools.size() == 1);
  CHECK(tools[0].number == 5);
  const auto spindles = only<cl::Spindle>(r.records);
  REQUIRE(spindles.size() == 2);
  CHECK(spindles[0].direction == cl::Spindle::Direction::cw);
  CHECK(spindles[0].rpm == 8000);
  CHECK(spindles[1].direction == cl::Spindle::Direction::off);
  const auto coolant = only<cl::Coolant>(r.records);
  REQUIRE(coolant.size() == 2);
  CHECK(coolant[0].on);
  CHECK_FALSE(coolant[1].on);
  // order: the tool change comes before the first (held) motion; M5 M9 after line 10's motion
  std::size_t tool_at = 0, first_motion_at = 0, spindle_off_at = 0, last_motion_at = 0;
  for (std::size_t i = 0; i < r.records.size(); ++i) {
    if (std::holds_alternative<cl::ToolChange>(r.records[i])) tool_at = i;
    if (std::holds_alternative<cl::Motion>(r.records[i])) {
      if (!first_motion_at) first_motion_at = i;
      last_motion_at = i;
    }
    if (auto* s = std::get_if<cl::Spindle>(&r.records[i]); s && s->direction == cl::Spindle::Direction::off)
      spindle_off_at = i;
  }
  CHECK(tool_at < first_motion_at);
  CHECK(spindle_off_at > last_motion_at);
  const auto comments = only<cl::Comment>(r.records);
  REQUIRE(comments.size() == 1);
  CHECK(comments[0].text == "above the hole");
  const auto ends = only<cl::End>(r.records);
  REQUIRE(ends.size() == 1);
  CHECK(ends[0].where.line == 12);  // M30 at line 12 of the text (the first line is line 1)
  CHECK(any_contains(r.notices, "BLK FORM"));
  CHECK(any_contains(r.notices, "A, C not programmed yet: taken as 0"));
}

TEST_CASE("klartext: RL / RR / R0 are cutter compensation records") {
  const auto rs = read(program("1 TOOL CALL 1 Z S100\n2 L X+0 Y+0 Z+0 R0 FMAX\n3 L X+10 RL F100\n4 L Y+10\n"
                               "5 L X+0 RR\n6 L X-5 R0\n"))
                      .records;
  const auto comp = only<cl::CutterComp>(rs);
  REQUIRE(comp.size() == 3);
  CHECK(comp[0].side == cl::CutterComp::Side::left);
  CHECK(comp[0].where.line == 4);
  CHECK(comp[1].side == cl::CutterComp::Side::right);
  CHECK(comp[2].side == cl::CutterComp::Side::off);
}

TEST_CASE("klartext: M128 and FUNCTION TCPM programs give the tool tip in W; M129 machine axes again") {
  const auto ms =
      motions(program("1 TOOL CALL 1 Z S1000\n"
                      "2 L X+0 Y+0 Z+100 A+0 C+0 R0 FMAX\n"
                      "3 L X+10 Y+20 Z+30 A+30 C+90 F500 M128\n"
                      "4 M129\n"
                      "5 L X+10 Y+20 Z+30 F500\n"
                      "6 FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS\n"
                      "7 L X+1 Y+2 Z+3 A+90 C+0 F100\n"
                      "8 FUNCTION RESET TCPM\n"));
  REQUIRE(ms.size() == 4);
  check_tip(ms[1], 10, 20, 30);
  CHECK((ms[1].point.axis - ac_axis(30, 90)).norm() < 1e-12);
  REQUIRE(ms[1].rotary_rad);
  CHECK((*ms[1].rotary_rad)[0] == Approx(deg_to_rad(30)));
  CHECK((*ms[1].rotary_rad)[1] == Approx(deg_to_rad(90)));
  // machine axes at A30 C90: Rz(-90) Rx(-30) (10, 20, 30)
  const double a = deg_to_rad(30);
  const double y1 = 20 * std::cos(a) + 30 * std::sin(a), z1 = -20 * std::sin(a) + 30 * std::cos(a);
  check_tip(ms[2], y1, -10, z1);
  check_tip(ms[3], 1, 2, 3);
  CHECK((ms[3].point.axis - ac_axis(90, 0)).norm() < 1e-12);
}

TEST_CASE("klartext: M128 F in a block of its own limits the compensating moves; the path's feed stays") {
  // (the TNC's M128 F: a feed for the control's compensating moves of the linear axes, not a path feed)
  const Read r =
      read(program("1 TOOL CALL 1 Z S1000\n"
                   "2 L X+0 Y+0 Z+100 A+0 C+0 R0 F300\n"
                   "3 M128 F900000\n"
                   "4 L X+10 Y+20 Z+30\n"));
  const auto feeds = only<cl::Feed>(r.records);
  REQUIRE(feeds.size() == 1);
  CHECK(feeds[0].value == 300.0);
  const auto ms = only<cl::Motion>(r.records);
  REQUIRE(ms.size() == 2);
  CHECK_FALSE(ms[1].rapid);
  check_tip(ms[1], 10, 20, 30);
  CHECK(any_contains(r.notices, "t.h:4:"));  // (line 1 is BEGIN PGM)
  CHECK(any_contains(r.notices, "M128 F900000: the feed limit"));
  CHECK_THAT(error_of(program("1 L X+0 Y+0 Z+100 A+0 C+0 R0 F300\n2 M3 F500\n")), Catch::Contains("with path words"));
}

TEST_CASE("klartext: M140 MB MAX retracts machine Z to the top of its travel; MB d by d") {
  const auto ms =
      motions(program("1 TOOL CALL 1 Z S100\n2 L X+10 Y+0 Z+5 R0 FMAX\n3 M140 MB+50\n4 L Z+5 FMAX\n"
                      "5 L Z+5 FMAX M140 MB MAX\n"));
  REQUIRE(ms.size() == 5);
  check_tip(ms[1], 10, 0, 55);
  CHECK(ms[1].rapid);
  check_tip(ms[4], 10, 0, 600);  // Z travel -600 .. 600 mm
  CHECK(ms[4].rapid);
}

TEST_CASE("klartext: M126 turns a continuous rotary axis the short way") {
  const auto ms =
      motions(program("1 L X+0 Y+0 Z+50 A+0 C+350 R0 FMAX\n2 M126\n3 L C+10 FMAX\n4 M127\n5 L C+350 FMAX\n"));
  REQUIRE(ms.size() == 3);
  CHECK((*ms[1].rotary_rad)[1] == Approx(deg_to_rad(370)));
  CHECK((*ms[2].rotary_rad)[1] == Approx(deg_to_rad(350)));
}

TEST_CASE("klartext: what is not read is refused by name with file:line:column") {
  const auto refused = [](const std::string& body, const std::string& what) {
    const std::string e = error_of(program("1 TOOL CALL 1 Z S100\n2 L X+0 Y+0 Z+10 R0 FMAX\n" + body));
    INFO(body << " -> " << e);
    CHECK(e.find("t.h:4:") == 0);
    CHECK(e.find(what) != std::string::npos);
  };
  refused("3 CYCL DEF 19.1 B+15\n", "CYCL DEF 19 (working plane): its angles are axis or spatial angles");
  refused("3 CYCL DEF 7.1 #5\n", "datum table");
  refused("3 CYCL DEF 7.1 C+10\n", "a shift of C is not read");
  refused("3 PLANE RESET MOVE DIST50 F1000\n", "PLANE RESET MOVE DIST: a swivel about a point");
  refused("3 CYCL DEF 200 DRILLING ~\n  Q200=2 ;SET-UP CLEARANCE ~\n  Q201=-10 ;DEPTH\n", "CYCL DEF 200");
  refused("3 PLANE RELATIV SPA+10 STAY\n", "PLANE RELATIV is not read");
  refused("3 PLANE PROJECTED PROPR+90 PROMIN+0 PROROT+0 STAY\n", "the sign convention of those angles");
  refused("3 PLANE PROJECTED PROPR+20 PROMIN+30 ROT+15 STAY\n", "PLANE PROJECTED with a projection angle");
  refused("3 PLANE PROJECTED PROPR+0 PROMIN+0 ROT+0 PROROT+0 STAY\n", "PLANE PROJECTED with both ROT and PROROT");
  refused("3 PLANE POINTS P1X+0 P1Y+0 P1Z+0 P2X+10 P2Y+0 P2Z+0 P3X+20 P3Y+0 P3Z+0 STAY\n",
          "PLANE POINTS: the three points lie on one line");
  refused("3 RND R5\n", "RND without a straight line in X Y at a feed (L or LP) just before it");
  refused("3 CHF 2\n", "CHF without a straight line in X Y at a feed (L or LP) just before it");
  refused("3 LP PR+10 PA+30\n", "LP without a CC before it");
  refused("3 FN 14: ERROR = 1000\n", "FN 14 is not read");
  refused("3 Q1 = Q7 + 1\n", "Q7 is not set in this program");
  refused("3 Q1 = LOG(10)\n", "LOG in a Q formula is not read");
  refused("3 CALL LBL 1 REP 2\n", "CALL LBL 1 REP 2: LBL 1 is not in the program");
  refused("3 CALL PGM SUB.H\n", "a program call is not read");
  refused("3 L X+Q1\n", "X+Q1: Q1 is not set in this program");
  refused("3 L X+10 FQ1\n", "Q1 is not set");
  refused("3 L Z+10 R0 FMAX M91\n",
          "M91 Z10: machine coordinates count from the axis's reference point, which "
          "the machine file ac-trunnion does not give");
  refused("3 L Z+10 R0 FMAX M92\n",
          "M92 Z10: machine coordinates count from the axis's second reference point "
          "(the TNC's additional machine datum, M92), which the machine file ac-trunnion "
          "does not give; add [axes.Z] reference2");
  refused("3 L X+10 FMAX M99\n",
          "a cycle call without a hole cycle (CYCL DEF 200, 201, 203, 206, 207, 208, 209, 240 or 241) before it");
  refused("3 CYCL DEF 203 UNIVERSAL DRILLING ~\n  Q200=2 ~\n  Q201=-10\n", "CYCL DEF 203 without Q206");
  refused("3 CYCL DEF 201 REAMING ~\n  Q200=2 ~\n  Q201=-10\n", "CYCL DEF 201 without Q206");
  refused("3 CYCL DEF 205 UNIVERSAL PECKING ~\n  Q200=2 ~\n  Q201=-10\n",
          "'CYCL DEF 205 UNIVERSAL PECKING': this cycle");
  refused("3 M114\n", "M114");
  // M136: F in mm per revolution; M103 F20: 20 % of the feed when plunging (TNC 640 manual): neither F is a path feed
  refused("3 M136\n", "M136: a feed in mm per spindle revolution");
  refused("3 L Z+0 F1000 M103 F20\n", "M103: M103 F (the plunge feed reduced to a percentage");
  refused("3 M124\n", "M124 (contour points closer than a tolerance left out) changes the path");
  refused("3 TOOL CALL \"\" Z S100\n", "expected a tool name between the quotes");
  refused("3 TOOL CALL 5 \"D10\" Z S100\n", "both a number and a name");
  refused("3 TOOL CALL 2 Z DL+0.5\n", "DL+0.5");
  refused("3 TOOL CALL 2 X S100\n", "tool axis X");
  refused("3 L B+10\n", "has no B axis");
  refused("3 FUNCTION TCPM F TCP AXIS SPAT PATHCTRL AXIS\n", "spatial angles");
  refused("3 APPR LCT X+0 Y+0 R5 RL F100\n", "approach");
  refused("3 C X+1 Y+1 DR+\n", "without a CC");
  CHECK_THAT(
      error_of("0 BEGIN PGM T INCH\n1 L X+0\n"),
      Catch::Contains("t.h:1:3: BEGIN PGM ... INCH: an inch program is not read") && Catch::Contains("0.1 inch/min"));
  CHECK_THAT(error_of("0 BEGIN PGM T IN\n1 L X+0\n"), Catch::Contains("t.h:1:3: BEGIN PGM ... IN: an inch program"));
  CHECK_THAT(error_of(program("1 TOOL CALL 2 Z DR+0.1\n2 L X+0 Y+0 Z+5 FMAX\n3 L X+5 RL F100\n")),
             Catch::Contains("t.h:4:9: RL with a delta radius"));
  CHECK_THAT(error_of("0 BEGIN PGM T MM\n1 L X+0 Y+0 FMAX\n2 L Z-1 F100\n3 END PGM T MM\n"),
             Catch::Contains("t.h:2:3: this rapid does not say where Z goes, and Z is first programmed by the cutting "
                             "motion at line 3"));
  CHECK_THAT(error_of("0 BEGIN PGM T MM\n1 L X+0 F100\n3 END PGM T MM\n"),
             Catch::Contains("t.h:2:3: a cutting motion before Y, Z are programmed"));
  CHECK_THAT(error_of("0 BEGIN PGM T MM\n1 L X+0 Y+0 Z+10 FMAX\n"), Catch::Contains("truncated"));
  CHECK_THAT(error_of("1 L X+0 Y+0 Z+10 FMAX\n"), Catch::Contains("t.h:1:3: 'L' before BEGIN PGM"));
  klartext::ReaderOptions lax;
  lax.allow_unterminated = true;
  CHECK(only<cl::End>(read("0 BEGIN PGM T MM\n1 L X+0 Y+0 Z+10 FMAX\n", lax).records).size() == 1);
}

TEST_CASE("klartext: CYCL DEF 7 shifts the datum (absolute from the preset, I... from the last shift); 32 is noted") {
  const Read r =
      read(program("1 TOOL CALL 1 Z S100\n"
                   "2 CYCL DEF 7.0 DATUM SHIFT\n"
                   "3 CYCL DEF 7.1 X+10\n"
                   "4 CYCL DEF 7.2 Y-5\n"
                   "5 L X+0 Y+0 Z+10 A+0 C+0 R0 FMAX\n"
                   "6 CYCL DEF 7.1 IX+2\n"
                   "7 L X+1 F100\n"
                   "8 L IY+1\n"
                   "9 CC X+0 Y+1\n"      // the pole at (12, -4) in the preset's coordinates
                   "10 C X+0 Y+2 DR+\n"  // a quarter circle from (13, -4) to (12, -3)
                   "11 CYCL DEF 7.0 DATUM SHIFT\n"
                   "12 CYCL DEF 7.1 X+0\n"
                   "13 CYCL DEF 7.2 Y+0\n"
                   "14 L X+1 Y+1\n"
                   "15 CYCL DEF 32.0 TOLERANCE\n"
                   "16 CYCL DEF 32.1 T0.02\n"
                   "17 PLANE RESET STAY\n"));
  const auto ms = only<cl::Motion>(r.records);
  REQUIRE(ms.size() == 5);
  check_tip(ms[0], 10, -5, 10);
  check_tip(ms[1], 13, -5, 10);
  check_tip(ms[2], 13, -4, 10);
  // C X+0 Y+2 ends at (12, -3): 1 mm from the pole (12, -4) as the start (13, -4) is
  check_tip(ms[3], 12, -3, 10);
  const auto circles = only<cl::Circle>(r.records);
  REQUIRE(circles.size() == 1);
  CHECK((circles[0].center_mm - Vec3d(12, -4, 10)).norm() < 1e-12);
  check_tip(ms[4], 1, 1, 10);
  CHECK(any_contains(r.notices, "CYCL DEF 32"));
  CHECK(any_contains(r.notices, "PLANE RESET STAY"));
}

/// CYCL DEF 200 with the parameters of the TNC manual's example, the surface at Z+1.
const std::string kDrilling =
    "3 CYCL DEF 200 DRILLING ~\n"
    "  Q200=+2 ;SET-UP CLEARANCE ~\n"
    "  Q201=-15 ;DEPTH ~\n"
    "  Q206=+150 ;FEED RATE FOR PLNGNG ~\n"
    "  Q202=+5 ;PLUNGING DEPTH ~\n"
    "  Q210=+0 ;DWELL TIME AT TOP ~\n"
    "  Q203=+1 ;SURFACE COORDINATE ~\n"
    "  Q204=+20 ;2ND SET-UP CLEARANCE ~\n"
    "  Q211=+0 ;DWELL TIME AT DEPTH ~\n"
    "  Q395=+0 ;DEPTH REFERENCE\n";

TEST_CASE("klartext: CYCL DEF 200 drilled at M99 and CYCL CALL, the hole's top at Q203") {
  const Read r = read(program("1 TOOL CALL 4 Z S2000\n2 L X+0 Y+0 Z+50 A+0 C+0 R0 FMAX M3\n" + kDrilling +
                              "4 L X+30 Y+20 R0 FMAX M99\n5 L X+40 FMAX\n6 CYCL CALL\n7 L Z+50 FMAX\n"));
  const auto ms = only<cl::Motion>(r.records);
  REQUIRE(ms.size() == 6);
  check_tip(ms[1], 30, 20, 50);
  CHECK(ms[1].rapid);
  check_tip(ms[2], 30, 20, 1);  // the hole: its top, the surface Q203
  CHECK_FALSE(ms[2].rapid);
  CHECK(ms[2].where.line == 14);
  check_tip(ms[3], 40, 20, 21);  // the TNC left the tool at the 2nd set-up clearance, 20 above the surface
  check_tip(ms[4], 40, 20, 1);
  CHECK(ms[4].where.line == 16);
  check_tip(ms[5], 40, 20, 50);
  const auto cycles = only<cl::Cycle>(r.records);
  REQUIRE(cycles.size() == 4);
  const cl::Cycle& c = cycles[0];
  CHECK(c.kind == cl::Cycle::Kind::deep);  // plunging depth 5 < depth 15: pecks with a full retract
  CHECK(c.depth_mm == 15);
  CHECK(c.rapid_to_mm == 2);
  REQUIRE(c.retract_mm);
  CHECK(*c.retract_mm == 20);
  CHECK(c.peck_mm == 5);
  REQUIRE(c.feed);
  CHECK(*c.feed == 150);
  CHECK(cycles[1].kind == cl::Cycle::Kind::off);
  // the record order of a call: the cycle, the hole, the cycle off
  const std::size_t none = r.records.size();
  std::size_t cycle_at = none, hole_at = none, off_at = none;
  for (std::size_t i = 0; i < r.records.size(); ++i) {
    const auto* k = std::get_if<cl::Cycle>(&r.records[i]);
    if (k && k->kind != cl::Cycle::Kind::off && cycle_at == none) cycle_at = i;
    if (k && k->kind == cl::Cycle::Kind::off && off_at == none) off_at = i;
    const auto* m = std::get_if<cl::Motion>(&r.records[i]);
    if (m && m->where.line == 14 && !m->rapid && hole_at == none) hole_at = i;
  }
  CHECK(cycle_at < hole_at);
  CHECK(hole_at < off_at);
  // one plunge when Q202 reaches the depth; its dwell Q211 is the cycle's
  std::string one = kDrilling;
  one.replace(one.find("Q202=+5"), 7, "Q202=20");
  one.replace(one.find("Q211=+0"), 7, "Q211=.5");
  const auto single = only<cl::Cycle>(read(program("1 L X+0 Y+0 Z+50 R0 FMAX\n" + one + "4 CYCL CALL\n")).records);
  REQUIRE(single.size() == 2);
  CHECK(single[0].kind == cl::Cycle::Kind::drill);
  CHECK(single[0].dwell_s == 0.5);
  // parameters that change the meaning are refused by name
  std::string top_dwell = kDrilling;
  top_dwell.replace(top_dwell.find("Q210=+0"), 7, "Q210=+1");
  CHECK_THAT(error_of(program("1 L X+0 Y+0 Z+50 R0 FMAX\n" + top_dwell)), Catch::Contains("Q210=1"));
  std::string auto_feed = kDrilling;
  auto_feed.replace(auto_feed.find("Q206=+150"), 9, "Q206=FAUTO");
  CHECK_THAT(error_of(program("1 L X+0 Y+0 Z+50 R0 FMAX\n" + auto_feed)), Catch::Contains("t.h:6: Q206=FAUTO"));
}

TEST_CASE("klartext: machine limits make the program infeasible") {
  CHECK_THROWS_AS(read(program("1 L X+0 Y+0 Z+700 R0 FMAX\n")), Infeasible);
  CHECK_THROWS_AS(read(program("1 L X+0 Y+0 Z+0 A+130 R0 FMAX\n")), Infeasible);
}

TEST_CASE("klartext: M91 and M92 count from the machine file's reference and reference2 points") {
  // tests/data/machines/ac-trunnion-references.toml: reference X -400 Y 450 Z 550, reference2 X 300
  // Y -200 Z 400; at A = C = 0 with the origin of W at M's and no tool the tip is the machine's X Y Z
  const Machine m = load_machine(test::data("machines/ac-trunnion-references.toml"));
  std::istringstream in(
      program("1 L X+0 Y+0 Z+10 A+0 C+0 R0 FMAX\n"
              "2 L Z+5 R0 FMAX M92\n"
              "3 L X+0 Y+0 R0 FMAX M92\n"
              "4 L Z-100 R0 FMAX M91\n"
              "5 L X+1 Y+2 Z+3 FMAX\n"
              "6 M30\n"));
  klartext::KlartextReader r(in, "t.h", m, Setup{}, {});
  const auto ms = only<cl::Motion>(test::all_records(r));
  REQUIRE(ms.size() == 5);
  check_tip(ms[0], 0, 0, 10);
  check_tip(ms[1], 0, 0, 400 + 5);
  check_tip(ms[2], 300, -200, 405);
  check_tip(ms[3], 300, -200, 550 - 100);
  check_tip(ms[4], 1, 2, 3);
  CHECK(any_contains(r.take_notices(), "M92: the block's X Y Z are machine coordinates"));
}

TEST_CASE("klartext: TOOL CALL \"name\" changes to the tool of that name, TOOL CALL n to tool n") {
  const auto tools = only<cl::ToolChange>(
      read(program("1 TOOL CALL \"FRA-P15251 D15.2\" Z S100 DL+0 DR+0\n2 L X+0 Y+0 Z+10 A+0 C+0 R0 FMAX\n"
                   "3 TOOL CALL 4 Z S200\n4 M30\n"))
          .records);
  REQUIRE(tools.size() == 2);
  CHECK(tools[0].name == "FRA-P15251 D15.2");  // as written: case and blanks kept
  CHECK(tools[0].number == 0);
  CHECK(tools[0].where.line == 2);
  CHECK(tools[1].name.empty());
  CHECK(tools[1].number == 4);
}

TEST_CASE("klartext: CYCL DEF 9 dwells where it is defined, its time at the end of 9.1 in any language") {
  const Read r =
      read(program("1 L X+0 Y+0 Z+10 A+0 C+0 R0 FMAX\n"
                   "2 CYCL DEF 9.0 DWELL TIME\n"
                   "3 CYCL DEF 9.1 DWELL 1.5\n"
                   "4 CYCL DEF9 .0 VARAKOZASI IDO\n"  // a Hungarian TNC, as hyperMILL writes it
                   "5 CYCL DEF9.1 V.IDO2\n"
                   "6 M30\n"));
  const auto dwells = only<cl::Dwell>(r.records);
  REQUIRE(dwells.size() == 2);
  CHECK(dwells[0].seconds == 1.5);
  CHECK(dwells[0].where.line == 4);
  CHECK(dwells[1].seconds == 2.0);
  CHECK_THAT(error_of(program("1 L X+0 Y+0 Z+10 A+0 C+0 R0 FMAX\n2 CYCL DEF 9.1 DWELL\n")),
             Catch::Contains("t.h:3:") && Catch::Contains("expected CYCL DEF 9.1 with the dwell time in s"));
}

TEST_CASE("klartext: a jump on a parameter the program does not set ends it where nothing can move after it") {
  // hyperMILL for DMG: `/ M30` (skipped with block skip on), then tool-edge checks after it
  const std::string tail =
      "3 LBL \"CuttingEdgesCheck\"\n"
      "4 FN 9: IF +Q1900 EQU +1 GOTO LBL \"CuttingEdges1\"\n"
      "5 FN 9: IF +Q1900 EQU +2 GOTO LBL \"CuttingEdges2\"\n"
      "6 LBL 0\n"
      "7 ; ----\n"
      "8 LBL \"CuttingEdges1\"\n"
      "9 FN 0: Q1901=4\n"
      "10 LBL 0\n"
      "11 LBL \"CuttingEdges2\"\n"
      "12 FN 0: Q1901=3\n"
      "13 LBL 0\n";
  const Read r = read(program("1 L X+0 Y+0 Z+10 A+0 C+0 R0 FMAX\n2 L X+5 FMAX\n/2 M30\n" + tail));
  CHECK(only<cl::Motion>(r.records).size() == 2);
  const auto ends = only<cl::End>(r.records);
  REQUIRE(ends.size() == 1);
  CHECK(ends[0].where.line == 6);  // the first jump on Q1900
  CHECK(any_contains(r.notices, "t.h:6:"));
  CHECK(any_contains(r.notices, "nothing moves whichever way it jumps"));
  // a motion after it, or a jump back before it: refused as before
  CHECK_THAT(error_of(program("1 L X+0 Y+0 Z+10 A+0 C+0 R0 FMAX\n" + tail + "14 L X+5 FMAX\n")),
             Catch::Contains("t.h:4:") && Catch::Contains("Q1900 is not set in this program"));
  CHECK_THAT(error_of(program("1 LBL 7\n2 L X+0 Y+0 Z+10 A+0 C+0 R0 FMAX\n"
                              "3 FN 9: IF +Q1900 EQU +1 GOTO LBL 7\n")),
             Catch::Contains("Q1900 is not set in this program"));
}
