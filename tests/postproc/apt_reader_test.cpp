// SPDX-License-Identifier: Apache-2.0
// The APT reader on the quirks of real CAM files (tests/data/real/SOURCES.md) and on bad input.
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>
#include <vector>

#include "cl_records.hpp"
#include "ncpost/postproc/read/apt/apt_reader.hpp"
#include "test_paths.hpp"

using namespace ncpost;

namespace {

/// Reads a snippet (snippets end without FINI: apt_grammar_test checks that rule).
std::vector<cl::Record> read_all(const std::string& text, cl::ReaderOptions o = {}) {
  o.allow_unterminated = true;
  std::istringstream in(text);
  cl::AptReader r(in, "t.cls", o);
  std::vector<cl::Record> out = test::all_records(r);
  return out;
}

using test::only;

/// The InputError message of reading `text`, or "" if it reads.
std::string error_of(const std::string& text) {
  try {
    read_all(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("numbers as CAM systems write them") {
  const auto m = only<cl::Motion>(read_all("GOTO/25.,.5,-0.000000,.5773503E+00,.5773503E+00,.5773503E+00\n"));
  REQUIRE(m.size() == 1);
  CHECK(m[0].point.tip_mm == Vec3d(25.0, 0.5, 0.0));
  CHECK(m[0].point.axis.x() == Approx(1.0 / std::sqrt(3.0)).epsilon(1e-6));
  CHECK(m[0].axis_given);
}

TEST_CASE("$ continuation may split a number (CATIA)") {
  const auto m =
      only<cl::Motion>(read_all("FROM  / -26.370000,   0.000000,  46.745000,  -1.000000,   0.000000,   0$\n.000000\n"));
  REQUIRE(m.size() == 1);
  CHECK(m[0].from);
  CHECK(m[0].point.tip_mm.x() == Approx(-26.37));
  CHECK(m[0].point.axis == Vec3d(-1, 0, 0));
}

TEST_CASE("spaces around / and , , CRLF, trailing commas, UNITS and UNIT") {
  const auto rs = read_all("UNIT/INCHES\r\nGOTO / 1.0 , 2.0 , 3.0,\r\nUNITS / MM\r\nGOTO/1,2,3\r\n");
  const auto m = only<cl::Motion>(rs);
  REQUIRE(m.size() == 2);
  CHECK((m[0].point.tip_mm - Vec3d(25.4, 50.8, 76.2)).norm() < 1e-12);
  CHECK(m[1].point.tip_mm == Vec3d(1, 2, 3));
}

TEST_CASE("a 3-value GOTO keeps the last tool axis; RAPID and RAPID/ mark one motion") {
  const auto m =
      only<cl::Motion>(read_all("RAPID\nGOTO/0,0,0,0,0.6,0.8\nGOTO/1,1,1\nRAPID/\nGOTO/2,2,2\nGOTO/3,3,3\n"));
  REQUIRE(m.size() == 4);
  CHECK(m[0].rapid);
  CHECK_FALSE(m[1].rapid);
  CHECK((m[1].point.axis - Vec3d(0, 0.6, 0.8)).norm() < 1e-12);
  CHECK_FALSE(m[1].axis_given);
  CHECK(m[2].rapid);
  CHECK_FALSE(m[3].rapid);
}

TEST_CASE("FEDRAT in both argument orders and units") {
  const auto f =
      only<cl::Feed>(read_all("UNITS/MM\nFEDRAT/MMPM,250\nFEDRAT/ 1000.0,MMPM\nFEDRAT/IPM,10.0000\nFEDRAT/0.1,MMPR\n"));
  REQUIRE(f.size() == 4);
  CHECK(f[0].value == 250.0);
  CHECK(f[1].value == 1000.0);
  CHECK(f[2].value == Approx(254.0));
  CHECK(f[3].per_rev);
}

TEST_CASE("NX: TOOL PATH with a space, listing headers, MSYS as information, END-OF-PATH") {
  const auto rs = read_all(
      "\nInformation listing created by\tphill\nTOOL PATH/NORM_PART,TOOL,BALL_MILL_1.00\n"
      "MSYS/3.0,3.0,0.0,1,0,0,0,1,0\nGOTO/1,2,3\nEND-OF-PATH\n");
  CHECK(only<cl::Unsupported>(rs).size() == 1);  // the listing header, passed through
  CHECK(only<cl::Comment>(rs).size() == 2);
  CHECK(only<cl::End>(rs).size() == 1);
  const auto m = only<cl::Motion>(rs);
  REQUIRE(m.size() == 1);
  CHECK(m[0].point.tip_mm == Vec3d(1, 2, 3));  // MSYS is not applied (NX's posts keep GOTO as is)
}

TEST_CASE("Creo: CIRCLE over two lines, $$-> comments, CYCLE/DEEP, FINI") {
  const auto rs = read_all(
      "$$-> CSYS / 1,0,0,0,  $\n  0,1,0,0\nCIRCLE / -16.7, -22.9, -0.24,  $\n0.0, 0.0, 1.0,  0.896\n"
      "GOTO / 1, 2, 3\nCYCLE / DEEP, DEPTH, 3.5, STEP, 1.0, MMPM, 50.0, CLEAR,$\n 1.0\nCYCLE / OFF\nFINI\n");
  const auto c = only<cl::Circle>(rs);
  REQUIRE(c.size() == 1);
  CHECK(c[0].radius_mm == Approx(0.896));
  CHECK(c[0].center_mm.y() == Approx(-22.9));
  const auto cy = only<cl::Cycle>(rs);
  REQUIRE(cy.size() == 2);
  CHECK(cy[0].kind == cl::Cycle::Kind::deep);
  CHECK(cy[0].depth_mm == 3.5);
  CHECK(cy[0].peck_mm == 1.0);
  CHECK(cy[0].rapid_to_mm == 1.0);
  REQUIRE(cy[0].feed);
  CHECK(*cy[0].feed == 50.0);
  CHECK(cy[1].kind == cl::Cycle::Kind::off);
  CHECK(only<cl::Comment>(rs).size() == 1);
  REQUIRE(only<cl::End>(rs).size() == 1);
  CHECK(only<cl::End>(rs)[0].program);
}

TEST_CASE("unknown statements pass through with a notice and do not abort") {
  std::istringstream in("FOOBAR/1,2\nGOTO/1,2,3\n");
  cl::AptReader r(in, "t.cls", {.allow_unterminated = true});
  int n = 0;
  while (r.next()) ++n;
  CHECK(n == 2);
  const auto notices = r.take_notices();
  REQUIRE(notices.size() == 1);
  CHECK(notices[0].find("t.cls:1:1") != std::string::npos);
}

TEST_CASE("bad input: file:line:column and what was expected") {
  CHECK_THAT(error_of("GOTO/1,2,3\nGOTO/1,2.5.3,4\n"),
             Catch::Contains("t.cls:2:") && Catch::Contains("malformed number"));
  CHECK_THAT(error_of("GOTO/1,nan,3\n"), Catch::Contains("t.cls:1:8") && Catch::Contains("finite"));
  CHECK_THAT(error_of("GOTO/1,2,3,0,0,0\n"), Catch::Contains("t.cls:1:1") && Catch::Contains("zero"));
  CHECK_THAT(error_of("GOTO/1,2\n"), Catch::Contains("3 or 6 numbers"));
  CHECK_THAT(error_of("GOTO/1,,2\n"), Catch::Contains("empty argument"));
  CHECK_THAT(error_of(std::string("GOTO/1,2,3\n\x01\x02\x7f\n", 14)),
             Catch::Contains("t.cls:2") && Catch::Contains("binary"));
  CHECK_THAT(error_of("GOTO/1e999,2,3\n"), Catch::Contains("finite") || Catch::Contains("malformed"));
  CHECK_THAT(error_of("LOADTL/9E9\n"), Catch::Contains("t.cls:1:1") && Catch::Contains("out of range"));
}

TEST_CASE("every real CL file reads completely") {
  // NX's inch parts (nx_APT_*) have no UNITS record; read as inches, as their NX posts (G20) say.
  // nx_APT_Project2.txt has NX helices (CIRCLE/...,TIMES,7): see below.
  for (const char* f : {"nx_APT_Variable_Axis.txt", "nx_APT_SimpleMillPlane.txt", "nx_APT_Zig_Zag_Smoothed.txt",
                        "catia_peening.aptsource", "creo_bohren_1.ncl", "creo_schruppen_1.ncl"}) {
    INFO(f);
    std::ifstream in(test::data(std::string("real/") + f), std::ios::binary);
    REQUIRE(in);
    cl::ReaderOptions o;
    o.default_inch = std::string(f).rfind("nx_APT_", 0) == 0;
    cl::AptReader r(in, f, o);
    int motions = 0;
    while (auto x = r.next())
      if (std::holds_alternative<cl::Motion>(*x)) ++motions;
    CHECK(motions > 0);
  }
}

TEST_CASE("INSERT/STOP and INSERT/OPSTOP are program stops; other INSERT text is a comment (SOLIDWORKS CAM)") {
  // swcam basemach.apt: "INSERT/STOP  change fixture" between two setups; the CAM's own post
  // writes a program stop there. As a comment the machine would run on into the next setup.
  const auto rs = read_all(
      "INSERT/8MM CRB 4FL 20 LOC\nINSERT/STOP  change fixture\nINSERT/stop\nINSERT/OPSTOP,(check)\n"
      "INSERT/STOPWATCH\n");
  const auto stops = only<cl::Stop>(rs);
  REQUIRE(stops.size() == 3);
  CHECK_FALSE(stops[0].optional);
  CHECK(stops[0].text == "change fixture");
  CHECK(stops[0].where.line == 2);
  CHECK_FALSE(stops[1].optional);
  CHECK(stops[1].text.empty());
  CHECK(stops[2].optional);
  CHECK(stops[2].text == "check");
  const auto comments = only<cl::Comment>(rs);
  REQUIRE(comments.size() == 2);
  CHECK(comments[0].text == "8MM CRB 4FL 20 LOC");
  CHECK(comments[1].text == "STOPWATCH");
}

TEST_CASE("a tool change or a CIRCLE while a CYCLE is in force is refused (SOLIDWORKS CAM file without CYCLE/OFF)") {
  // swcam RotateThin.apt: CYCLE/DRILL for a drill, no CYCLE/OFF, LOAD/TOOL,2 (an end mill), RAPID,
  // FEDRAT, CIRCLE: its milling went out as G81 holes 7.65 mm deep.
  const std::string head =
      "UNIT/MM\nLOAD/TOOL,15\nRAPID/\nGOTO/10,20,100\nCYCLE/INIT\n"
      "CYCLE/DRILL,FEDTO,7.65,MMPM,125.,RAPTO,3.,RTRCTO,100.,DWELL,0\nGOTO/10,20,0\n";
  const std::string tool = error_of(head + "LOAD/TOOL,2\nRAPID/\nGOTO/10,20,2.5\n");
  CHECK(tool.find("t.cls:8:1: a tool change while the CYCLE of line 6 is in force (no CYCLE/OFF since)") !=
        std::string::npos);
  const std::string arc = error_of(head + "CIRCLE/10,20,0,0,0,1,5\nGOTO/15,20,0\n");
  CHECK(arc.find("t.cls:8:1: a CIRCLE (arc motion) while the CYCLE of line 6 is in force") != std::string::npos);
  // with CYCLE/OFF both read
  CHECK(error_of(head + "CYCLE/OFF\nLOAD/TOOL,2\nGOTO/5,20,0\nCIRCLE/10,20,0,0,0,1,5\nGOTO/15,20,0\n").empty());
}

TEST_CASE("GOHOME/x,y,z is a rapid move there; GOHOME alone returns to FROM (NX drilling, HumMan CLSF samples)") {
  // nx 9_SVERL_63_N2.cls ends "GOTO/297.5,-393,471 / GOHOME/297.5,-393,483 / END-OF-PATH": the last
  // retract was lost as a comment.
  const auto m =
      only<cl::Motion>(read_all("FROM/1,2,50,0,0,1\nFEDRAT/MMPM,120\nGOTO/1,2,3\nGOHOME/297.5,-393.0,483.0\n"
                                "GOTO/5,6,7\nGOHOME\n"));
  REQUIRE(m.size() == 5);
  CHECK(m[2].point.tip_mm == Vec3d(297.5, -393.0, 483.0));
  CHECK(m[2].rapid);
  CHECK_FALSE(m[2].from);
  CHECK(m[2].where.line == 4);
  CHECK_FALSE(m[3].rapid);  // the rapid was for the GOHOME only
  CHECK(m[4].point.tip_mm == Vec3d(1, 2, 50));
  CHECK(m[4].rapid);
  CHECK(error_of("GOTO/1,2,3\nGOHOME\n").find("t.cls:2:1: GOHOME without a point and no FROM before it") !=
        std::string::npos);
}

TEST_CASE("NX inch files without UNITS: FEDRAT/IPM is refused until --units says (they were read as mm)") {
  // nx_APT_Variable_Axis.txt: no UNITS record, FEDRAT/IPM,10 at line 15; NX's own post writes G20.
  // Read as mm (the default), every length was 25.4 times too small, with exit 0.
  std::ifstream in(test::data("real/nx_APT_Variable_Axis.txt"), std::ios::binary);
  REQUIRE(in);
  cl::AptReader r(in, "nx_APT_Variable_Axis.txt");
  try {
    while (r.next()) {
    }
    FAIL("read as mm");
  } catch (const InputError& e) {
    CHECK_THAT(e.what(), Catch::Contains("nx_APT_Variable_Axis.txt:15:1: FEDRAT/IPM,10.0000 gives the feed in inches, "
                                         "and the file has no UNITS statement") &&
                             Catch::Contains("--units inch"));
  }
  // UNITS/MM, --units (default_inch or units_given) or IPR likewise
  CHECK(error_of("UNITS/MM\nFEDRAT/IPM,10\nGOTO/1,2,3\n").empty());
  CHECK(error_of("UNITS/INCHES\nFEDRAT/IPM,10\nGOTO/1,2,3\n").empty());
  CHECK_THAT(error_of("GOTO/1,2,3\nFEDRAT/0.004,IPR\n"),
             Catch::Contains("t.cls:2:1: FEDRAT/0.004,IPR gives the feed in inches"));
  cl::ReaderOptions mm;
  mm.units_given = true;  // --units mm
  REQUIRE(only<cl::Feed>(read_all("FEDRAT/IPM,10\n", mm)).size() == 1);
}

TEST_CASE("NX CIRCLE/...,TIMES,n: n turns in all, the last one the arc to the next GOTO (nx_APT_Project2.txt)") {
  // TIMES,7 for 0.3845 in of depth along the axis, radius 0.1687 in, the arc to the GOTO 331.2 deg
  // clockwise about (i,j,k) (NX): 6 whole turns and the arc give a 3.0008 deg ramp in both records
  std::ifstream in(test::data("real/nx_APT_Project2.txt"), std::ios::binary);
  REQUIRE(in);
  cl::ReaderOptions o;
  o.default_inch = true;
  cl::AptReader r(in, "nx_APT_Project2.txt", o);
  int motions = 0;
  std::vector<cl::Circle> helices;
  while (auto x = r.next()) {
    if (std::holds_alternative<cl::Motion>(*x)) ++motions;
    if (const auto* c = std::get_if<cl::Circle>(&*x); c && c->extra_turns > 0) helices.push_back(*c);
  }
  CHECK(motions > 4000);  // read to the end
  REQUIRE(helices.size() == 2);
  for (const cl::Circle& c : helices) {
    CHECK(c.extra_turns == 6);
    CHECK(c.radius_mm == Approx(0.1687 * 25.4).margin(0.0002 * 25.4));  // 0.1687 and 0.1688 in
  }
  CHECK(helices[0].where.line == 4641);
  // outside an NX file the count's convention is not known: refused
  CHECK(error_of("UNITS/MM\nGOTO/0,5,1\nCIRCLE/0,0,0,0,0,1,5,0.006,0.5,10,0,TIMES,2\nGOTO/5,0,0\n")
            .find("t.cls:3:1: CIRCLE ...,TIMES,2: a helix of several turns outside an NX file") != std::string::npos);
  CHECK(
      error_of("TOOL PATH/A,TOOL,B\nUNITS/MM\nGOTO/0,5,1\nCIRCLE/0,0,0,0,0,1,5,0.006,0.5,10,0,TIMES,2.5\nGOTO/5,0,0\n")
          .find("a whole number from 1") != std::string::npos);
}
