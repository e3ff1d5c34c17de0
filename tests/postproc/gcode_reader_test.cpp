// SPDX-License-Identifier: Apache-2.0
// G-code -> CL: modal state, units, incremental mode, feeds, arcs, records, both program kinds,
// framing, and errors with positions.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <sstream>

#include <fmt/format.h>

#include "shipped_machines.hpp"
#include "cl_records.hpp"
#include "ncpost/kinematics/forward.hpp"
#include "ncpost/kinematics/inverse.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/machines/trr_xy_file.hpp"
#include "ncpost/postproc/read/gcode/gcode_cl_reader.hpp"
#include "ncpost/postproc/read/gcode/gcode_detect.hpp"

using namespace ncpost;
using namespace ncpost::gcode;
using ncpost::gcode::InputKind;  // (ncpost::InputKind is the CL input's kind)

namespace {

std::vector<cl::Record> read_all(const std::string& text, GcodeReaderOptions o = {}, Setup s = {},
                                 std::vector<std::string>* notices = nullptr) {
  std::istringstream in(text);
  GcodeClReader r(in, "t.ngc", test::ac_trunnion(), s, o);
  std::vector<cl::Record> out = test::all_records(r);
  if (notices) *notices = r.take_notices();
  return out;
}

using test::only;

std::vector<cl::Motion> motions(const std::string& text, GcodeReaderOptions o = {}, Setup s = {}) {
  return only<cl::Motion>(read_all(text, o, s));
}

/// Input errors are the subject: the machine's limits are not checked (gcode_control_test.cpp does).
GcodeReaderOptions input_only() {
  GcodeReaderOptions o;
  o.check_limits = false;
  return o;
}

InputError error_of(const std::string& text, GcodeReaderOptions o = input_only()) {
  try {
    read_all(text, o);
  } catch (const InputError& e) {
    return e;
  }
  FAIL("no error for: " << text);
  throw;
}

void check_tip(const cl::Motion& m, double x, double y, double z) {
  CHECK(m.point.tip_mm.x() == Approx(x).margin(1e-9));
  CHECK(m.point.tip_mm.y() == Approx(y).margin(1e-9));
  CHECK(m.point.tip_mm.z() == Approx(z).margin(1e-9));
}

}  // namespace

TEST_CASE("gcode reader: modal motion, axes and feed carry over") {
  const auto rs = read_all("G90 G21 G94\nG1 X1 Y2 Z3 F100\nX4\nY5 F200\nG0 Z10\nX0\n");
  const auto ms = only<cl::Motion>(rs);
  REQUIRE(ms.size() == 5);
  check_tip(ms[0], 1, 2, 3);
  check_tip(ms[1], 4, 2, 3);
  check_tip(ms[2], 4, 5, 3);
  check_tip(ms[3], 4, 5, 10);
  check_tip(ms[4], 0, 5, 10);
  CHECK_FALSE(ms[1].rapid);
  CHECK(ms[3].rapid);
  CHECK(ms[4].rapid);
  REQUIRE(ms[0].feed);
  CHECK(*ms[0].feed == 100.0);
  CHECK_FALSE(ms[1].feed);
  const auto feeds = only<cl::Feed>(rs);
  REQUIRE(feeds.size() == 2);
  CHECK(feeds[0].value == 100.0);
  CHECK(feeds[1].value == 200.0);
  CHECK(feeds[1].where.line == 4);
  CHECK(feeds[1].where.column == 4);
  CHECK(ms[2].where.line == 4);
  CHECK(ms[2].where.column == 1);
  for (const auto& m : ms) {
    CHECK(m.axis_given);
    REQUIRE(m.rotary_rad);
    CHECK(m.point.axis.isApprox(Vec3d::UnitZ()));
  }
}

TEST_CASE("gcode reader: G20 converts lengths and feeds to mm, G21 back") {
  const auto rs = read_all("G20 G1 X1 Y-0.5 Z.1 F10\nG21 X1\n");
  const auto ms = only<cl::Motion>(rs);
  REQUIRE(ms.size() == 2);
  check_tip(ms[0], 25.4, -12.7, 2.54);
  check_tip(ms[1], 1.0, -12.7, 2.54);
  CHECK(only<cl::Feed>(rs).at(0).value == Approx(254.0));
  // the reader option starts in inches
  GcodeReaderOptions inch;
  inch.default_inch = true;
  check_tip(motions("G1 X2 F1\n", inch).at(0), 50.8, 0, 0);
}

TEST_CASE("gcode reader: G91 incremental positions, including rotary axes") {
  const auto ms = motions("G90 G1 X1 Y1 Z1 A10 C20 F50\nG91 X1 Y-2 C-5\nX0.5 A2\nG90 X0\n");
  REQUIRE(ms.size() == 4);
  REQUIRE(ms[1].rotary_rad);
  CHECK(rad_to_deg((*ms[1].rotary_rad)[0]) == Approx(10.0));
  CHECK(rad_to_deg((*ms[1].rotary_rad)[1]) == Approx(15.0));
  CHECK(rad_to_deg((*ms[2].rotary_rad)[0]) == Approx(12.0));
  // machine-axis program: the CL point maps back to the programmed X Y Z
  const Machine& m = test::ac_trunnion();
  const Vec3d xyz = linear_for(m, *ms[2].rotary_rad, ms[2].point.tip_mm, Setup{});
  CHECK(xyz.x() == Approx(2.5));
  CHECK(xyz.y() == Approx(-1.0));
  CHECK(xyz.z() == Approx(1.0));
  const Vec3d last = linear_for(m, *ms[3].rotary_rad, ms[3].point.tip_mm, Setup{});
  CHECK(last.x() == Approx(0.0).margin(1e-12));
}

TEST_CASE("gcode reader: machine-axis program goes through the nominal forward kinematics") {
  Setup setup;
  setup.workpiece_origin_mm = Vec3d(5, -3, 40);
  const auto ms = motions("G0 X10 Y20 Z30 A30 C45\nG1 X-4 A-60 C-120 F300\n", {}, setup);
  REQUIRE(ms.size() == 2);
  const Machine& m = test::ac_trunnion();
  AxisPosition q = home_of(m);
  q.linear_mm = Vec3d(10, 20, 30);
  q.rotary_rad = Eigen::Vector2d(deg_to_rad(30), deg_to_rad(45));
  const auto expected = forward(m, q, setup);
  CHECK((ms[0].point.tip_mm - expected.tip_mm).norm() < 1e-12);
  CHECK((ms[0].point.axis - expected.axis).norm() < 1e-12);
  CHECK(ms[0].point.axis.z() < 0.9);  // tilted by A
  // and back: our inverse kinematics with the programmed angles gives the programmed X Y Z
  const Vec3d xyz = linear_for(m, *ms[1].rotary_rad, ms[1].point.tip_mm, setup);
  CHECK((xyz - Vec3d(-4, 20, 30)).norm() < 1e-9);
  // and the closed-form IK finds the programmed angles again
  AxisPosition previous = home_of(m);
  previous.rotary_rad = *ms[1].rotary_rad;
  const IkOutcome ik = solve(m, ms[1].point, setup, previous);
  REQUIRE(ik.ok());
  CHECK((ik.position->rotary_rad - *ms[1].rotary_rad).norm() < 1e-9);
  CHECK((ik.position->linear_mm - Vec3d(-4, 20, 30)).norm() < 1e-9);
}

TEST_CASE("gcode reader: RTCP programs keep the tip and take the axis from the angles") {
  for (const char* on : {"M428", "G43.4 H1", "G234", "TRAORI", "M128"}) {
    INFO(on);
    const std::string text = std::string(on) + "\nG1 X1 Y2 Z3 A30 C90 F100\n";
    const auto ms = motions(text);
    REQUIRE(ms.size() == 1);
    check_tip(ms[0], 1, 2, 3);
    AxisPosition q = home_of(test::ac_trunnion());
    q.rotary_rad = Eigen::Vector2d(deg_to_rad(30), deg_to_rad(90));
    CHECK((ms[0].point.axis - forward(test::ac_trunnion(), q, Setup{}).axis).norm() < 1e-12);
  }
  // switched off again: machine axes, from where the machine stands (issue 27.3: the words are not
  // re-labelled). The tip (1, 2, 3) at A30 C90 needs machine Rot(x, 30°)·Rot(z, 90°)·(1, 2, 3) =
  // (-2, cos30 - 3 sin30, sin30 + 3 cos30); G1 X1 then moves machine X alone to 1.
  const auto ms = motions("M428\nG1 X1 Y2 Z3 A30 C90 F100\nM429\nG1 X1\n");
  REQUIRE(ms.size() == 2);
  AxisPosition q = home_of(test::ac_trunnion());
  q.rotary_rad = Eigen::Vector2d(deg_to_rad(30), deg_to_rad(90));
  const double c30 = std::cos(deg_to_rad(30)), s30 = std::sin(deg_to_rad(30));
  q.linear_mm = Vec3d(1, c30 - 3 * s30, s30 + 3 * c30);
  CHECK((ms[1].point.tip_mm - forward(test::ac_trunnion(), q, Setup{}).tip_mm).norm() < 1e-9);
  q.linear_mm = Vec3d(1, 2, 3);
  // forced kinds
  GcodeReaderOptions machine_kind;
  machine_kind.kind = InputKind::machine;
  CHECK((motions("M428\nG1 X1 Y2 Z3 A30 C90 F1\n", machine_kind)[0].point.tip_mm -
         forward(test::ac_trunnion(), q, Setup{}).tip_mm)
            .norm() < 1e-12);
  GcodeReaderOptions rtcp_kind;
  rtcp_kind.kind = InputKind::rtcp;
  check_tip(motions("G1 X1 Y2 Z3 A30 C90 F1\n", rtcp_kind)[0], 1, 2, 3);
  CHECK(parse_input_kind("auto") == InputKind::automatic);
  CHECK(parse_input_kind("rtcp") == InputKind::rtcp);
  CHECK_FALSE(parse_input_kind("cl"));
}

TEST_CASE("gcode reader: G93 inverse-time feed is kept per motion") {
  const auto ms = motions("G94 G1 X0 Y0 Z0 F500\nG93 G1 X10 F2.5\nY10 F20\nG94 X0 F400\n");
  REQUIRE(ms.size() == 4);
  CHECK_FALSE(ms[0].inverse_time);
  CHECK(ms[1].inverse_time);
  REQUIRE(ms[1].feed);
  CHECK(*ms[1].feed == 2.5);
  CHECK(*ms[2].feed == 20.0);
  CHECK_FALSE(ms[3].inverse_time);
  const InputError e = error_of("G93 G1 X1 F1\nX2\n");
  CHECK(e.where().line == 2);
  CHECK(e.where().column == 1);
  CHECK_THAT(e.detail(), Catch::Contains("needs an F word"));
  // G95: the feed per revolution is a cl::Feed record, not a motion feed
  const auto per_rev = read_all("G95 G1 X1 F0.1\n");
  CHECK(only<cl::Feed>(per_rev).at(0).per_rev);
  CHECK(only<cl::Feed>(per_rev).at(0).value == 0.1);
  CHECK_FALSE(only<cl::Motion>(per_rev).at(0).feed);
  // in G20 an inverse-time F stays 1/min
  CHECK(*motions("G20 G93 G1 X1 F3\n")[0].feed == 3.0);
}

TEST_CASE("gcode reader: arcs expand within the chord tolerance") {
  SECTION("quarter circle, centre format") {
    const auto ms = motions("G17 G1 X10 Y0 Z0 F100\nG3 X0 Y10 I-10 J0\n");
    REQUIRE(ms.size() > 10);
    const long n = static_cast<long>(ms.size()) - 1;
    const double step = 2.0 * std::acos(1.0 - 1e-3 / 10.0);
    CHECK(n == static_cast<long>(std::ceil((kPi / 2) / step)));
    check_tip(ms.back(), 0, 10, 0);
    Vec3d previous = ms[0].point.tip_mm;
    for (std::size_t i = 1; i < ms.size(); ++i) {
      const Vec3d p = ms[i].point.tip_mm;
      CHECK(p.head<2>().norm() == Approx(10.0).margin(1e-9));
      CHECK(p.x() <= previous.x() + 1e-12);  // counter-clockwise from +X to +Y
      const double sagitta = 10.0 - (0.5 * (p + previous)).head<2>().norm();
      CHECK(sagitta <= 1e-3 + 1e-12);
      CHECK_FALSE(ms[i].feed);  // no F word on the arc's block
      previous = p;
    }
  }
  SECTION("clockwise, radius format, helical") {
    const auto ms = motions("G1 X10 Y0 Z0 F100\nG2 X0 Y-10 Z-5 R10\n");
    REQUIRE(ms.size() > 3);
    const cl::Motion& mid = ms[ms.size() / 2];
    CHECK(mid.point.tip_mm.x() > 0);
    CHECK(mid.point.tip_mm.y() < 0);
    CHECK(mid.point.tip_mm.z() < 0);
    CHECK(mid.point.tip_mm.z() > -5);
    check_tip(ms.back(), 0, -10, -5);
    // negative R: the long way round, about the centre (10, -10), through (20, -10)
    const auto longway = motions("G1 X10 Y0 Z0 F100\nG2 X0 Y-10 R-10\n");
    bool through_far_side = false;
    for (const auto& m : longway) {
      through_far_side = through_far_side || m.point.tip_mm.x() > 19.99;
      CHECK((m.point.tip_mm.head<2>() - Eigen::Vector2d(10, -10)).norm() == Approx(10.0));
    }
    CHECK(through_far_side);
  }
  SECTION("full circle, G18 plane, G93 feed scaled per segment") {
    const auto ms = motions("G18 G1 X5 Y0 Z0 F100\nG93 G2 X5 Z0 I-5 F2\n");
    REQUIRE(ms.size() > 20);
    const double n = static_cast<double>(ms.size() - 1);
    check_tip(ms.back(), 5, 0, 0);
    for (std::size_t i = 1; i < ms.size(); ++i) {
      CHECK(ms[i].point.tip_mm.y() == 0.0);
      CHECK(std::hypot(ms[i].point.tip_mm.x() + 0.0 - 0.0, ms[i].point.tip_mm.z()) <= 5.0 + 1e-9);
      CHECK(ms[i].inverse_time);
      CHECK(*ms[i].feed == Approx(2.0 * n));
    }
  }
  SECTION("bad arcs") {
    const InputError off = error_of("G1 X10 Y0 F1\nG3 X0 Y12 I-10\n");
    CHECK(off.where().line == 2);
    CHECK_THAT(off.detail(), Catch::Contains("not on the arc"));
    const InputError small = error_of("G1 X10 Y0 F1\nG3 X-10 Y0 R2\n");
    CHECK_THAT(small.detail(), Catch::Contains("less than half"));
    const InputError none = error_of("G1 X10 Y0 F1\nG3 X0 Y10\n");
    CHECK_THAT(none.detail(), Catch::Contains("centre"));
    CHECK(error_of("G1 X1 I5 F1\n").where().column == 7);
  }
}

TEST_CASE("gcode reader: comments, tool, spindle, coolant, stops and the program end") {
  std::vector<std::string> notices;
  const auto rs = read_all(
      "%\nO0042 (DEMO)\n(first)\nN10 T3 M6 ; change\nN20 S1200 M3\nN30 M8 G0 X1\nS1500\nG4 P2.\nM0\nM5 M9\nM30\nG0 "
      "X99\n%\n",
      {}, {}, &notices);
  const auto comments = only<cl::Comment>(rs);
  REQUIRE(comments.size() == 3);
  CHECK(comments[0].text == "DEMO");
  CHECK(comments[1].text == "first");
  CHECK(comments[1].where.line == 3);
  CHECK(comments[2].text == "change");
  const auto tools = only<cl::ToolChange>(rs);
  REQUIRE(tools.size() == 1);
  CHECK(tools[0].number == 3);
  const auto spindles = only<cl::Spindle>(rs);
  REQUIRE(spindles.size() == 3);
  CHECK(spindles[0].direction == cl::Spindle::Direction::cw);
  CHECK(spindles[0].rpm == 1200.0);
  CHECK(spindles[1].rpm == 1500.0);
  CHECK(spindles[2].direction == cl::Spindle::Direction::off);
  const auto coolant = only<cl::Coolant>(rs);
  REQUIRE(coolant.size() == 2);
  CHECK(coolant[0].on);
  CHECK(coolant[0].mode == "FLOOD");
  CHECK_FALSE(coolant[1].on);
  const auto dwells = only<cl::Dwell>(rs);
  REQUIRE(dwells.size() == 1);
  CHECK(dwells[0].seconds == 2.0);
  CHECK(dwells[0].where.line == 8);
  // M0 is a program stop (it was passed through as a comment: the machine no longer stopped)
  CHECK(only<cl::Unsupported>(rs).empty());
  const auto stops = only<cl::Stop>(rs);
  REQUIRE(stops.size() == 1);
  CHECK(stops[0].where.line == 9);
  CHECK_FALSE(stops[0].optional);
  REQUIRE(notices.size() == 1);
  CHECK_THAT(notices[0], Catch::Contains("t.ngc:6:") && Catch::Contains("not programmed before the first motion"));
  const auto ends = only<cl::End>(rs);
  REQUIRE(ends.size() == 1);
  CHECK(ends[0].program);
  CHECK(std::holds_alternative<cl::End>(rs.back()));
  // nothing after M30 is read: one motion only
  CHECK(only<cl::Motion>(rs).size() == 1);
  // tool change comes before the spindle of the same block, the motion after the coolant
  const auto idx = [&](auto pred) {
    for (std::size_t i = 0; i < rs.size(); ++i)
      if (pred(rs[i])) return i;
    return rs.size();
  };
  CHECK(idx([](const cl::Record& r) { return std::holds_alternative<cl::Coolant>(r); }) <
        idx([](const cl::Record& r) { return std::holds_alternative<cl::Motion>(r); }));
}

TEST_CASE("gcode reader: block delete and percent framing") {
  CHECK(motions("G0 X1\n/G0 X5\nG0 X2\n").size() == 2);
  GcodeReaderOptions keep;
  keep.block_delete = false;
  CHECK(motions("G0 X1\n/G0 X5\nG0 X2\n", keep).size() == 3);
  // text after the closing % is not part of the program
  CHECK(motions("%\nG0 X1\n%\nthis is not G-code\n").size() == 1);
  // a leading % without its closing % or M30: truncated
  const InputError e = error_of("%\nG0 X1\nG1 X2 F10\n");
  CHECK(e.where().line == 3);
  CHECK_THAT(e.detail(), Catch::Contains("truncated"));
  // a line cut in the middle of a word
  const InputError cut = error_of("%\nG0 X1\nG1 X");
  CHECK(cut.where().line == 3);
  CHECK(cut.where().column == 5);
  // a leader before the opening % (lines that do not move; NX's information listing:
  // gcode_leader_test.cpp), and G-code before % is kept when nothing moves after it
  std::vector<std::string> notices;
  const auto led =
      only<cl::Motion>(read_all("PowerMill title\nDate\t28-Nov-2021\n\n%\nG0 X4\nM30\n%\n", {}, {}, &notices));
  REQUIRE(led.size() == 1);
  check_tip(led[0], 4, 0, 0);
  REQUIRE_FALSE(notices.empty());
  CHECK_THAT(notices[0], Catch::Contains("3 line(s) before the opening '%'"));
  CHECK(motions("G0 X1\nM30\n%\nG0 X2\n").size() == 1);    // a '%' after the program's end closes it
  CHECK(error_of("G0 X1\n%\nG0 X2\n").where().line == 2);  // motions on both sides: refused
  // a UTF-8 byte order mark (NX writes one)
  check_tip(motions("\xEF\xBB\xBF%\nG0 X3\nM30\n%\n").at(0), 3, 0, 0);
  // CRLF line ends
  const auto crlf = motions("G0 X1\r\nG0 X2 (c)\r\nM30\r\n");
  REQUIRE(crlf.size() == 2);
  check_tip(crlf[1], 2, 0, 0);
  // CR-only line ends (classic Mac OS files) end lines like LF: three motions, not one bad line
  const auto cr_only = motions("G0 X1\rG0 X2 (c)\rG1 X5 F100\rM30\r");
  REQUIRE(cr_only.size() == 3);
  check_tip(cr_only[2], 5, 0, 0);
}

TEST_CASE("gcode reader: semantic errors with their positions") {
  const auto check = [](const std::string& text, int line, int column, const char* says) {
    INFO(text);
    const InputError e = error_of(text);
    CHECK(e.where().file == "t.ngc");
    CHECK(e.where().line == line);
    CHECK(e.where().column == column);
    CHECK_THAT(e.detail(), Catch::Contains(says));
    CHECK_FALSE(e.source_line().empty());
  };
  check("G1 X1 F1\nG41.1 X2 D1\n", 2, 1, "dynamic cutter radius compensation");  // G41/G42: gcode_control_test.cpp
  check("G0 X1\nG0 Y1 B5\n", 2, 7, "no B axis");
  check("G0 X1 X2\n", 1, 7, "twice");
  check("G0 G1 X2\n", 1, 4, "same modal group");
  check("X5\n", 1, 1, "without a motion mode");
  check("G0 X1\nG81 X1 Y1 Z-5 R1\n", 2, 11, "canned cycle before any feed F");  // cycles are read (post_cycle_test)
  check("G1 X1e5 F1\n", 1, 6, "E words");
  check("G0 U1\n", 1, 4, "U axis");
  check("M98 P100\n", 1, 1, "the file holds no program O100");
  check("G0 X1 M3 M4\n", 1, 10, "same modal group");
  check("G1 X1 F-5\n", 1, 7, "expected a feed within");
  check("G91 G0 X900000000\nX900000000\n", 2, 1, "out of range");
  check("G20 G0 X99999999\n", 1, 8, "out of range");
  check("G0 X1\nG1.5 X1\n", 2, 1, "not supported");
  check("G0 X1 T1.5\n", 1, 7, "tool number");
}

TEST_CASE("gcode reader: G80 beside G0/G1 in one block cancels the cycle and sets the motion (Fanuc group 09)") {
  // the safe-start line of Fanuc-style posts: G80 is its own group there, G00 the motion mode
  // (the first rapid says its Z: a rapid before any Z, released by the cut that programs Z first,
  // is refused — gcode_control_test)
  const auto start =
      motions("N1 G00 G17 G21 G40 G49 G80 G90\nN3 X-75. Y-93.703 Z5.\nG1 Z-6. F300\nG80 G1 X75.\n", input_only());
  REQUIRE(start.size() == 3);
  CHECK(start[0].rapid);
  check_tip(start[0], -75, -93.703, 5);
  CHECK_FALSE(start[1].rapid);
  CHECK_FALSE(start[2].rapid);
  check_tip(start[2], 75, -93.703, -6);

  // after a modal G81: "G80 G0 Z20" ends the cycle (a CYCLE/OFF record) and the rapid is a motion, not a hole
  const auto rs = read_all("G90 G21 G94\nG0 X0 Y0 Z10\nG1 F100\nG81 X1 Y1 Z-5 R1\nX2\nG0 G80 Z20\n", input_only());
  const auto cycles = only<cl::Cycle>(rs);
  REQUIRE(cycles.size() >= 2);
  CHECK(cycles.front().kind == cl::Cycle::Kind::drill);
  CHECK(cycles.back().kind == cl::Cycle::Kind::off);
  CHECK(cycles.back().where.line == 6);
  const auto ms = only<cl::Motion>(rs);
  REQUIRE(!ms.empty());
  CHECK(ms.back().rapid);
  check_tip(ms.back(), 2, 1, 20);

  // still contradictions: a cycle beside G80, two motion codes
  CHECK_THAT(error_of("G1 X0 F100\nG81 G80 X1 Y1 Z-5 R1\n").detail(), Catch::Contains("same modal group"));
  CHECK_THAT(error_of("G80 G0 G1 X1\n").detail(), Catch::Contains("same modal group"));
}

TEST_CASE("gcode reader: unreadable files and invalid options") {
  CHECK_THROWS_AS(open_gcode("/nonexistent/file.ngc", test::ac_trunnion(), Setup{}), InputError);
  const std::string dir = std::filesystem::temp_directory_path().string();
  try {
    auto r = open_gcode(dir, test::ac_trunnion(), Setup{});
    while (r->next()) {
    }
    FAIL("a directory was read");
  } catch (const InputError& e) {
    CHECK(e.where().file == dir);
  }
  GcodeReaderOptions bad;
  bad.arc_chord_tolerance_mm = 0.0;
  CHECK_FALSE(bad.validate().empty());
  std::istringstream in("G0 X1\n");
  CHECK_THROWS_AS(GcodeClReader(in, "t.ngc", test::ac_trunnion(), Setup{}, bad), std::invalid_argument);
}

TEST_CASE("gcode detection: G-code versus APT, RTCP versus machine axes") {
  CHECK(looks_like_gcode("%\nO1000\nG0 X1 Y2\n"));
  CHECK(looks_like_gcode("(header)\nG1X10Y-5\n"));
  CHECK_FALSE(looks_like_gcode("PARTNO/TEST\nGOTO/1,2,3\n"));
  CHECK_FALSE(looks_like_gcode("$$ comment\nFROM/0,0,100\n"));
  std::istringstream rtcp("G0 X1\nM428 ;TCP\nG1 X2 F1\n");
  CHECK(scan_input_kind(rtcp, "t") == InputKind::rtcp);
  std::istringstream fanuc("G43.4 H1\n");
  CHECK(scan_input_kind(fanuc, "t") == InputKind::rtcp);
  std::istringstream plain("G0 X1 A20\nG43 H1 Z5\n");
  CHECK(scan_input_kind(plain, "t") == InputKind::machine);
}

TEST_CASE("gcode reader: every machine file maps machine-axis programs through its forward kinematics") {
  for (const auto& entry : std::filesystem::directory_iterator(NCPOST_SOURCE_DIR "/machines")) {
    if (entry.path().extension() != ".toml") continue;
    if (machine_file_kind(entry.path().string()) != "serial") continue;  // the TRR-XY machine: no serial chain
    INFO(entry.path().filename().string());
    const Machine m = load_machine(entry.path().string());
    Setup setup;
    setup.workpiece_origin_mm = Vec3d(12, -7, 55);
    setup.tool_length_mm = 120;
    std::string program = "G90 G94\n";
    std::vector<AxisPosition> programmed;
    for (int i = 0; i < 20; ++i) {
      AxisPosition q = home_of(m);
      q.linear_mm = Vec3d(10.0 * i - 50.0, 3.0 * i, -2.5 * i);
      std::string line = fmt::format("G1 X{} Y{} Z{}", q.linear_mm.x(), q.linear_mm.y(), q.linear_mm.z());
      for (int k = 0; k < m.rotary_count(); ++k) {
        const double deg = (k == 0 ? 4.5 : -17.0) * (i - 7);
        q.rotary_rad[k] = deg_to_rad(deg);
        line += fmt::format(" {}{}", m.rotary(k).letter, deg);
      }
      program += line + " F500\n";
      programmed.push_back(q);
    }
    std::istringstream in(program);
    GcodeReaderOptions mapping_only;  // the angles sweep beyond some machines' limits: the mapping is the subject
    mapping_only.check_limits = false;
    GcodeClReader reader(in, "t.ngc", m, setup, mapping_only);
    std::size_t n = 0;
    while (auto r = reader.next()) {
      const auto* mo = std::get_if<cl::Motion>(&*r);
      if (!mo) continue;
      REQUIRE(n < programmed.size());
      const AxisPosition& q = programmed[n++];
      const auto expected = forward(m, q, setup);
      CHECK((mo->point.tip_mm - expected.tip_mm).norm() < 1e-9);
      CHECK((mo->point.axis - expected.axis).norm() < 1e-12);
      if (m.rotary_count() > 0) {
        REQUIRE(mo->rotary_rad);
        CHECK((*mo->rotary_rad - q.rotary_rad).norm() < 1e-12);
        CHECK((linear_for(m, *mo->rotary_rad, mo->point.tip_mm, setup) - q.linear_mm).norm() < 1e-9);
      }
    }
    CHECK(n == programmed.size());
  }
}

TEST_CASE("gcode reader: absolute arc centres (G90.1), the G19 plane and several turns") {
  const auto absolute = motions("G90.1 G1 X10 Y0 Z0 F100\nG3 X0 Y10 I0 J0\n");
  for (std::size_t i = 1; i < absolute.size(); ++i) CHECK(absolute[i].point.tip_mm.head<2>().norm() == Approx(10.0));
  const auto yz = motions("G19 G1 X0 Y5 Z0 F100\nG3 Y0 Z5 J-5 K0\n");
  REQUIRE(yz.size() > 2);
  const Vec3d mid = yz[yz.size() / 2].point.tip_mm;
  CHECK(mid.x() == 0.0);
  CHECK(mid.y() > 0);
  CHECK(mid.z() > 0);  // counter-clockwise seen from +X: from +Y toward +Z
  CHECK(std::hypot(mid.y(), mid.z()) == Approx(5.0));
  const auto one = motions("G1 X5 Y0 Z0 F100\nG2 I-5 Z-2\n");
  const auto three = motions("G1 X5 Y0 Z0 F100\nG2 I-5 Z-2 P3\n");
  const double step = 2.0 * std::acos(1.0 - 1e-3 / 5.0);
  CHECK(one.size() - 1 == static_cast<std::size_t>(std::ceil(2 * kPi / step)));
  CHECK(three.size() - 1 == static_cast<std::size_t>(std::ceil(6 * kPi / step)));
  check_tip(three.back(), 5, 0, -2);
  // the helix descends linearly with the angle
  const double n = static_cast<double>(three.size() - 1);
  for (std::size_t i = 1; i < three.size(); ++i) {
    CHECK(three[i].point.tip_mm.z() == Approx(-2.0 * static_cast<double>(i) / n).margin(1e-9));
    CHECK(three[i].point.tip_mm.head<2>().norm() == Approx(5.0));
  }
}

TEST_CASE("gcode reader: ':' program numbers and labels (ISO O address) move nothing") {
  // nxpost_Fadal_VMC_6030 line 2 and nxpost_MS_SH8000 line 12
  const auto rs = read_all("%\n:1234 (PROGRAM)\nN0100 S485 M03\n:0110 T01 M06\nG0 G90 X1 Y2 Z3 A0 C0\nM30\n%\n");
  const auto tools = only<cl::ToolChange>(rs);
  REQUIRE(tools.size() == 1);
  CHECK(tools[0].number == 1);
  CHECK(tools[0].where.line == 4);
  CHECK(only<cl::Comment>(rs).size() == 1);
  const auto ms = only<cl::Motion>(rs);
  REQUIRE(ms.size() == 1);
  check_tip(ms[0], 1, 2, 3);
}

TEST_CASE("gcode reader: a coordinate with leading zeros and no decimal point (tape format) is refused") {
  // X0019685 is 1.9685 in on a Fanuc reading least increments (0.0001 in), 19685 in as whole units:
  // neither reading is the program's to choose, so it is refused naming the word
  const InputError e = error_of("G20 G90\nG0 X0019685 Y-0008937 Z1. A0 C0\nG1 Z-.1 F10.\nM30\n");
  CHECK(e.where().line == 2);
  CHECK(e.where().column == 4);
  CHECK_THAT(e.detail(), Catch::StartsWith("X0019685: a number without a decimal point but with leading zeros"));
  // whole numbers without leading zeros, and zeros, are read as they are written
  const std::vector<cl::Motion> m = motions("G21 G90\nG0 X20 Y00 Z5 A0 C0\nG1 Z-1 F100\nM30\n");
  REQUIRE(m.size() == 2);
  check_tip(m[1], 20, 0, -1);
}
