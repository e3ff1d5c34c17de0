// SPDX-License-Identifier: Apache-2.0
// Sinumerik programs re-posted (post_request.hpp, the input detected by its DEF / TRAORI /
// CYCLE800): the INPUT is run by the tests' own small Sinumerik interpreter
// (tests/support/sinumerik_mini.hpp), the written OUTPUT by the tests' executor
// (tests/support/nc_executor.hpp); both with the tests' own forward kinematics of the machine
// file. At every input block end the tool tip agrees within 1 µm and the tool axis within the
// resolution of the written angles (1e-4 deg),
// the output's blocks passing through the input's ends in order. The rotary angles of TRAORI
// vectors and of CYCLE800 are checked against the angles the tests compute themselves.
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

#include "nc_executor.hpp"
#include "shipped_machines.hpp"
#include "sinumerik_mini.hpp"
#include "ncpost/postproc/machine/serial_post_machine.hpp"
#include "ncpost/postproc/post_request.hpp"
#include "ncpost/postproc/write/dialect.hpp"
#include "test_paths.hpp"

using namespace ncpost;

namespace {

Setup job_setup() {
  Setup s;
  s.workpiece_origin_mm = Vec3d(10, -20, 50);
  s.tool_length_mm = 120;
  return s;
}

test::ExecJob exec_job() {
  test::ExecJob j;
  j.workpiece_origin_mm = test::V3(10, -20, 50);
  j.tool_length_mm = 120;
  return j;
}

std::string repost(const std::string& text, bool rtcp) {
  PostRequest r;
  r.machine = serial_post_machine(test::ac_trunnion());
  r.setup = job_setup();
  r.dialect = dialect_named("fanuc");
  r.rtcp = rtcp;
  r.threads = 1;
  r.input_name = "repost.mpf";
  std::istringstream in(text);
  std::ostringstream out;
  post(in, out, r);
  return out.str();
}

/// The written angles have 4 decimals of a degree: the axis they give is within 1e-4 deg (1.7e-6).
constexpr double kAxisTolerance = 5e-6;

/// Every input block end must be reached by an output block end, in order.
void check_ends(const std::string& input, const std::string& output) {
  const std::string machine_file = test::source("machines/ac-trunnion.toml");
  const test::ExecMachine m = test::ExecMachine::load(machine_file);
  const auto expected = test::sinumerik_block_ends(input, m, exec_job());
  const test::Executor ex(machine_file, exec_job(), output);
  REQUIRE(!expected.empty());
  std::size_t at = 0;
  for (const auto& e : expected) {
    INFO("input line " << e.line << ": expected tip " << e.tip_W.transpose() << " axis " << e.axis_W.transpose());
    bool found = false;
    for (; at < ex.blocks.size() && !found; ++at) {
      const test::ExecPose p = ex.at(ex.blocks[at], 1.0);
      found = (p.tip_W - e.tip_W).norm() < 1e-3 && (p.axis_W - e.axis_W).norm() < kAxisTolerance;
    }
    CHECK(found);
  }
}

/// The program re-posted, every input block end checked against it (check_ends).
std::string reposted_and_checked(const std::string& text, bool rtcp) {
  const std::string out = repost(text, rtcp);
  INFO(out);
  check_ends(text, out);
  return out;
}

/// The words in force after the first output block that turns A away from 0.
std::map<char, double> first_tilt(const std::string& output) {
  const test::Executor ex(test::source("machines/ac-trunnion.toml"), exec_job(), output);
  for (const auto& b : ex.blocks)
    if (b.to.count('A') && std::abs(b.to.at('A')) > 1e-6) return b.to;
  return {};
}

}  // namespace

TEST_CASE("sinumerik re-post: a machine-axis program with variables ends every block where it did") {
  const std::string text =
      "%_N_PLAIN_MPF\n"
      "N10 DEF REAL _Z=-3\n"
      "N20 G17 G90 G71 G94\n"
      "N30 T1 M6\n"
      "N40 G0 X0 Y0 Z30 A0 C0 S3000 M3\n"
      "N50 G1 Z-3 F300\n"
      "N60 X40 Y10\n"
      "N70 G3 X30 Y20 I-10 J0\n"
      "N80 G1 A10 C20 F500\n"
      "N90 G0 Z30\n"
      "N100 M30\n";
  const std::string out = repost(text, false);
  INFO(out);
  check_ends(text, out);
}

TEST_CASE("sinumerik re-post: TRAORI with A3= B3= C3= vectors; the rotary angles are the tests' own solution") {
  const std::string text =
      "N10 G17 G90 G71 G94 T1 M6\n"
      "N20 G0 X0 Y0 Z80 A0 C0 S3000 M3\n"
      "N30 TRAORI\n"
      "N40 G1 X10 Y0 Z20 A3=0 B3=-0.5 C3=0.5 F500\n"
      "N50 X20 Y5 A3=0.3 B3=-0.4 C3=0.866\n"
      "N60 X25 Y-5 Z15 A3=0.5 B3=0 C3=0.866\n"
      "N70 TRAFOOF\n"
      "N80 M30\n";
  const std::string out = repost(text, true);
  INFO(out);
  check_ends(text, out);
  // (0, -s, s) in W on the AC trunnion: the tests' own forward kinematics over the candidates
  const test::ExecMachine m = test::ExecMachine::load(test::source("machines/ac-trunnion.toml"));
  const test::V3 want = test::V3(0, -1, 1).normalized();
  const std::map<char, double> got = first_tilt(out);
  REQUIRE(got.count('A'));
  const test::ExecPose pose = test::forward(m, exec_job(), test::V3::Zero(), {{'A', got.at('A')}, {'C', got.at('C')}});
  CHECK((pose.axis_W - want).norm() < kAxisTolerance);
  CHECK(std::abs(got.at('A')) == Approx(45.0).margin(1e-6));
}

TEST_CASE("sinumerik re-post: CYCLE800 tilts the plane 30 deg about X; the output's angles are the control's (_DIR)") {
  const std::string text =
      "N10 G17 G90 G71 G94 T1 M6\n"
      "N20 G0 X0 Y0 Z100 A0 C0 S3000 M3\n"
      "N30 CYCLE800(0,\"TC1\",200000,57,10,0,0,30,0,0,0,0,0,1,100,1)\n"
      "N40 G0 X0 Y0 Z20\n"
      "N50 G1 Z-2 F300\n"
      "N60 X20\n"
      "N70 Y15\n"
      "N80 G0 Z20\n"
      "N90 CYCLE800()\n"
      "N100 M30\n";
  const std::string out = repost(text, true);
  INFO(out);
  check_ends(text, out);
  // the plane's normal Rx(30) e_z; the candidates A = +-30, C = 0 / 180 through the tests' FK
  const test::ExecMachine m = test::ExecMachine::load(test::source("machines/ac-trunnion.toml"));
  const test::V3 normal = test::sin_rot(0, 30) * test::V3::UnitZ();
  std::vector<std::pair<double, double>> reaching;
  for (double a : {30.0, -30.0})
    for (double c : {0.0, 180.0, -180.0})
      if ((test::forward(m, exec_job(), test::V3::Zero(), {{'A', a}, {'C', c}}).axis_W - normal).norm() < 1e-9)
        reaching.emplace_back(a, c);
  REQUIRE(!reaching.empty());
  const std::map<char, double> got = first_tilt(out);
  REQUIRE(got.count('A'));
  bool among = false, positive_exists = false;
  for (const auto& [a, c] : reaching) {
    among = among || (std::abs(got.at('A') - a) < 1e-6 && std::abs(std::remainder(got.at('C') - c, 360.0)) < 1e-6);
    positive_exists = positive_exists || a > 0;
  }
  CHECK(among);
  if (positive_exists) CHECK(got.at('A') > 0);  // _DIR = +1: the reference axis A on its plus side
  // a bare CYCLE800 (no parameter list: every parameter left out) is CYCLE800(), the reset
  std::string bare = text;
  bare.replace(bare.find("N90 CYCLE800()"), 14, "N90 CYCLE800");
  CHECK(repost(bare, true) == out);
}

TEST_CASE(
    "sinumerik re-post: CYCLE800 about Y with a retract and _DIR=-1, then TRAORI with rotary words, on a machine-axis "
    "output") {
  const std::string text =
      "G17 G90 G94 G54\n"
      "T1 D1 M6\n"
      "S2500 M3\n"
      "CYCLE800(1,\"TABLE\",100000,57,15,0,0,0,30,0,0,0,0,-1,100,1)\n"
      "G0 X4 Y-40 Z60\n"
      "G1 Z5 F300\n"
      "G1 Y40 F700\n"
      "G0 Z60\n"
      "CYCLE800()\n"
      "G0 X0 Y0 Z100 A45 C180\n"  // machine axes again: every word given (the linear axes stood still)
      "TRAORI\n"
      "G0 X40 Y-28 Z50\n"
      "G1 Z-2 F600\n"
      "G1 X-28\n"
      "G1 C270\n"
      "G1 Y28\n"
      "G0 Z50\n"
      "TRAFOOF\n"
      "M30\n";
  const std::string out = repost(text, false);
  INFO(out);
  check_ends(text, out);
  // the plane Ry(30): A on its minus side (_DIR = -1) where the tests' FK has such a solution
  const test::ExecMachine m = test::ExecMachine::load(test::source("machines/ac-trunnion.toml"));
  const test::V3 normal = test::sin_rot(1, 30) * test::V3::UnitZ();
  const std::map<char, double> got = first_tilt(out);
  REQUIRE(got.count('A'));
  const test::ExecPose pose = test::forward(m, exec_job(), test::V3::Zero(), {{'A', got.at('A')}, {'C', got.at('C')}});
  CHECK((pose.axis_W - normal).norm() < kAxisTolerance);
  CHECK(got.at('A') < 0);
}

TEST_CASE("sinumerik re-post: the tests' CYCLE83 infeeds follow the manual's degression rule (hand-computed)") {
  // first 10 from RFP, DAM 3, 32 deep: 10, 7, 4, then 3 while more than 6 is left (3, 3), the last 5 split 2.5 + 2.5
  const std::vector<double> want = {10, 7, 4, 3, 3, 2.5, 2.5};
  const std::vector<double> got = test::cycle83_infeeds(10, 32, 3);
  REQUIRE(got.size() == want.size());
  for (std::size_t i = 0; i < want.size(); ++i) CHECK(got[i] == Approx(want[i]).margin(1e-12));
  // no degression: every infeed as long as the first, the last what is left
  CHECK(test::cycle83_infeeds(5, 12, 0) == std::vector<double>{5, 5, 2});
}

TEST_CASE(
    "sinumerik re-post: MCALL CYCLE83 (chip removal, degression), CYCLE83 (chip breaking), CYCLE85, CYCLE86 as "
    "motions") {
  const std::string text =
      "N10 G17 G90 G71 G94 T1 M6\n"
      "N20 G0 X0 Y0 Z50 A0 C0 S2000 M3\n"
      "N30 G1 Z40 F200\n"
      "N40 MCALL CYCLE83(20, 0, 2, -32, , -10, , 3, 0.2, 0.1, 0.5, 1)\n"
      "N50 G0 X10 Y5\n"
      "N60 X30 Y5\n"
      "N70 MCALL\n"
      "N80 G0 X30 Y-20 Z20\n"
      "N90 CYCLE83(20, 0, 2, -12, , -5, , 0, 0, 0, 1, 0, 0, 0, 0.5)\n"
      "N100 G0 X0 Y-20\n"
      "N110 CYCLE85(20, 0, 2, -8, , 0.3, 150, 400)\n"
      "N120 G1 X-10 Y-20\n"
      "N130 G0 X-20 Y-20\n"
      "N140 CYCLE86(20, 0, 2, , 6, 0.5, 3, 0, 0, 0, 0)\n"
      "N150 G0 Z50\n"
      "N160 M30\n";
  const std::string out = reposted_and_checked(text, false);
  // the feeds: the first infeed at F * FRF (100), the later ones at F (200); CYCLE85 in at FFR, out at
  // RFF; after the cycle the programmed F (200) again
  const test::ExecMachine m = test::ExecMachine::load(test::source("machines/ac-trunnion.toml"));
  const test::Executor ex(test::source("machines/ac-trunnion.toml"), exec_job(), out);
  const auto feed_ending_at = [&](double x, double y, double z) {
    const test::V3 tip = test::forward(m, exec_job(), test::V3(x, y, z), {{'A', 0.0}, {'C', 0.0}}).tip_W;
    for (const auto& b : ex.blocks) {
      if (b.kind == test::ExecBlock::Kind::linear && (ex.at(b, 1.0).tip_W - tip).norm() < 1e-6) return b.feed;
    }
    return -1.0;
  };
  CHECK(feed_ending_at(10, 5, -10) == Approx(100));
  CHECK(feed_ending_at(10, 5, -17) == Approx(200));
  CHECK(feed_ending_at(30, 5, -32) == Approx(200));
  CHECK(feed_ending_at(0, -20, -8) == Approx(150));
  CHECK(feed_ending_at(0, -20, 2) == Approx(400));
  CHECK(feed_ending_at(-10, -20, 20) == Approx(200));
}

TEST_CASE("sinumerik re-post: MCALL CYCLE83 and CYCLE81 in a plane tilted by CYCLE800, along the plane's Z") {
  const std::string text =
      "N10 G17 G90 G71 G94 T1 M6\n"
      "N20 G0 X0 Y0 Z100 A0 C0 S3000 M3 F250\n"
      "N30 CYCLE800(0,\"TC1\",200000,57,10,0,0,-20,0,15,0,0,0,1,100,1)\n"
      "N40 G0 X0 Y0 Z30\n"
      "N50 MCALL CYCLE83(30, 0, 3, -14, , -4, , 1, 0, 0, 0.8, 0, 0, 0, 0.4)\n"
      "N60 X5 Y5\n"
      "N70 X-5 Y5\n"
      "N80 MCALL\n"
      "N90 X0 Y-8\n"
      "N100 CYCLE81(30, 0, 2, -6)\n"
      "N110 CYCLE800()\n"
      "N120 M30\n";
  const std::string out = reposted_and_checked(text, true);
}

TEST_CASE("sinumerik re-post: CYCLE800 _MODE=27 turns about Z, then Y', then X'' (the order ncpost's output writes)") {
  const std::string text =
      "N10 G17 G90 G71 G94 T1 M6\n"
      "N20 G0 X0 Y0 Z100 A0 C0 S3000 M3 F400\n"
      "N30 CYCLE800(0,\"TC1\",200000,27,5,-5,0,30,20,0,0,0,0,1,100,1)\n"
      "N40 G0 X0 Y0 Z20\n"
      "N50 G1 Z-1\n"
      "N60 X15 Y10\n"
      "N70 G0 Z20\n"
      "N80 CYCLE800()\n"
      "N90 M30\n";
  const std::string out = reposted_and_checked(text, true);
  // by hand: Rz(30) Ry(20) e_z = (sin20 cos30, sin20 sin30, cos20)
  const double s20 = std::sin(20 * M_PI / 180), c20 = std::cos(20 * M_PI / 180);
  const test::V3 normal(s20 * std::cos(M_PI / 6), s20 * std::sin(M_PI / 6), c20);
  const test::ExecMachine m = test::ExecMachine::load(test::source("machines/ac-trunnion.toml"));
  const std::map<char, double> got = first_tilt(out);
  REQUIRE(got.count('A'));
  const test::ExecPose pose = test::forward(m, exec_job(), test::V3::Zero(), {{'A', got.at('A')}, {'C', got.at('C')}});
  CHECK((pose.axis_W - normal).norm() < kAxisTolerance);
}

TEST_CASE("sinumerik re-post: CYCLE84 (rigid, MPIT and PIT, left-hand) and MCALL CYCLE840 as the tap G84 / G74") {
  const std::string text =
      "N10 G17 G90 G71 G94 T1 M6\n"
      "N20 G0 X0 Y0 Z30 A0 C0 S500 M3\n"
      "N30 G0 X10 Y5 Z20\n"
      "N40 CYCLE84(20, 0, 2, -12, , 0, 3, 8, , 0, 400, 0)\n"  // M8: 1.25 mm at 400 rpm, on RTP
      "N50 G0 X-15 Y5 Z25\n"
      "N60 CYCLE84(2, 0, 2, , 9, 0, 5, , -1.5, 0, 300, 300)\n"  // left-hand 1.5 mm, RTP = the safety plane
      "N70 G1 Y0 F333\n"
      "N80 G0 Z20 S600 M3\n"
      "N90 MCALL CYCLE840(20, 0, 3, -10, , 0, 0, 3, 0, 0, 1.0)\n"  // with encoder: 1 mm x 600 rpm
      "N100 G0 X30 Y-10\n"
      "N110 X40\n"
      "N120 MCALL\n"
      "N130 G0 Z50\n"
      "N140 M30\n";
  const std::string out = reposted_and_checked(text, false);
  // the thread's feed pitch x speed (hand-computed: M8 1.25 x 400, 1.5 x 300, 1.0 x 600) and its hand
  CHECK_THAT(out, Catch::Contains("G84") && Catch::Contains("F500.") && Catch::Contains("G74") &&
                      Catch::Contains("F450.") && Catch::Contains("F600."));
  const test::Executor ex(test::source("machines/ac-trunnion.toml"), exec_job(), out);
  int threads_followed_out = 0;
  for (const auto& b : ex.blocks)
    if (b.kind == test::ExecBlock::Kind::linear && b.to.at('Z') > b.from.at('Z') + 1.0) ++threads_followed_out;
  CHECK(threads_followed_out == 4);
}

TEST_CASE("sinumerik CYCLE84 / CYCLE840: what the posted tap cannot hold is refused by name") {
  const auto refusal = [](const std::string& call) {
    try {
      repost("G0 X0 Y0 Z20 A0 C0 S500 M3 F100\n" + call + "\nM30\n", false);
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string("(posted)");
  };
  CHECK_THAT(refusal("CYCLE84(20, 0, 2, -12, , 0.5, 3, 8, , 0, 400, 0)"),
             Catch::Contains("repost.mpf:2:") && Catch::Contains("DTB=0.5"));
  CHECK_THAT(refusal("CYCLE84(20, 0, 2, -12, , 0, 3, 8, , 0, 400, 800)"), Catch::Contains("SST1=800"));
  CHECK_THAT(refusal("CYCLE84(20, 0, 2, -12, , 0, 3, 7, , 0, 400, 0)"), Catch::Contains("MPIT=7"));
  CHECK_THAT(refusal("CYCLE84(20, 0, 2, -12, , 0, 3, 8, 1.5, 0, 400, 0)"), Catch::Contains("disagree"));
  CHECK_THAT(refusal("CYCLE84(20, 0, 2, -12, , 0, 3, 8, , 0, 400, 0, 0, 0, 0, 1)"), Catch::Contains("_VARI=1"));
  CHECK_THAT(refusal("CYCLE840(20, 0, 2, -12, , 0, 0, 3, 0, 0, -1.0)"),
             Catch::Contains("left-hand thread") && Catch::Contains("program M4"));
  CHECK_THAT(refusal("ROT Z30\nCYCLE84(20, 0, 2, -12, , 0, 3, 8, , 0, 400, 0)"), Catch::Contains("rotated"));
}
