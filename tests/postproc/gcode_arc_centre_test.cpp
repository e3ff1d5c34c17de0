// SPDX-License-Identifier: Apache-2.0
// What the I J K of a G2/G3 give (--arc-centre): the vector from the start to the centre (RS274,
// the default), from the centre to the start (NX posts for Fadal/Makino-era controls), or the
// centre itself (G90.1); an arc that does not fit is refused, naming the readings it fits.
// Every centre and end below is worked out by hand in the comment beside it.
#include <catch2/catch.hpp>

#include <stdlib.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "shipped_machines.hpp"
#include "cl_records.hpp"
#include "cli_run.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/read/gcode/gcode_cl_reader.hpp"
#include "temp_dir.hpp"
#include "test_paths.hpp"

using namespace ncpost;
using namespace ncpost::gcode;

namespace {

GcodeReaderOptions reading(ArcCentre arc_centre) {
  GcodeReaderOptions o;
  o.circles = true;  // the arc reaches the post as a Circle (its centre) and its end motion
  o.check_limits = false;
  o.arc_centre = arc_centre;
  return o;
}

std::vector<cl::Record> read_all(const std::string& text, const GcodeReaderOptions& o) {
  std::istringstream in(text);
  GcodeClReader r(in, "t.ngc", test::ac_trunnion(), Setup{}, o);
  return test::all_records(r);
}

InputError error_of(const std::string& text, const GcodeReaderOptions& o) {
  try {
    read_all(text, o);
  } catch (const InputError& e) {
    return e;
  }
  FAIL("no error for: " << text);
  throw;
}

/// The one arc of a program: its Circle and the end motion after it.
struct OneArc {
  cl::Circle circle;
  Vec3d end_mm;
};

OneArc one_arc(const std::string& text, ArcCentre arc_centre) {
  const auto rs = read_all(text, reading(arc_centre));
  const auto circles = test::only<cl::Circle>(rs);
  REQUIRE(circles.size() == 1);
  for (std::size_t i = 0; i < rs.size(); ++i)
    if (std::holds_alternative<cl::Circle>(rs[i])) {
      REQUIRE(i + 1 < rs.size());
      REQUIRE(std::holds_alternative<cl::Motion>(rs[i + 1]));
      return {circles[0], std::get<cl::Motion>(rs[i + 1]).point.tip_mm};
    }
  FAIL("no circle");
  throw;
}

}  // namespace

TEST_CASE("gcode arc centre: each reading of I J, checked on a hand-worked arc") {
  SECTION("incremental (the default): I J from the start to the centre") {
    // start (10, 0); I-10 J0 -> centre (0, 0), radius 10; G3 ends at (0, 10)
    const OneArc a =
        one_arc("G21 G90 G17\nG0 X10 Y0 Z5 A0 C0\nG1 Z0 F100\nG3 X0 Y10 I-10 J0\nM30\n", ArcCentre::incremental);
    CHECK((a.circle.center_mm - Vec3d(0, 0, 0)).norm() < 1e-12);
    CHECK(a.circle.radius_mm == Approx(10.0));
    CHECK((a.circle.axis - Vec3d(0, 0, 1)).norm() < 1e-12);
    CHECK((a.end_mm - Vec3d(0, 10, 0)).norm() < 1e-12);
  }
  SECTION("centre-to-start: I J from the centre to the start") {
    // start (10, 0); I10 J0 -> centre (10 - 10, 0 - 0) = (0, 0); the same arc as above
    const OneArc a =
        one_arc("G21 G90 G17\nG0 X10 Y0 Z5 A0 C0\nG1 Z0 F100\nG3 X0 Y10 I10 J0\nM30\n", ArcCentre::centre_to_start);
    CHECK((a.circle.center_mm - Vec3d(0, 0, 0)).norm() < 1e-12);
    CHECK(a.circle.radius_mm == Approx(10.0));
    CHECK((a.end_mm - Vec3d(0, 10, 0)).norm() < 1e-12);
    // G18 (Z X plane, a1 = Z, a2 = X): start Z10 X0; K10 I0 -> centre Z0 X0; G3 turns from +Z
    // toward +X (counter-clockwise about +Y) to X10 Z0
    const OneArc zx =
        one_arc("G21 G90 G18\nG0 X0 Y0 Z20 A0 C0\nG1 Z10 F100\nG3 X10 Z0 I0 K10\nM30\n", ArcCentre::centre_to_start);
    CHECK((zx.circle.center_mm - Vec3d(0, 0, 0)).norm() < 1e-12);
    CHECK(zx.circle.radius_mm == Approx(10.0));
    CHECK((zx.circle.axis - Vec3d(0, 1, 0)).norm() < 1e-12);
    CHECK((zx.end_mm - Vec3d(10, 0, 0)).norm() < 1e-12);
  }
  SECTION("centre-to-start, the Yama Seiki VMB 1600 sample's line 19 (NX post, inch)") {
    // start X-.3937 Y2.1654; I.2756 J0 -> centre (-.3937 - .2756, 2.1654) = (-.6693, 2.1654) in
    // = (-17.00022, 55.00116) mm; radius .2756 in = 7.00024 mm; the end X-.5118 Y2.3915 lies
    // .27555 in from it (within the reader's 0.01 mm), and the arc leaves the tool's +Y motion
    // tangentially (the start is the circle's point at angle 0, G3 heads +Y there)
    // = (-17.00022, 55.00116) mm; radius .2756 in = 7.00024 mm at the start; the end
    // X-.5118 Y2.3915 = (-12.99972, 60.7441) mm lies hypot(4.0005, 5.74294) = 6.99895 mm from it
    // (within the reader's 0.01 mm: a slight spiral, so points, not a Circle), at 55.1 deg
    GcodeReaderOptions o = reading(ArcCentre::centre_to_start);
    o.circles = false;
    const auto ms =
        test::only<cl::Motion>(read_all("G20 G90 G17\nG0 X-.3937 Y1.9685 Z.1 A0 C0\nG1 Z0 F10\n"
                                        "Y2.1654\nG03 X-.5118 Y2.3915 I.2756 J0\nM30\n",
                                        o));
    REQUIRE(ms.size() > 4);
    const Vec3d centre(-17.00022, 55.00116, 0);
    CHECK((ms.back().point.tip_mm - Vec3d(-12.99972, 60.7441, 0)).norm() < 1e-9);
    for (std::size_t i = 3; i < ms.size(); ++i) {  // the arc's points: from angle 0 to 55.1 deg about the centre
      const Vec3d v = ms[i].point.tip_mm - centre;
      CHECK(v.norm() >= 6.99895 - 1e-9);
      CHECK(v.norm() <= 7.00024 + 1e-9);
      CHECK(std::atan2(v.y(), v.x()) >= 0.0);
      CHECK(std::atan2(v.y(), v.x()) <= std::atan2(5.74294, 4.0005) + 1e-9);
    }
  }
  SECTION("absolute: I J the centre's coordinates") {
    // start (15, 5); I5 J5 -> centre (5, 5), radius 10; G3 ends at (5, 15)
    const OneArc a =
        one_arc("G21 G90 G17\nG0 X15 Y5 Z5 A0 C0\nG1 Z0 F100\nG3 X5 Y15 I5 J5\nM30\n", ArcCentre::absolute);
    CHECK((a.circle.center_mm - Vec3d(5, 5, 0)).norm() < 1e-12);
    CHECK(a.circle.radius_mm == Approx(10.0));
    CHECK((a.end_mm - Vec3d(5, 15, 0)).norm() < 1e-12);
  }
}

TEST_CASE("gcode arc centre: an arc that does not fit names the readings it fits, never switches") {
  const GcodeReaderOptions incremental = reading(ArcCentre::incremental);
  SECTION("fits centre-to-start") {
    // incremental: centre (20, 0), radius 10 at the start, hypot(20, 10) = 22.3607 at the end
    const InputError e = error_of("G21 G90\nG0 X10 Y0 Z5 A0 C0\nG1 Z0 F100\nG3 X0 Y10 I10 J0\nM30\n", incremental);
    CHECK(e.where().line == 4);
    CHECK(e.where().column == 1);
    CHECK(e.detail() ==
          "the end point is not on the arc: radius 10.0000 mm at the start, 22.3607 mm at the end (they may differ "
          "by 0.0100 mm); it fits if I and J "
          "are the vector from the centre to the start: post with --arc-centre centre-to-start");
  }
  SECTION("fits absolute") {
    // incremental: centre (20, 10), radius 7.0711 at the start, hypot(15, 5) = 15.8114 at the end
    const InputError e = error_of("G21 G90\nG0 X15 Y5 Z5 A0 C0\nG1 Z0 F100\nG3 X5 Y15 I5 J5\nM30\n", incremental);
    CHECK(e.detail() ==
          "the end point is not on the arc: radius 7.0711 mm at the start, 15.8114 mm at the end (they may differ by "
          "0.0100 mm); it fits if I and J "
          "are the centre's coordinates: post with --arc-centre absolute");
  }
  SECTION("fits incremental, read centre-to-start") {
    // centre-to-start: centre (20, 0), as above
    const InputError e = error_of("G21 G90\nG0 X10 Y0 Z5 A0 C0\nG1 Z0 F100\nG3 X0 Y10 I-10 J0\nM30\n",
                                  reading(ArcCentre::centre_to_start));
    CHECK_THAT(e.detail(), Catch::EndsWith("; it fits if I and J are the vector from the start to the centre: post "
                                           "with --arc-centre incremental"));
  }
  SECTION("fits two readings") {
    // start (10, 0), I5 J0, G3 to (5, 5): incremental centre (15, 0), radius 5 at the start, 10
    // at the end; centre-to-start (10 - 5, 0) and absolute (5, 0) are the same centre, radius 5
    const InputError e = error_of("G21 G90\nG0 X10 Y0 Z5 A0 C0\nG1 Z0 F100\nG3 X5 Y5 I5 J0\nM30\n", incremental);
    CHECK_THAT(e.detail(),
               Catch::EndsWith("; it fits if I and J are the vector from the centre to the start (--arc-centre "
                               "centre-to-start), or if I and J are the centre's coordinates (--arc-centre absolute): "
                               "post with the one the program's control uses"));
  }
  SECTION("fits only without the signs") {
    // true centre (4, 3), radius sqrt(45), from (10, 0) to (-2, 6); written I6 J3 (signs dropped):
    // incremental (16, 3), centre-to-start (4, -3), absolute (6, 3) all miss the end
    const InputError e = error_of("G21 G90\nG0 X10 Y0 Z5 A0 C0\nG1 Z0 F100\nG3 X-2 Y6 I6 J3\nM30\n", incremental);
    CHECK_THAT(e.detail(), Catch::EndsWith("; it fits only if I and J are distances without their signs, a writing "
                                           "ncpost does not read (the centre is then a guess): post the CL data, or a "
                                           "program with signed I and J"));
  }
  SECTION("fits none") {
    const InputError e = error_of("G21 G90\nG0 X10 Y0 Z5 A0 C0\nG1 Z0 F100\nG3 X0 Y12 I-10\nM30\n", incremental);
    // centre-to-start (20, 0): radii 10 and hypot(20, 12) = 23.3238; absolute (-10, 0): radii 20 and
    // hypot(10, 12) = 15.6205, nearer
    CHECK_THAT(e.detail(), Catch::EndsWith("; no other reading of I and J (from the start, from the centre, absolute, "
                                           "unsigned) fits it either (the nearest: if I and J are the centre's "
                                           "coordinates, radius 20.0000 mm at the start, 15.6205 mm at the end)"));
  }
  SECTION("the program's G90.1 is named, not --arc-centre") {
    const InputError e =
        error_of("G21 G90 G90.1\nG0 X10 Y0 Z5 A0 C0\nG1 Z0 F100\nG3 X0 Y10 I-10 J0\nM30\n", incremental);
    CHECK_THAT(e.detail(), Catch::EndsWith("; it fits if I and J are the vector from the start to the centre, but "
                                           "G90.1 at line 1 says I and J are the centre's coordinates"));
  }
  SECTION("a full circle fits every reading: it takes the one chosen") {
    // start (10, 0), I10 J0: centre (20, 0) incremental, (0, 0) centre-to-start
    const std::string full = "G21 G90\nG0 X10 Y0 Z5 A0 C0\nG1 Z0 F100\nG3 I10 J0\nM30\n";
    CHECK((one_arc(full, ArcCentre::incremental).circle.center_mm - Vec3d(20, 0, 0)).norm() < 1e-12);
    CHECK((one_arc(full, ArcCentre::centre_to_start).circle.center_mm - Vec3d(0, 0, 0)).norm() < 1e-12);
  }
}

TEST_CASE("gcode arc centre: G90.1 and G91.1 beside a --arc-centre they contradict are refused") {
  const std::string arc = "G0 X10 Y0 Z5 A0 C0\nG1 Z0 F100\nG3 X0 Y10 I10 J0\nM30\n";
  const InputError g91 = error_of("G21 G90 G91.1\n" + arc, reading(ArcCentre::centre_to_start));
  CHECK(g91.where().line == 1);
  CHECK(g91.where().column == 9);
  CHECK(g91.detail() ==
        "G91.1 says I, J and K are the vector from the start to the centre (incremental), which "
        "contradicts --arc-centre centre-to-start: post without --arc-centre centre-to-start (the "
        "program says how it writes arc centres)");
  CHECK_THAT(error_of("G21 G90 G90.1\n" + arc, reading(ArcCentre::centre_to_start)).detail(),
             Catch::StartsWith("G90.1 says I, J and K are the centre's coordinates (absolute), which contradicts "
                               "--arc-centre centre-to-start"));
  CHECK_THAT(error_of("G21 G90 G91.1\n" + arc, reading(ArcCentre::absolute)).detail(),
             Catch::StartsWith("G91.1 says I, J and K are the vector from the start to the centre (incremental)"));
  // agreeing words are taken
  CHECK((one_arc("G21 G90 G90.1\nG0 X15 Y5 Z5 A0 C0\nG1 Z0 F100\nG3 X5 Y15 I5 J5\nM30\n", ArcCentre::absolute)
             .circle.center_mm -
         Vec3d(5, 5, 0))
            .norm() < 1e-12);
}

TEST_CASE("gcode arc centre: ncpost post --arc-centre centre-to-start writes the arc with RS274 I J") {
  const std::string dir = ncpost::test::make_temp_dir("ncpost_arc_centre");
  REQUIRE(dir != ".");
  const std::string program = std::string(dir) + "/c2s.ngc";
  std::ofstream(program) << "G21 G90 G17\nG0 X10 Y0 Z10 A0 C0\nG1 Z0 F100\nG3 X0 Y10 I10 J0\nG0 Z10\nM30\n";
  const std::string out = std::string(dir) + "/out.nc", log = std::string(dir) + "/log";
  const std::string common = "post --machine " + test::source("machines/ac-trunnion.toml") + " -o " + out + " ";
  CHECK(test::run_ncpost(common + "--arc-centre centre-to-start " + program, log) == 0);
  // the centre (0, 0): from the start (10, 0) the vector I-10 J0
  CHECK_THAT(test::read_text_file(out), Catch::Contains("\nG3 X0.0000 Y10.0000 Z0.0000 I-10.0000 J0.0000\n"));
  CHECK(test::run_ncpost(common + program, log) == 2);
  CHECK_THAT(test::read_text_file(log), Catch::Contains("c2s.ngc:4:1: the end point is not on the arc") &&
                                            Catch::Contains("post with --arc-centre centre-to-start"));
}

TEST_CASE("gcode arc centre: I J and R are not modal; one omitted centre word is 0") {
  const GcodeReaderOptions o = reading(ArcCentre::incremental);
  // nxpost_Mori_Seiki_Dura_Vert5100 lines 32-33: a full circle with I J, then an arc without them
  const InputError ij = error_of(
      "G20 G90\nG0 X1.1811 Y1.9685 Z.1 A0 C0\nG1 Z0 F10\nG17 G03 I.7874 J0\nX1.2056 Y1.7737\n"
      "M30\n",
      o);
  CHECK(ij.where().line == 5);
  CHECK(ij.detail() ==
        "an arc needs I and J (its centre) or R; they are not modal: the I and J of the arc at line 4 "
        "are not carried over (write the centre or R on every arc)");
  // nxpost_LeBlond_Makino_KE_55 lines 322-324: an R arc, a line, an arc without R
  const InputError r = error_of(
      "G20 G90\nG0 X0 Y1.9685 Z.1 A0 C0\nG1 Z0 F10\nG02X0.0Y2.1329R.1644\nG01X1.9685\n"
      "G02X2.1329Y1.9685\nM30\n",
      o);
  CHECK(r.where().line == 6);
  CHECK_THAT(r.detail(), Catch::EndsWith("the R of the arc at line 4 is not carried over (write the centre or R on "
                                         "every arc)"));
  CHECK(error_of("G21 G90\nG0 X10 Y0 Z5 A0 C0\nG1 Z0 F100\nG3 X0 Y10\nM30\n", o).detail() ==
        "an arc needs I and J (its centre) or R");
  // J omitted (RS274NGC, Fanuc: 0): start (10, 0), I-10 -> centre (0, 0); G3 to (-10, 0)
  const OneArc a = one_arc("G21 G90\nG0 X10 Y0 Z5 A0 C0\nG1 Z0 F100\nG3 X-10 Y0 I-10\nM30\n", ArcCentre::incremental);
  CHECK((a.circle.center_mm - Vec3d(0, 0, 0)).norm() < 1e-12);
  CHECK((a.end_mm - Vec3d(-10, 0, 0)).norm() < 1e-12);
  // I omitted: start (0, -10), J10 -> centre (0, 0); G3 to (0, 10)
  const OneArc b = one_arc("G21 G90\nG0 X0 Y-10 Z5 A0 C0\nG1 Z0 F100\nG3 X0 Y10 J10\nM30\n", ArcCentre::incremental);
  CHECK((b.circle.center_mm - Vec3d(0, 0, 0)).norm() < 1e-12);
  CHECK((b.end_mm - Vec3d(0, 10, 0)).norm() < 1e-12);
}

TEST_CASE("gcode arcs: I J alone under a modal G3 is the full circle G3 with its end at its start (Fanuc)") {
  // NX's LeBlond Makino post: N2250 G03 X... I... J..., N2260 I-.9193 J0.0 F.8
  const std::string head = "G21 G90 G17\nG0 X10 Y0 Z5 A0 C0\nG1 Z0 F100\n";
  const std::string modal = head + "G3 X0 Y10 I-10 J0\nI0 J-10 F80\nG0 Z5\nM30\n";
  const std::string written = head + "G3 X0 Y10 I-10 J0\nG3 X0 Y10 I0 J-10 F80\nG0 Z5\nM30\n";
  const auto a = read_all(modal, reading(ArcCentre::incremental));
  const auto b = read_all(written, reading(ArcCentre::incremental));
  const auto ca = test::only<cl::Circle>(a), cb = test::only<cl::Circle>(b);
  REQUIRE(ca.size() == 2);
  REQUIRE(cb.size() == 2);
  CHECK((ca[1].center_mm - Vec3d(0, 0, 0)).norm() < 1e-12);  // the second circle's centre: (0, 10) + (0, -10)
  CHECK(ca[1].radius_mm == Approx(10.0));
  CHECK((ca[1].axis - cb[1].axis).norm() < 1e-12);  // counter-clockwise, as G3
  const auto ma = test::only<cl::Motion>(a), mb = test::only<cl::Motion>(b);
  REQUIRE(ma.size() == mb.size());
  for (std::size_t i = 0; i < ma.size(); ++i) CHECK((ma[i].point.tip_mm - mb[i].point.tip_mm).norm() < 1e-12);
  // under LinuxCNC's reading the block stays refused (its behaviour there is not confirmed)
  GcodeReaderOptions linuxcnc = reading(ArcCentre::incremental);
  linuxcnc.control = cl::ControlFamily::linuxcnc;
  CHECK_THAT(std::string(error_of(modal, linuxcnc).what()), Catch::Contains("I without an arc"));
}
