// SPDX-License-Identifier: Apache-2.0
// Klartext circular paths (klartext_arc.hpp, klartext_reader.hpp): CC + C, CR with R+ and R-, CT,
// CP helices (several turns: points) and CP to a polar angle. Centres, directions and end points
// are worked out by hand from the TNC's rules (DR+ counter-clockwise seen from +Z; CR R+ the arc up
// to 180 deg; CT tangential to the element before it) on the AC trunnion at A0 C0 with the
// workpiece origin at the machine origin, where W coordinates are the program's.
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

#include "cl_records.hpp"
#include "shipped_machines.hpp"
#include "ncpost/kinematics/pose.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/postproc/read/klartext/klartext_arc.hpp"
#include "ncpost/postproc/read/klartext/klartext_reader.hpp"

using namespace ncpost;
using test::only;

namespace {

std::vector<cl::Record> read(const std::string& text) {
  std::istringstream in(text);
  klartext::KlartextReader r(in, "arcs.h", test::ac_trunnion(), Setup{});
  return test::all_records(r);
}

std::string error_of(const std::string& text) {
  try {
    read(text);
  } catch (const InputError& e) {
    return e.what();
  }
  FAIL("no input error for: " << text);
  return {};
}

void check_point(const Vec3d& p, double x, double y, double z) {
  CHECK(p.x() == Approx(x).margin(1e-9));
  CHECK(p.y() == Approx(y).margin(1e-9));
  CHECK(p.z() == Approx(z).margin(1e-9));
}

/// The motions of one source line.
std::vector<cl::Motion> of_line(const std::vector<cl::Motion>& ms, int line) {
  std::vector<cl::Motion> out;
  for (const auto& m : ms)
    if (m.where.line == line) out.push_back(m);
  return out;
}

}  // namespace

TEST_CASE("klartext arcs: C about CC, CR R+ and R-, CT, CP helix and CP PA") {
  const auto rs = read(
      "0 BEGIN PGM ARCS MM\n"                  // line 1
      "1 TOOL CALL 1 Z S1000\n"                // 2
      "2 L X+10 Y+0 Z+0 A+0 C+0 R0 FMAX M3\n"  // 3
      "3 CC X+0 Y+0\n"                         // 4
      "4 C X+0 Y+10 DR+ F100\n"                // 5: quarter circle counter-clockwise
      "5 C X+10 Y+0 DR-\n"                     // 6: back clockwise
      "6 CR X+30 Y+0 R+10 DR+\n"               // 7: half circle, centre (20, 0)
      "7 CR X+40 Y+10 R-10 DR-\n"              // 8: 270 deg clockwise, centre (30, 10)
      "8 CT X+30 Y+20\n"                       // 9: leaves (40, 10) downwards: centre (30, 10), clockwise
      "9 CC X+30 Y+10\n"                       // 10
      "10 CP IPA+720 IZ-4 DR+\n"               // 11: two turns down 4 mm
      "11 CP PA+0 DR-\n"                       // 12: from 90 deg clockwise to 0 deg
      "12 END PGM ARCS MM\n");
  const auto circles = only<cl::Circle>(rs);
  const auto ms = only<cl::Motion>(rs);
  REQUIRE(circles.size() == 6);
  const int lines[] = {5, 6, 7, 8, 9, 12};
  const Vec3d centres[] = {{0, 0, 0}, {0, 0, 0}, {20, 0, 0}, {30, 10, 0}, {30, 10, 0}, {30, 10, -4}};
  const double turn[] = {+1, -1, +1, -1, -1, -1};  // the sense about +Z
  const Vec3d ends[] = {{0, 10, 0}, {10, 0, 0}, {30, 0, 0}, {40, 10, 0}, {30, 20, 0}, {40, 10, -4}};
  for (int i = 0; i < 6; ++i) {
    INFO("circle of line " << lines[i]);
    CHECK(circles[static_cast<std::size_t>(i)].where.line == lines[i]);
    check_point(circles[static_cast<std::size_t>(i)].center_mm, centres[i].x(), centres[i].y(), centres[i].z());
    CHECK((circles[static_cast<std::size_t>(i)].axis - turn[i] * Vec3d::UnitZ()).norm() < 1e-12);
    CHECK(circles[static_cast<std::size_t>(i)].radius_mm == Approx(10.0));
    const auto end = of_line(ms, lines[i]);
    REQUIRE(end.size() == 1);
    check_point(end[0].point.tip_mm, ends[i].x(), ends[i].y(), ends[i].z());
  }
  // the helix: points on the cylinder of radius 10 about (30, 10), Z falling with the angle
  const auto helix = of_line(ms, 11);
  REQUIRE(helix.size() > 100);
  const double n = static_cast<double>(helix.size());
  for (std::size_t k = 0; k < helix.size(); ++k) {
    const double t = static_cast<double>(k + 1) / n;
    const double angle = kPi / 2 + t * 4 * kPi;
    INFO("helix point " << k);
    check_point(helix[k].point.tip_mm, 30 + 10 * std::cos(angle), 10 + 10 * std::sin(angle), -4 * t);
  }
  // chord error within 1 µm: the sagitta of the step
  const double step = 4 * kPi / n;
  CHECK(10 * (1 - std::cos(step / 2)) <= 1e-3 + 1e-12);
}

TEST_CASE("klartext arcs: CR picks the centre by the sign of R and the direction") {
  klartext::ProgramPoint s{}, e{};
  e[0] = 10;
  e[1] = 10;
  const auto short_ccw = klartext::arc_by_radius(s, e, 10, true);
  REQUIRE(short_ccw.arc);
  CHECK(short_ccw.arc->centre1_mm == Approx(0).margin(1e-12));
  CHECK(short_ccw.arc->centre2_mm == Approx(10));
  CHECK(short_ccw.arc->sweep_rad == Approx(kPi / 2));
  const auto long_ccw = klartext::arc_by_radius(s, e, -10, true);
  REQUIRE(long_ccw.arc);
  CHECK(long_ccw.arc->centre1_mm == Approx(10));
  CHECK(long_ccw.arc->centre2_mm == Approx(0).margin(1e-12));
  CHECK(long_ccw.arc->sweep_rad == Approx(3 * kPi / 2));
  const auto short_cw = klartext::arc_by_radius(s, e, 10, false);
  REQUIRE(short_cw.arc);
  CHECK(short_cw.arc->centre1_mm == Approx(10));
  CHECK(short_cw.arc->sweep_rad == Approx(-kPi / 2));
  CHECK_FALSE(klartext::arc_by_radius(s, e, 5, true).arc);  // the chord is longer than the diameter
  CHECK(klartext::sweep_between(0, 0, true) == Approx(2 * kPi));
  CHECK(klartext::sweep_between(0, 0, false) == Approx(-2 * kPi));
}

TEST_CASE("klartext arcs: what the TNC refuses is refused with the line") {
  const std::string head = "0 BEGIN PGM A MM\n1 L X+10 Y+0 Z+0 A+0 C+0 R0 FMAX\n2 CC X+0 Y+0\n";
  CHECK_THAT(error_of(head + "3 C X+0 Y+11 DR+\n4 END PGM A MM\n"), Catch::Contains("arcs.h:4:3: C: the end point is"));
  CHECK_THAT(error_of(head + "3 C X+0 Y+10\n4 END PGM A MM\n"), Catch::Contains("without DR+ or DR-"));
  CHECK_THAT(error_of(head + "3 CP IPA-90 DR+\n4 END PGM A MM\n"), Catch::Contains("signs of IPA and DR differ"));
  CHECK_THAT(error_of(head + "3 L X+20\n4 CT X+30 Y+0\n5 END PGM A MM\n"), Catch::Contains("a line, not an arc"));
  CHECK_THAT(error_of(head + "3 C X+0 Y+10 Z+5 DR+\n4 END PGM A MM\n"),
             Catch::Contains("a helix is programmed with CP"));
  CHECK_THAT(error_of("0 BEGIN PGM A MM\n1 CT X+1 Y+1\n2 END PGM A MM\n"),
             Catch::Contains("arcs.h:2:3: CT before X, Y and Z"));
}
