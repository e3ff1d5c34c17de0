// SPDX-License-Identifier: Apache-2.0
// Lexical quirks of RS274 blocks: case, spacing, numbers, comments, framing, N/O words, block
// delete, and errors with their exact columns.
#include <catch2/catch.hpp>

#include <cmath>
#include <list>
#include <string>

#include "ncpost/postproc/read/gcode/gcode_block.hpp"

using namespace ncpost;
using namespace ncpost::gcode;

namespace {

/// Parses a line kept alive for the whole test run (comments view the line).
Block parse(const std::string& line) {
  static std::list<std::string> lines;
  lines.push_back(line);
  Block b;
  parse_block(lines.back(), b, "t.ngc", 7);
  return b;
}

/// The error a line raises (fails the test if it raises none).
InputError error_of(const std::string& line) {
  try {
    parse(line);
  } catch (const InputError& e) {
    return e;
  }
  FAIL("no error for: " << line);
  throw;
}

}  // namespace

TEST_CASE("gcode block: words need no spaces and keep their columns") {
  const Block b = parse("G1X10Y-5");
  REQUIRE(b.words.size() == 3);
  CHECK(b.words[0].letter == 'G');
  CHECK(b.words[0].value == 1.0);
  CHECK(b.words[0].column == 1);
  CHECK(b.words[1].letter == 'X');
  CHECK(b.words[1].value == 10.0);
  CHECK(b.words[1].column == 3);
  CHECK(b.words[2].letter == 'Y');
  CHECK(b.words[2].value == -5.0);
  CHECK(b.words[2].column == 6);
  CHECK(b.column == 1);
}

TEST_CASE("gcode block: letters are case-insensitive and numbers take every RS274 form") {
  const Block b = parse("g1 x.5 y5. z+5 a-0.000 c-12.25");
  REQUIRE(b.words.size() == 6);
  CHECK(b.words[0].letter == 'G');
  CHECK(b.words[1].letter == 'X');
  CHECK(b.words[1].value == 0.5);
  CHECK(b.words[2].value == 5.0);
  CHECK(b.words[3].value == 5.0);
  CHECK(b.words[4].letter == 'A');
  CHECK(b.words[4].value == 0.0);
  CHECK(std::signbit(b.words[4].value));
  CHECK(b.words[5].value == -12.25);
}

TEST_CASE("gcode block: blanks between a letter and its number (LinuxCNC CAM output)") {
  const Block b = parse("G1  X  16.339  Y -25.409\tZ\t33.353  F 318");
  REQUIRE(b.words.size() == 5);
  CHECK(b.words[1].value == 16.339);
  CHECK(b.words[1].column == 5);
  CHECK(b.words[2].value == -25.409);
  CHECK(b.words[3].value == 33.353);
  CHECK(b.words[4].value == 318.0);
}

TEST_CASE("gcode block: parenthesis and semicolon comments") {
  const Block b = parse("G0 (rapid: move) X1 ; the rest (is) a comment");
  REQUIRE(b.words.size() == 2);
  CHECK(b.words[1].letter == 'X');
  REQUIRE(b.comments.size() == 2);
  CHECK(b.comments[0].text == "rapid: move");
  CHECK(b.comments[0].column == 4);
  CHECK(b.comments[1].text == " the rest (is) a comment");
  CHECK(b.comments[1].column == 21);
  const Block only = parse("(  Impeller 5-axis  12/24/2011)");
  CHECK(only.words.empty());
  REQUIRE(only.comments.size() == 1);
  CHECK(only.comments[0].text == "  Impeller 5-axis  12/24/2011");
  const Block semicolon = parse("M428 ;TCP:xyzac");
  REQUIRE(semicolon.comments.size() == 1);
  CHECK(semicolon.comments[0].text == "TCP:xyzac");
  CHECK(semicolon.words[0].value == 428.0);
}

TEST_CASE("gcode block: percent lines, N and O numbers, block delete, blank lines") {
  CHECK(parse("%").percent);
  CHECK(parse("  %  ").percent);
  CHECK(parse("").empty());
  CHECK(parse(" \t ").empty());
  const Block n = parse("N0010 G0 X1");
  REQUIRE(n.words.size() == 3);
  CHECK(n.words[0].letter == 'N');
  CHECK(n.words[0].value == 10.0);
  const Block o = parse("O1234 (PART)");
  REQUIRE(o.words.size() == 1);
  CHECK(o.words[0].letter == 'O');
  CHECK(o.words[0].value == 1234.0);
  CHECK(o.comments.size() == 1);
  const Block name = parse("Omnf01_vx_0 (NX program name)");
  CHECK(name.program_name == "mnf01_vx_0");
  CHECK(name.words.empty());
  CHECK(name.comments.size() == 1);
  CHECK(parse("O2021-11-28_test2setup_1").program_name == "2021-11-28_test2setup_1");
  const Block d = parse("  /G1 X5");
  CHECK(d.deleted);
  CHECK(d.column == 3);
  REQUIRE(d.words.size() == 2);
  CHECK(d.words[1].value == 5.0);
  CHECK_FALSE(parse("G1 X5").deleted);
}

TEST_CASE("gcode block: G and M codes with decimals, Sinumerik TRAORI keywords") {
  const Block b = parse("G43.4 H1 M3 S1200");
  REQUIRE(b.words.size() == 4);
  CHECK(b.words[0].value == Approx(43.4));
  const Block t = parse("TRAORI");
  REQUIRE(t.keywords.size() == 1);
  CHECK(t.keywords[0].keyword == Keyword::traori);
  CHECK(parse("traori(1) G1 X1").keywords.size() == 1);
  CHECK(parse("TRAFOOF").keywords[0].keyword == Keyword::trafoof);
  // a T word still parses where no keyword matches
  const Block tool = parse("T12 M6");
  CHECK(tool.keywords.empty());
  CHECK(tool.words[0].letter == 'T');
  CHECK(tool.words[0].value == 12.0);
}

TEST_CASE("gcode block: errors name the exact column and what was expected") {
  SECTION("missing number") {
    const InputError e = error_of("G1 X");
    CHECK(e.where().file == "t.ngc");
    CHECK(e.where().line == 7);
    CHECK(e.where().column == 5);
    CHECK_THAT(e.detail(), Catch::Contains("a number after 'X'"));
    CHECK(e.source_line() == "G1 X");
  }
  SECTION("malformed number") {
    const InputError e = error_of("G1 X1.2.3");
    CHECK(e.where().column == 8);
    CHECK_THAT(e.detail(), Catch::Contains("malformed number"));
  }
  SECTION("NaN and Inf are not numbers") {
    const InputError nan = error_of("G1 XNaN");
    CHECK(nan.where().column == 5);
    CHECK_THAT(nan.detail(), Catch::Contains("a number after 'X'"));
    const InputError inf = error_of("G1 Y-inf");
    CHECK(inf.where().column == 5);
  }
  SECTION("overflowing number") {
    const InputError e = error_of("G1 X1" + std::string(400, '0'));
    CHECK(e.where().column == 5);
    CHECK_THAT(e.detail(), Catch::Contains("out of range"));
  }
  SECTION("parameters") {
    const InputError e = error_of("G1 X#1");
    CHECK(e.where().column == 5);
    CHECK_THAT(e.detail(), Catch::Contains("parameters (#...) are not supported"));
    const InputError assign = error_of("#1 = 5");
    CHECK(assign.where().column == 1);
    CHECK_THAT(assign.detail(), Catch::Contains("not supported"));
  }
  SECTION("expressions") {
    const InputError e = error_of("G1 X[1+2] Y0");
    CHECK(e.where().column == 5);
    CHECK_THAT(e.detail(), Catch::Contains("expressions ([...]) are not supported"));
    CHECK(error_of("  [1]").where().column == 3);
  }
  SECTION("blanks inside a number") {
    const InputError e = error_of("G1 X1 0");
    CHECK(e.where().column == 7);
    CHECK_THAT(e.detail(), Catch::Contains("blanks inside a number"));
  }
  SECTION("unclosed comment") {
    const InputError e = error_of("G0 X1 (to the left");
    CHECK(e.where().column == 19);
    CHECK_THAT(e.detail(), Catch::Contains("')' closing the comment"));
  }
  SECTION("binary junk") {
    const InputError e = error_of(std::string("G1 X1 \x01\x7f\xfe", 9));
    CHECK(e.where().column == 7);
    CHECK_THAT(e.detail(), Catch::Contains("0x01"));
    const InputError nul = error_of(std::string("\0\0G1", 4));
    CHECK(nul.where().column == 1);
  }
  SECTION("O-word control flow") {
    const InputError e = error_of("o100 sub");
    CHECK(e.where().column == 6);
    CHECK_THAT(e.detail(), Catch::Contains("O-word"));
    CHECK(error_of("o<probe> call").where().column == 2);
  }
  SECTION("a stray character") {
    const InputError e = error_of("G1 X1 $");
    CHECK(e.where().column == 7);
    CHECK_THAT(e.detail(), Catch::Contains("found '$'"));
  }
}

TEST_CASE("gcode block: ':' is the ISO program number address O (NX's Fadal and Mori Seiki posts)") {
  const Block fadal = parse(":1234 (PROGRAM)");  // nxpost_Fadal_VMC_6030 line 2
  REQUIRE(fadal.words.size() == 1);
  CHECK(fadal.words[0].letter == 'O');
  CHECK(fadal.words[0].value == 1234.0);
  CHECK(fadal.words[0].column == 1);
  CHECK(fadal.comments.size() == 1);
  const Block sh8000 = parse(":0110 T01 M06");  // nxpost_MS_SH8000 line 12: a label before the tool change
  REQUIRE(sh8000.words.size() == 3);
  CHECK(sh8000.words[0].letter == 'O');
  CHECK(sh8000.words[0].value == 110.0);
  CHECK(sh8000.words[1].letter == 'T');
  CHECK(sh8000.words[1].column == 7);
  CHECK(parse("/:5 G0 X1").deleted);
  // only where a program number stands: first in the block
  const InputError inside = error_of("G0 :5 X1");
  CHECK(inside.where().column == 4);
  CHECK(inside.detail() == "expected a word (letter and number), a comment or the end of the line, found ':'");
  CHECK(error_of(":").detail() ==
        "O-word subroutines and control flow (sub, call, if, while, ...) are not supported; "
        "expected a program number");
}

TEST_CASE("gcode block: a line that starts with a number says what it is") {
  // Heidenhain conversational (nxpost_Bridgeport_412 line 1, nxpost_DMG_DMC_100_MILLPLUS line 1)
  const InputError pgm = error_of("0010 BEGIN PGM 100 IN");
  CHECK(pgm.where().column == 1);
  CHECK(pgm.detail() ==
        "'0010 BEGIN PGM...' is a Heidenhain conversational (plain-language) block, not G-code: "
        "ncpost reads ISO G-code (RS274, Fanuc, Haas, Sinumerik, LinuxCNC); post the CL data, or "
        "have the CAM post the part for an ISO control");
  CHECK_THAT(error_of("21 L X+.6079 Y+4.6458 Z+11.9106 FMAX M3").detail(),
             Catch::StartsWith("'21 L...' is a Heidenhain"));
  CHECK_THAT(error_of("  9 CYCL DEF 7.0 DATUM SHIFT").detail(), Catch::StartsWith("'9 CYCL DEF...' is a Heidenhain"));
  // a block number without its N
  CHECK(error_of("0010 G1 X5").detail() ==
        "a block that starts with the number '0010' (expected a word: a letter and "
        "its number, such as N0010 for a block number)");
  // binary data (a compressed file named .nc)
  const InputError bin = error_of(std::string("6=\xd0\x34") + "O_");
  CHECK(bin.where().column == 1);
  CHECK(bin.detail() == "unexpected byte 0xD0 at column 3 (binary data?); expected G-code text");
}

TEST_CASE("gcode block: a Heidenhain ISO program's '%' line is refused; other '%' lines delimit") {
  // nxpost_Micron_WF21D line 1
  const InputError e = error_of("% 123 G71");
  CHECK(e.where().column == 1);
  CHECK(e.detail() ==
        "a Heidenhain ISO program ('%' with its name and G70/G71): its T calls the tool without M6, I J "
        "K are absolute centres and M91/M92 move in machine coordinates, so ncpost does not read it as "
        "RS274 G-code; post the CL data");
  CHECK_THROWS_AS(parse("%PART1 G70 *"), InputError);
  CHECK(parse("%_N_PART1_MPF").percent);  // Sinumerik
  CHECK(parse("% 123").percent);
  CHECK(parse("%").percent);
  CHECK(parse("% part G71X").percent);  // not the units word alone
}
