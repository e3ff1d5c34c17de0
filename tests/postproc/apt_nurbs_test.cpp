// SPDX-License-Identifier: Apache-2.0
// NX NURBS records: the rational B-spline evaluated and linearized within the curve tolerance.
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

#include "ncpost/postproc/read/apt/apt_nurbs.hpp"
#include "ncpost/postproc/read/apt/apt_reader.hpp"

using namespace ncpost;

namespace {

std::vector<cl::Motion> motions(const std::string& text, cl::ReaderOptions o = {}) {
  std::istringstream in(text);
  cl::AptReader r(in, "n.cls", o);
  std::vector<cl::Motion> out;
  while (auto x = r.next())
    if (auto* m = std::get_if<cl::Motion>(&*x)) out.push_back(*m);
  return out;
}

std::string error_of(const std::string& text) {
  try {
    motions(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const char* const kQuarterCircle =  // radius 50 about the origin, as a rational quadratic
    "GOTO/50,0,0,0,0,1\n"
    "NURBS/\n"
    "KNOT/0,0,0,1,1,1\n"
    "CNTRL/50,0,0,1\n"
    "CNTRL/50,50,0,0.70710678118654757\n"
    "CNTRL/0,50,0,1\n"
    "GOTO/0,50,0,0,0,1\n"
    "FINI\n";

}  // namespace

TEST_CASE("a quarter circle as a rational spline: every point on the circle, every chord within the tolerance") {
  for (const double tol : {0.01, 0.001}) {
    INFO("tolerance " << tol);
    cl::ReaderOptions o;
    o.curve_tolerance_mm = tol;
    const auto m = motions(kQuarterCircle, o);
    REQUIRE(m.size() >= 3);
    CHECK(m.front().point.tip_mm == Vec3d(50, 0, 0));
    CHECK(m.back().point.tip_mm == Vec3d(0, 50, 0));
    CHECK(m.back().where.line == 7);  // the GOTO at the curve's end is its last motion
    // the chords a circle of radius 50 needs at this tolerance: sagitta R (1 - cos(a/2)) <= tol
    const double step = 2.0 * std::acos(1.0 - tol / 50.0);
    const auto needed = static_cast<std::size_t>(std::ceil(0.5 * M_PI / step));
    const std::size_t chords = m.size() - 1;
    CHECK(chords >= needed);
    CHECK(chords <= 4 * needed);
    double worst = 0.0;
    for (std::size_t i = 1; i < m.size(); ++i) {
      const Vec3d a = m[i - 1].point.tip_mm, b = m[i].point.tip_mm;
      CHECK(std::abs(b.norm() - 50.0) < 1e-9);
      CHECK(b.z() == 0.0);
      const double angle = std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0));
      worst = std::max(worst, 50.0 * (1.0 - std::cos(0.5 * angle)));  // the exact sagitta of the chord
      CHECK(std::atan2(b.y(), b.x()) > std::atan2(a.y(), a.x()));     // in order, counter-clockwise
    }
    CHECK(worst <= tol);
    CHECK(worst > 0.25 * tol);  // not needlessly fine
  }
}

TEST_CASE("NURBS: degree from the counts, KNOT/CNTRL on one line, tool axis blended to the end GOTO's") {
  // a cubic Bezier as a B-spline (weights 1): C(0.5) = (P0 + 3 P1 + 3 P2 + P3) / 8
  cl::NurbsCurve c;
  c.degree = 3;
  c.knots = {0, 0, 0, 0, 2, 2, 2, 2};
  c.points_mm = {Vec3d(0, 0, 0), Vec3d(10, 20, 0), Vec3d(30, 20, 5), Vec3d(40, 0, 5)};
  c.weights = {1, 1, 1, 1};
  CHECK(c.defect().empty());
  CHECK((c.point_at(1.0) - Vec3d(20, 15, 2.5)).norm() < 1e-12);
  const std::string file =
      "GOTO/0,0,0,0,0,1\nNURBS/\nKNOT/0,CNTRL/0,0,0\nKNOT/0\nKNOT/0\nKNOT/0,CNTRL/10,20,0\nKNOT/2,CNTRL/30,20,5\n"
      "KNOT/2,CNTRL/40,0,5\nKNOT/2\nKNOT/2\nGOTO/40,0,5,0,0.6,0.8\nFINI\n";
  const auto m = motions(file);
  REQUIRE(m.size() > 10);
  for (const auto& x : m) {
    // every point on the curve: its distance to the curve's samples is tiny
    double best = 1e9;
    for (int i = 0; i <= 200000; ++i) best = std::min(best, (c.point_at(i * 1e-5) - x.point.tip_mm).norm());
    CHECK(best < 1e-3);
    CHECK(std::abs(x.point.axis.norm() - 1.0) < 1e-12);
    CHECK(x.point.axis.x() == 0.0);
  }
  CHECK((m.back().point.axis - Vec3d(0, 0.6, 0.8)).norm() < 1e-12);
  CHECK(m[m.size() / 2].point.axis.y() > 0.05);
  CHECK(m[m.size() / 2].point.axis.y() < 0.55);
  // a GOTO elsewhere after the curve: the curve ends with the current axis, then the GOTO moves
  const auto away = motions("GOTO/0,0,0\nNURBS/\nKNOT/0,0,1,1\nCNTRL/0,0,0\nCNTRL/10,0,0\nGOTO/10,5,0\nFINI\n");
  REQUIRE(away.size() == 3);
  CHECK(away[1].point.tip_mm == Vec3d(10, 0, 0));
  CHECK(away[2].point.tip_mm == Vec3d(10, 5, 0));
  // tool axes on the control points are a spline too
  const auto axes = motions("GOTO/0,0,0\nNURBS/\nKNOT/0,0,1,1\nCNTRL/0,0,0,0,0,1\nCNTRL/10,0,0,0,1,0\nEND\n");
  REQUIRE(axes.size() == 2);
  CHECK(axes[1].point.axis == Vec3d(0, 1, 0));
}

TEST_CASE("NURBS: bad curves are refused naming the line") {
  {
    cl::NurbsCurve big;  // a circle of radius 1e6 mm: 90 degrees need 5,554 chords at 0.01 mm
    big.degree = 2;
    big.knots = {0, 0, 0, 1, 1, 1};
    big.points_mm = {Vec3d(1e6, 0, 0), Vec3d(1e6, 1e6, 0), Vec3d(0, 1e6, 0)};
    big.weights = {1, std::sqrt(0.5), 1};
    CHECK(cl::linearize(big, 0.01, 1000).empty());
    const double needed = 0.5 * M_PI / (2.0 * std::acos(1.0 - 0.01 / 1e6));
    CHECK(cl::linearize(big, 0.01).size() - 1 >= static_cast<std::size_t>(std::ceil(needed)));
  }
  CHECK_THAT(error_of("GOTO/0,0,0\nNURBS/DEGREE,3\nKNOT/0,0,1,1\nCNTRL/0,0,0\nCNTRL/10,0,0\nFINI\n"),
             Catch::Contains("n.cls:2:1") && Catch::Contains("2 control points for degree 3 (expected at least 4)"));
  CHECK_THAT(error_of("GOTO/0,0,0\nNURBS/ORDER,2\nKNOT/0,0,0,1,1\nCNTRL/0,0,0\nCNTRL/10,0,0\nFINI\n"),
             Catch::Contains("n.cls:2:1") && Catch::Contains("5 knots for 2 control points of degree 1 (expected 4)"));
  CHECK_THAT(error_of("GOTO/5,0,0\nNURBS/\nKNOT/0,0,1,1\nCNTRL/0,0,0\nCNTRL/10,0,0\nFINI\n"),
             Catch::Contains("n.cls:2:1") && Catch::Contains("starts 5.0000 mm away"));
  CHECK_THAT(error_of("GOTO/0,0,0\nKNOT/0,0,1,1\nFINI\n"),
             Catch::Contains("n.cls:2:1") && Catch::Contains("outside a NURBS"));
  CHECK_THAT(error_of("GOTO/0,0,0\nNURBS/\nKNOT/0,1,0,1\nCNTRL/0,0,0\nCNTRL/10,0,0\nFINI\n"),
             Catch::Contains("less than the one before"));
  CHECK_THAT(error_of("GOTO/0,0,0\nNURBS/\nKNOT/0,0,1,1\nCNTRL/0,0,0,0\nCNTRL/10,0,0,1\nFINI\n"),
             Catch::Contains("weight"));
  CHECK_THAT(error_of("NURBS/\nKNOT/0,0,1,1\nCNTRL/0,0,0\nCNTRL/10,0,0\nFINI\n"), Catch::Contains("before any motion"));
  // a degree that is no whole number of a sensible size (found by fuzz_apt_reader: 1.7e17 overflowed the int cast)
  CHECK_THAT(error_of("GOTO/0,0,0\nNURBS/DEGREE,170710678118654757\nKNOT/0,0,1,1\nFINI\n"),
             Catch::Contains("n.cls:2:1") && Catch::Contains("DEGREE must be a whole number from 0 to 1000"));
  CHECK_THAT(error_of("GOTO/0,0,0\nNURBS/ORDER,2.5\nFINI\n"), Catch::Contains("ORDER must be a whole number"));
  CHECK_THAT(error_of("GOTO/0,0,0\nNURBS/DEGREE,-3\nFINI\n"), Catch::Contains("DEGREE must be a whole number"));
}

TEST_CASE("NURBS: NX's short form (knots after 0, the first control point is the tool position)") {
  // HumMan/CLSFProcessor samples/nurbs.clsf writes "GOTO/start, NURBS/, KNOT/0.0417,0.375,0.625,0.9583,1,
  // 7 x CNTRL": degree 3 = 7 control points - 4 interior knots. Here the same form, hand-checkable:
  // degree 2 (2 control points, no interior knot) over (0,0,0), (1,1,0), (2,0,0): the parabola
  // x = 2u, y = 2u(1-u), i.e. y = x - x^2/2, from the GOTO to (2,0,0).
  const auto m = motions("GOTO/0,0,0\nNURBS/\nKNOT/1.0\nCNTRL/1,1,0\nCNTRL/2,0,0\nGOTO/2,0,0\nFINI\n");
  REQUIRE(m.size() >= 3);
  CHECK(m.front().point.tip_mm == Vec3d(0, 0, 0));
  CHECK(m.back().point.tip_mm == Vec3d(2, 0, 0));
  for (std::size_t i = 1; i < m.size(); ++i) {
    const Vec3d p = m[i].point.tip_mm;
    CHECK(p.y() == Approx(p.x() - p.x() * p.x() / 2.0).margin(1e-12));
    CHECK(p.x() > m[i - 1].point.tip_mm.x());
  }
  // degree 3 with an interior knot at 0.5: 4 control points after the start, 1 interior knot; a
  // straight line with the control points evenly spaced in pieces: the curve stays on the X axis
  // and ends at the last control point
  const auto line =
      motions("GOTO/0,0,0\nNURBS/\nKNOT/0.5,1\nCNTRL/1,0,0\nCNTRL/2,0,0\nCNTRL/3,0,0\nCNTRL/4,0,0\nGOTO/4,0,0\nFINI\n");
  REQUIRE(line.size() >= 2);
  CHECK(line.back().point.tip_mm == Vec3d(4, 0, 0));
  for (const auto& x : line) CHECK(x.point.tip_mm.y() == 0.0);
  // weights cannot be completed (the start point's is not written): refused
  CHECK_THAT(error_of("GOTO/0,0,0\nNURBS/\nKNOT/1\nCNTRL/1,1,0,0.5\nCNTRL/2,0,0,1\nFINI\n"),
             Catch::Contains("n.cls:2:1") && Catch::Contains("weighted control points in NX's short form"));
  // too few control points for the knots, read either way: refused as before
  CHECK_THAT(error_of("GOTO/0,0,0\nNURBS/\nKNOT/0.2,0.4,0.6,1\nCNTRL/1,1,0\nFINI\n"), Catch::Contains("n.cls:2:1"));
}
