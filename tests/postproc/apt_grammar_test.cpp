// SPDX-License-Identifier: Apache-2.0
// The APT reader on the grammar of issue 13/14: digit-first words, free text, 6-value CIRCLE,
// FINI at the end, empty files, CR-only line ends, a byte order mark, over-long lines, MSYS.
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

#include "cl_records.hpp"
#include "ncpost/postproc/read/apt/apt_reader.hpp"

using namespace ncpost;

namespace {

std::vector<cl::Record> read_all(const std::string& text, cl::ReaderOptions o = {}) {
  std::istringstream in(text);
  cl::AptReader r(in, "t.cls", o);
  std::vector<cl::Record> out = test::all_records(r);
  return out;
}

using test::only;

/// The InputError of reading `text` (its message and echoed source line), or empty strings.
std::pair<std::string, std::string> error_of(const std::string& text, cl::ReaderOptions o = {}) {
  try {
    read_all(text, o);
  } catch (const InputError& e) {
    return {e.what(), e.source_line()};
  }
  return {"", ""};
}

}  // namespace

TEST_CASE("words that start with a digit are names; free text is never read as numbers") {
  const auto rs = read_all(
      "TOOL PATH/10_SVERL_63_N2,TOOL,8MM_DRILL\nINSERT/14MM CRB 4FL 32 LOC\nPPRINT/1.5.3 , ,,\nTPRINT/2X,,3\n"
      "PARTNO 12-34 A/B\nOPERATION NAME/1ST OP\nGOTO/1,2,3\nFINI\n");
  const auto c = only<cl::Comment>(rs);
  REQUIRE(c.size() == 6);
  CHECK(c[0].text == "TOOL PATH: 10_SVERL_63_N2,TOOL,8MM_DRILL");
  CHECK(c[1].text == "14MM CRB 4FL 32 LOC");
  CHECK(c[2].text == "1.5.3 , ,,");
  CHECK(c[4].text == "PARTNO 12-34 A/B");
  CHECK(only<cl::Motion>(rs).size() == 1);
  const auto st = cl::parse_apt_statement("CYCLE/DEEP2,FEDTO,5.,1STPECK,5.,SUBPECK,2.", "t.cls", {1, 1});
  REQUIRE(st.arguments.size() == 7);
  CHECK_FALSE(st.arguments[3].is_number);
  CHECK(st.arguments[3].word == "1STPECK");
  CHECK(st.arguments[4].number == 5.0);
  // still malformed numbers: no character a name has
  CHECK_THROWS_WITH(cl::parse_apt_statement("GOTO/1,2.5.3,4", "t.cls", {1, 1}),
                    Catch::Contains("malformed number '2.5.3'"));
  CHECK_THROWS_WITH(cl::parse_apt_statement("GOTO/1,1.5E,4", "t.cls", {1, 1}), Catch::Contains("malformed number"));
}

TEST_CASE("CIRCLE with six values: the radius from the start point, the end checked") {
  // a quarter arc of radius 5 about (10,0,0), then a full circle (start = end)
  const auto rs =
      read_all("GOTO/15,0,0\nCIRCLE/10,0,0,0,0,1\nGOTO/10,5,0\nCIRCLE/10.,0.,0.,0.,0.,1.\nGOTO/10,5,0\nFINI\n");
  const auto c = only<cl::Circle>(rs);
  REQUIRE(c.size() == 2);
  CHECK(c[0].radius_mm == Approx(5.0).epsilon(1e-12));
  CHECK(c[0].center_mm == Vec3d(10, 0, 0));
  CHECK(c[0].axis == Vec3d(0, 0, 1));
  CHECK(c[1].radius_mm == Approx(5.0).epsilon(1e-12));
  // the start 0.5 mm higher along the axis does not change the radius
  const auto h = only<cl::Circle>(read_all("GOTO/13,4,0.5\nCIRCLE/10,0,0,0,0,1\nGOTO/15,0,0.5\nFINI\n"));
  CHECK(h.at(0).radius_mm == Approx(5.0).epsilon(1e-12));
  // an end 0.02 mm off the circle (tolerance 0.01 mm): refused, naming the CIRCLE's line
  const auto e = error_of("GOTO/15,0,0\nCIRCLE/10,0,0,0,0,1\nGOTO/10,5.02,0\nFINI\n");
  CHECK_THAT(e.first, Catch::Contains("t.cls:2:1") && Catch::Contains("5.0000") && Catch::Contains("5.0200") &&
                          Catch::Contains("line 3"));
  // within the tolerance: read
  CHECK(only<cl::Circle>(read_all("GOTO/15,0,0\nCIRCLE/10,0,0,0,0,1\nGOTO/10,5.005,0\nFINI\n")).size() == 1);
  CHECK_THAT(error_of("CIRCLE/10,0,0,0,0,1\nGOTO/1,2,3\nFINI\n").first, Catch::Contains("before any motion"));
  CHECK_THAT(error_of("GOTO/10,0,5\nCIRCLE/10,0,0,0,0,1\nGOTO/1,2,3\nFINI\n").first, Catch::Contains("radius 0"));
  CHECK_THAT(error_of("GOTO/1,2,3\nCIRCLE/10,0,0,0,1\nFINI\n").first, Catch::Contains("got 5"));
}

TEST_CASE("a file must end with FINI, END or END-OF-PATH unless told otherwise") {
  const auto e = error_of("GOTO/1,2,3\nGOTO/4,5,6\n");
  CHECK_THAT(e.first, Catch::Contains("t.cls:2") && Catch::Contains("file ends without FINI: truncated?") &&
                          Catch::Contains("--allow-unterminated"));
  cl::ReaderOptions allow;
  allow.allow_unterminated = true;
  CHECK(only<cl::Motion>(read_all("GOTO/1,2,3\nGOTO/4,5,6\n", allow)).size() == 2);
  CHECK(error_of("GOTO/1,2,3\nFINI\n").first.empty());
  CHECK(error_of("GOTO/1,2,3\nEND\n$$ a closing comment\n\n").first.empty());
  // NX listings end with a line that is no statement
  CHECK(error_of("TOOL PATH/A,TOOL,B\nGOTO/1,2,3\nEND-OF-PATH\nTool Path Listing has 3 lines.\n").first.empty());
  // a cut NX file: the last operation has no END-OF-PATH
  CHECK_THAT(error_of("GOTO/1,2,3\nEND-OF-PATH\nTOOL PATH/A,TOOL,B\nGOTO/1,2,3\n").first, Catch::Contains("truncated"));
}

TEST_CASE("empty files, CR-only line ends and a byte order mark") {
  for (const char* empty : {"", "\n\n  \r\n", "\xEF\xBB\xBF"}) {
    cl::ReaderOptions allow;
    allow.allow_unterminated = true;
    CHECK_THAT(error_of(empty, allow).first, Catch::Contains("t.cls: the CL file is empty"));
  }
  const auto cr = read_all("\xEF\xBB\xBFPARTNO/BOM\rGOTO/1,2,3\rGOTO/4,5,6\r\rFINI\r");
  const auto m = only<cl::Motion>(cr);
  REQUIRE(m.size() == 2);
  CHECK(m[1].point.tip_mm == Vec3d(4, 5, 6));
  CHECK(m[1].where.line == 3);
  CHECK(only<cl::Comment>(cr).at(0).text == "PARTNO BOM");  // no BOM bytes in the text
  // CRLF split across the reader's chunks reads as one line end
  std::string big = "PPRINT/" + std::string((1 << 16) - 8, 'A') + "\r\nGOTO/1,2,3\r\nFINI\r\n";
  const auto b = read_all(big);
  REQUIRE(only<cl::Motion>(b).size() == 1);
  CHECK(only<cl::Motion>(b)[0].where.line == 2);
  CHECK(cl::looks_like_apt("\xEF\xBB\xBFGOTO/1,2,3\rFINI\r"));
  CHECK(cl::looks_like_apt("REM\rGOTO/1,2,3\r"));
}

TEST_CASE("a line longer than 1 MiB: 'line too long', a short echo, bounded memory") {
  const std::string line(3u << 20, '7');
  const auto e = error_of("GOTO/1,2,3\nGOTO/" + line + "\nFINI\n");
  CHECK_THAT(e.first, Catch::Contains("t.cls:2:1") && Catch::Contains("line too long"));
  CHECK(e.first.size() < 300);
  CHECK(e.second.size() <= 203);
  CHECK(e.second.rfind("GOTO/777", 0) == 0);
  // a long line under the limit with an error far along it: no echo (the caret could not show it)
  const auto far = error_of("GOTO/1,2," + std::string(5000, ' ') + "3x\nFINI\n");
  CHECK_THAT(far.first, Catch::Contains("malformed number '3x'") || Catch::Contains("expects numbers only"));
  CHECK(far.second.size() <= 203);
}

TEST_CASE("huge numbers are refused with a short message") {
  const auto e = error_of("GOTO/1e308,0,0\nFINI\n");
  CHECK_THAT(e.first, Catch::Contains("t.cls:1:1") && Catch::Contains("1e+308") && Catch::Contains("out of range"));
  CHECK(e.first.size() < 200);
  CHECK_THAT(error_of("FEDRAT/1e300,MMPM\nFINI\n").first, Catch::Contains("1e+300") && Catch::Contains("out of range"));
  CHECK_THAT(error_of("GOTO/1,0,0\nCIRCLE/0,0,0,0,0,1,1e300\nFINI\n").first, Catch::Contains("1e+300"));
}

TEST_CASE("MSYS: ignore posts GOTOs as written; apply maps them into the absolute frame") {
  // MCS at (100, 0, 50), turned upside down (X stays, Y and Z flip)
  const std::string file =
      "MSYS/100,0,50,1,0,0,0,-1,0\nGOTO/1,2,3,0,0,-1\nGODLTA/0,0,1\nCIRCLE/0,0,0,0,0,1,5\nGOTO/1,2,3\nFINI\n";
  const auto as_written = only<cl::Motion>(read_all(file));
  REQUIRE(as_written.size() == 3);
  CHECK(as_written[0].point.tip_mm == Vec3d(1, 2, 3));
  CHECK(as_written[0].point.axis == Vec3d(0, 0, -1));
  cl::ReaderOptions apply;
  apply.msys = cl::ReaderOptions::Msys::apply;
  const auto rs = read_all(file, apply);
  const auto m = only<cl::Motion>(rs);
  REQUIRE(m.size() == 3);
  CHECK((m[0].point.tip_mm - Vec3d(101, -2, 47)).norm() < 1e-12);
  CHECK((m[0].point.axis - Vec3d(0, 0, 1)).norm() < 1e-12);
  CHECK((m[1].point.tip_mm - Vec3d(101, -2, 46)).norm() < 1e-12);  // GODLTA +Z of the MCS = -Z absolute
  const auto c = only<cl::Circle>(rs);
  CHECK((c.at(0).center_mm - Vec3d(100, 0, 50)).norm() < 1e-12);
  CHECK((c.at(0).axis - Vec3d(0, 0, -1)).norm() < 1e-12);
  // the notice and the hint for a failure, under ignore
  std::istringstream in(file);
  cl::AptReader r(in, "t.cls");
  while (r.next()) {
  }
  const auto notices = r.take_notices();
  REQUIRE(notices.size() == 1);
  CHECK_THAT(notices[0], Catch::Contains("t.cls:1: MSYS rotates the MCS"));
  CHECK_THAT(r.failure_hint(), Catch::Contains("t.cls:1") && Catch::Contains("MSYS is the likely cause") &&
                                   Catch::Contains("--msys apply"));
  // a translation only needs no hint
  std::istringstream in2("MSYS/3,3,0,1,0,0,0,1,0\nGOTO/1,2,3\nFINI\n");
  cl::AptReader r2(in2, "t.cls");
  while (r2.next()) {
  }
  CHECK(r2.failure_hint().empty());
  // operations in different MCSs: refused under ignore, posted under apply
  const std::string two =
      "MSYS/0,0,0,1,0,0,0,1,0\nGOTO/1,2,3\nMSYS/0,0,0,1,0,0,0,1,0\nGOTO/1,2,3\nMSYS/0,0,0,0,1,0,-1,0,0\n"
      "GOTO/1,2,3\nFINI\n";
  CHECK_THAT(error_of(two).first,
             Catch::Contains("t.cls:5:1") && Catch::Contains("line 1") && Catch::Contains("--msys apply"));
  const auto m2 = only<cl::Motion>(read_all(two, apply));
  REQUIRE(m2.size() == 3);
  CHECK((m2[2].point.tip_mm - Vec3d(-2, 1, 3)).norm() < 1e-12);
  CHECK_THAT(error_of("MSYS/0,0,0,1,0,0,1,0,0\nFINI\n").first, Catch::Contains("orthogonal"));
}
