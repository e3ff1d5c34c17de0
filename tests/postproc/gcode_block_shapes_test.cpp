// SPDX-License-Identifier: Apache-2.0
// Issue 24.6: blocks as shops write them — nested parentheses in a comment, ';' comments, block
// skip before the block number, blocks that start with a blank, words written without spaces.
#include <catch2/catch.hpp>

#include <deque>
#include <sstream>

#include "cl_records.hpp"
#include "shipped_machines.hpp"
#include "ncpost/postproc/read/gcode/gcode_block.hpp"
#include "ncpost/postproc/read/gcode/gcode_cl_reader.hpp"

using namespace ncpost;
using namespace ncpost::gcode;

namespace {

/// The block of `line`; its comments view the line, so the line is kept for the test's run.
Block parsed(const std::string& line) {
  static std::deque<std::string> lines;
  lines.push_back(line);
  Block b;
  parse_block(lines.back(), b, "t.ngc", 1);
  return b;
}

std::vector<cl::Record> read_all(const std::string& text) {
  std::istringstream in(text);
  GcodeReaderOptions o;
  o.check_limits = false;
  GcodeClReader r(in, "t.ngc", test::ac_trunnion(), Setup{}, o);
  return test::all_records(r);
}

}  // namespace

TEST_CASE("gcode block shapes: nested parentheses are one comment") {
  const Block b = parsed("O1000 (TEST (NESTED) COMMENT)");
  REQUIRE(b.words.size() == 1);
  CHECK(b.words[0].letter == 'O');
  CHECK(b.words[0].value == 1000.0);
  REQUIRE(b.comments.size() == 1);
  CHECK(b.comments[0].text == "TEST (NESTED) COMMENT");
  CHECK(b.comments[0].column == 7);
  // words after it are read
  const Block after = parsed("(A (B) C) G0 X1");
  REQUIRE(after.words.size() == 2);
  CHECK(after.words[1].letter == 'X');
  // an unclosed nesting is an error at the end of the line, saying what is missing
  try {
    parsed("(A (B) C");
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.where().column == 9);
    CHECK_THAT(e.detail(), Catch::Contains("')' closing the comment"));
  }
  // through the reader: the comment is a record with its text
  const auto comments = test::only<cl::Comment>(read_all("O1000 (TEST (NESTED) COMMENT)\nG0 X1 Y2 Z3\nM30\n"));
  REQUIRE(comments.size() == 1);
  CHECK(comments[0].text == "TEST (NESTED) COMMENT");
}

TEST_CASE("gcode block shapes: ';' comments, block skip before N, a leading blank, words without spaces") {
  const Block semi = parsed("G1 X5 ; feed to the wall (slowly)");
  REQUIRE(semi.words.size() == 2);
  REQUIRE(semi.comments.size() == 1);
  CHECK(semi.comments[0].text == " feed to the wall (slowly)");

  const Block skip = parsed("/N100 G0 X1");
  CHECK(skip.deleted);
  REQUIRE(skip.words.size() == 3);
  CHECK(skip.words[0].letter == 'N');
  CHECK(skip.words[0].value == 100.0);

  const Block blank = parsed("  G0 X1");
  CHECK(blank.column == 3);
  REQUIRE(blank.words.size() == 2);
  CHECK(blank.words[1].column == 6);

  const Block dense = parsed("N130G0G90G54X1.255Y-1.378S12000M3");
  const std::vector<std::pair<char, double>> expected = {{'N', 130},   {'G', 0},      {'G', 90},    {'G', 54},
                                                         {'X', 1.255}, {'Y', -1.378}, {'S', 12000}, {'M', 3}};
  REQUIRE(dense.words.size() == expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    CHECK(dense.words[i].letter == expected[i].first);
    CHECK(dense.words[i].value == expected[i].second);
  }
  // the reader reads the dense block as the spaced one: one motion to (1.255, -1.378) at Z from before
  const auto ms = test::only<cl::Motion>(read_all("G21\nG0 Z10\nN130G0G90G54X1.255Y-1.378S12000M3\nM30\n"));
  REQUIRE(ms.size() == 2);
  CHECK(ms[1].point.tip_mm.isApprox(Vec3d(1.255, -1.378, 10)));
}
