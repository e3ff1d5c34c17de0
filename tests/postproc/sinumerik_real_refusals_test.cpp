// SPDX-License-Identifier: Apache-2.0
// Sinumerik constructs met in real programs (issue 28). G53: frames suppressed for the block, read as
// SUPA, in machine coordinates counted from the machine file's reference point
// (tests/data/machines/ac-trunnion-references.toml: X -400, Y 450, Z 550, A 0, C 0). G53 and SUPA
// both suppress the settable and the programmable frame (SINUMERIK 840D sl Programming Manual
// Fundamentals, "Zero offset frame"), so a TRANS in force does not shift a G53 block. Setup{}: W at
// M's origin, tool length 0, so that at A0 C0 a machine position is the tool tip in W. Expected
// positions are computed here from those rules, never taken from the reader. Also the feed-only
// G62 (noted), the messages for what stays refused (M202(…), an ISO G43 … H) and which line a
// refusal names.
#include <catch2/catch.hpp>

#include <sstream>

#include "cl_records.hpp"
#include "nc_executor.hpp"
#include "shipped_machines.hpp"
#include "test_paths.hpp"
#include "ncpost/postproc/machine/serial_post_machine.hpp"
#include "ncpost/postproc/post_request.hpp"
#include "ncpost/postproc/read/sinumerik/sinumerik_reader.hpp"
#include "ncpost/postproc/write/dialect.hpp"

using namespace ncpost;

namespace {

using Read = test::MotionsAndNotices;

Read read(const std::string& text) {
  std::istringstream in(text);
  sinumerik::SinumerikReader r(in, "t.mpf", test::ac_trunnion_references(), Setup{});
  return test::motions_and_notices(r);
}

std::string error_of(const std::string& text) {
  const std::string e = test::input_error_of([&] { read(text); });
  if (e.empty()) FAIL("no input error for: " << text);
  return e;
}

void check_tip(const cl::Motion& m, const Vec3d& expected) {
  INFO("line " << m.where.line << ": tip " << m.point.tip_mm.transpose() << ", expected " << expected.transpose());
  CHECK((m.point.tip_mm - expected).norm() < 1e-9);
}

/// A TRANS in force, a retract in machine coordinates by `suppress` (G53 or SUPA) with D0, the
/// tool's edge again, then back into the shifted frame.
std::string retract_program(const std::string& suppress) {
  return "G17 G90 G71 G54 G40\n"
         "G0 X10 Y20 Z30 A0 C0\n"
         "TRANS X5 Y-5\n"
         "G0 X10 Y20 Z30\n"
         "G0 " +
         suppress +
         " Z-10 D0\n"
         "T1 D1\n"
         "G0 X0 Y0\n"
         "G1 Z30 F500\n"
         "M30\n";
}

}  // namespace

TEST_CASE("sinumerik G53: machine coordinates from the reference point, the TRANS suppressed, as SUPA") {
  const Read r = read(retract_program("G53"));
  REQUIRE(r.motions.size() == 5);
  check_tip(r.motions[0], Vec3d(10, 20, 30));
  check_tip(r.motions[1], Vec3d(15, 15, 30));   // TRANS X5 Y-5
  check_tip(r.motions[2], Vec3d(15, 15, 540));  // machine Z = reference 550 - 10; X Y stay
  check_tip(r.motions[3], Vec3d(5, -5, 540));   // X0 Y0 in the shifted frame, Z where G53 left it
  check_tip(r.motions[4], Vec3d(5, -5, 30));
  CHECK(r.motions[2].rapid);
  CHECK(r.motions[2].where.line == 5);
  CHECK_THAT(r.notices, Catch::Contains("t.mpf:5: G53") && Catch::Contains("basic frame"));
  // SUPA suppresses the same frames and more (the basic frame, DRF, external offsets): the same path
  const Read supa = read(retract_program("SUPA"));
  REQUIRE(supa.motions.size() == r.motions.size());
  for (std::size_t i = 0; i < r.motions.size(); ++i) check_tip(supa.motions[i], r.motions[i].point.tip_mm);
}

TEST_CASE("sinumerik G53: re-posted, the written program stands where the input's machine positions are") {
  // a job with the work offset and a tool: the input's X Y Z (no TRAORI) are machine positions, so
  // the expected block ends are the tests' own forward kinematics of the positions worked out by hand
  Setup setup;
  setup.workpiece_origin_mm = Vec3d(10, -20, 50);
  setup.tool_length_mm = 100;
  PostRequest request;
  request.machine = serial_post_machine(test::ac_trunnion_references());
  request.setup = setup;
  request.dialect = dialect_named("fanuc");
  request.threads = 1;
  request.input_name = "g53.mpf";
  std::istringstream in(retract_program("G53"));
  std::ostringstream out;
  post(in, out, request);
  INFO(out.str());
  test::ExecJob job;
  job.workpiece_origin_mm = test::V3(10, -20, 50);
  job.tool_length_mm = 100;
  const test::Executor ex(test::data("machines/ac-trunnion-references.toml"), job, out.str());
  const std::vector<test::V3> machine_positions = {
      {10, 20, 30}, {15, 15, 30}, {15, 15, 550 - 10}, {5, -5, 540}, {5, -5, 30}};
  std::size_t at = 0;
  for (const test::V3& q : machine_positions) {
    const test::V3 tip = test::forward(ex.machine, job, q, {{'A', 0.0}, {'C', 0.0}}).tip_W;
    INFO("machine position " << q.transpose() << ", tip " << tip.transpose());
    bool found = false;
    for (; at < ex.blocks.size() && !found; ++at) found = (ex.at(ex.blocks[at], 1.0).tip_W - tip).norm() < 1e-3;
    CHECK(found);
  }
}

TEST_CASE("sinumerik G53: alone in its block it moves nothing; in a CYCLE800 plane it is refused") {
  const Read alone = read("G17 G90 G71\nG0 X10 Y20 Z30 A0 C0\nG53\nG1 X12 F100\nM30\n");
  REQUIRE(alone.motions.size() == 2);
  check_tip(alone.motions[1], Vec3d(12, 20, 30));  // not a machine coordinate: G53 held for its own block
  CHECK_THAT(alone.notices, Catch::Contains("t.mpf:3: G53 without axis words moves nothing"));
  const std::string swivelled =
      error_of("G17 G90 G71\nG0 X0 Y0 Z100 A0 C0\nCYCLE800(0,\"TC\",0,57,0,0,0,30,0,0,0,0,0,1)\nG0 G53 Z-10\nM30\n");
  CHECK_THAT(swivelled, Catch::StartsWith("t.mpf:4:") && Catch::Contains("G53 in a plane swivelled by CYCLE800"));
  CHECK_THAT(error_of("G17 G90 G71\nG0 X0 Y0 Z30 A0 C0\nG91 G53 Z-10\nM30\n"),
             Catch::Contains("G53 with incremental words is not read"));
}

TEST_CASE("sinumerik G62: corner deceleration changes the feed only; the path is the one without it") {
  const std::string body = "G0 X0 Y0 Z5 A0 C0\nG42 G1 X20 Y0 F300\nY20\nX0\nG40 X-5\nM30\n";
  const Read with = read("G17 G90 G71\nG62\n" + body);
  const Read without = read("G17 G90 G71\n\n" + body);
  REQUIRE(with.motions.size() == without.motions.size());
  REQUIRE(with.motions.size() == 5);
  for (std::size_t i = 0; i < with.motions.size(); ++i) {
    check_tip(with.motions[i], without.motions[i].point.tip_mm);
    CHECK(with.motions[i].feed == without.motions[i].feed);
  }
  check_tip(with.motions[2], Vec3d(20, 20, 5));
  CHECK_THAT(with.notices, Catch::Contains("t.mpf:2: G62 (corner deceleration"));
}

TEST_CASE("sinumerik: M202(value) and an ISO G43 ... H stay refused, saying what they are and what to do") {
  const std::string m202 = error_of("G17 G90 G70\nM200\nM202(0.0024)\nG0 X0 Y0 Z1 A0 C0\nM30\n");
  CHECK_THAT(m202, Catch::StartsWith("t.mpf:3:") && Catch::Contains("M202(...)") &&
                       Catch::Contains("the machine builder's own") && Catch::Contains("delete the block"));
  const std::string iso =
      error_of("G17 G90 G71\nT1 M6\nG0 X0 Y0 A0 C0\nG43 Z110. H01\nMCALL CYCLE81(10,0,2,-5)\nM30\n");
  CHECK_THAT(iso, Catch::StartsWith("t.mpf:4:") && Catch::Contains("an ISO tool length offset") &&
                      Catch::Contains("D number"));
}

TEST_CASE("sinumerik: the first line that cannot be read is the one named, though the translator reads ahead") {
  // line 3 (an axis the AC trunnion lacks) is the G-code reader's refusal, line 5 (MIRROR) the
  // translator's: the translator runs up to 64 blocks ahead of the G-code reader, yet line 3 is named
  const std::string text = "G17 G90 G71\nG0 X0 Y0 Z50 A0 C0\nG0 B30\nG1 X10 F100\nMIRROR X0\nM30\n";
  CHECK_THAT(error_of(text), Catch::StartsWith("t.mpf:3:") && Catch::Contains("no B axis"));
  // with line 3 gone, line 5 is named, after the motions before it were read
  CHECK_THAT(error_of("G17 G90 G71\nG0 X0 Y0 Z50 A0 C0\n\nG1 X10 F100\nMIRROR X0\nM30\n"),
             Catch::StartsWith("t.mpf:5:") && Catch::Contains("MIRROR"));
}
