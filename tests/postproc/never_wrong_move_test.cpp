// SPDX-License-Identifier: Apache-2.0
// Issue 27, "Never a wrong move": the written program is read back with the tests' own executor
// (tests/support/nc_executor.hpp: its own machine-file reading, forward kinematics and word
// reader) and its motion is checked against what the CL data mean, computed here:
//  1. rapids out of (and into) a tilted hole or cut leave (enter) along the tool axis;
//  2. an inverse-time (G93) block runs for its executed tip path length over the feed;
//  4. a LOADTL length that the head's axis positions depend on is used or refused, never dropped;
//  6. small tilts away from a vertical tool axis (the singular pose of an AC table) are posted.
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "cli_run.hpp"
#include "nc_executor.hpp"
#include "temp_dir.hpp"
#include "test_paths.hpp"
#include "text_file.hpp"

using namespace ncpost::test;

namespace {

/// `ncpost post ARGS` of the CL text `cl` (an .apt file); the written program and the log.
PostRun post_cl(const std::string& cl, const std::string& args, const std::string& name) {
  const std::string dir = make_temp_dir("never_wrong_move");
  const std::string in = write_text_file(dir + "/" + name + ".apt", cl);
  const std::string out = dir + "/" + name + ".nc", log = dir + "/" + name + ".log";
  return run_post(args, in, out, log);
}

/// "GOTO/x,y,z,i,j,k" of a CL point.
std::string fmt_point(const V3& tip, const V3& axis) {
  const V3 u = axis.normalized();
  return fmt::format("GOTO/{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f}\n", tip.x(), tip.y(), tip.z(), u.x(), u.y(),
                     u.z());
}

/// The tilted hole of the issue: tool axis 20 deg from Z in XZ, top at (10, 0, 0) of W, R plane
/// 3 mm above the top, bottom 12 mm below it, drilled with CYCLE/DRILL.
const std::string kTiltedHole =
    "UNITS/MM\nMULTAX/ON\nLOADTL/2\nSPINDL/RPM,1500,CLW\nRAPID\n"
    "GOTO/27.101007,0,46.984631,0.342020,0,0.939693\n"
    "CYCLE/DRILL,RAPTO,3,FEDTO,-12,MMPM,120\n"
    "GOTO/10,0,0,0.342020,0,0.939693\n"
    "CYCLE/OFF\nFINI\n";

/// The largest distance of a rapid's executed tip from the tool-axis line through `top` (unit
/// `axis`) over the samples of every rapid block that lie inside the cylinder about that line from
/// `depth_mm` below `top` to `clear_mm` above it, `radius_mm` wide (the hole, or the space a
/// retract must leave along the axis); and how many rapid blocks entered that cylinder.
std::pair<double, int> worst_rapid_off_axis(const Executor& ex, const V3& top, const V3& axis, double depth_mm,
                                            double clear_mm, double radius_mm = 10.0) {
  double worst = 0.0;
  int seen = 0;
  for (const ExecBlock& b : ex.blocks) {
    if (b.kind != ExecBlock::Kind::rapid || !b.from_known) continue;
    bool inside_once = false;
    for (int i = 0; i <= 400; ++i) {
      const auto [off, along] = from_line(ex.at(b, i / 400.0).tip_W, top, axis);
      if (along < -depth_mm - 1e-6 || along > clear_mm - 1e-3 || off > radius_mm) continue;
      inside_once = true;
      worst = std::max(worst, off);
    }
    seen += inside_once ? 1 : 0;
  }
  return {worst, seen};
}

}  // namespace

TEST_CASE("a drill leaves and enters a tilted hole along its axis (RTCP, AC table)", "[post][retract]") {
  const PostRun p =
      post_cl(kTiltedHole, "--machine " + source("machines/ac-trunnion.toml") + " --workpiece-origin 0,0,50 --rtcp",
              "hole_rtcp");
  INFO(p.log);
  REQUIRE(p.exit_code == 0);
  const Executor ex(source("machines/ac-trunnion.toml"), ExecJob{V3(0, 0, 50), 0.0}, p.program);
  const V3 axis = V3(0.342020, 0, 0.939693).normalized();
  const V3 top(10, 0, 0);
  // the feed reaches the bottom 12 mm down the axis
  bool bottom_reached = false;
  for (const ExecBlock& b : ex.blocks)
    if (b.kind == ExecBlock::Kind::linear && (ex.at(b, 1.0).tip_W - (top - 12.0 * axis)).norm() < 1e-3)
      bottom_reached = true;
  CHECK(bottom_reached);
  const auto [off, seen] = worst_rapid_off_axis(ex, top, axis, 12.0, 3.0);
  CHECK(seen >= 1);   // the retract from the bottom (the approach ends at the R plane)
  CHECK(off < 2e-3);  // 4.8 mm sideways before the fix
}

TEST_CASE("a drill leaves a tilted hole along its axis on a head machine (machine axes)", "[post][retract]") {
  const PostRun p =
      post_cl(kTiltedHole,
              "--machine " + source("machines/gantry-bc-head.toml") + " --workpiece-origin 0,0,0 --tool-length 100",
              "hole_head");
  INFO(p.log);
  REQUIRE(p.exit_code == 0);
  const Executor ex(source("machines/gantry-bc-head.toml"), ExecJob{V3::Zero(), 100.0}, p.program);
  const V3 axis = V3(0.342020, 0, 0.939693).normalized();
  const auto [off, seen] = worst_rapid_off_axis(ex, V3(10, 0, 0), axis, 12.0, 3.0);
  CHECK(seen >= 1);
  CHECK(off < 2e-3);
}

TEST_CASE("a rapid retract along a tilted tool axis stays on the axis line (head, 50 mm)", "[post][retract]") {
  // a feed cut ending at (0, 0, 0) with the tool 30 deg from Z, then a rapid 50 mm out along the axis
  const double s = std::sin(M_PI / 6), c = std::cos(M_PI / 6);
  const std::string cl = "UNITS/MM\nMULTAX/ON\nLOADTL/1\nRAPID\n" +
                         fmt_point(V3(-20, 0, 10) + 60 * V3(s, 0, c), V3(s, 0, c)) + "FEDRAT/MMPM,500\n" +
                         fmt_point(V3(-20, 0, 0), V3(s, 0, c)) + fmt_point(V3(0, 0, 0), V3(s, 0, c)) + "RAPID\n" +
                         fmt_point(50 * V3(s, 0, c), V3(s, 0, c)) + "FINI\n";
  for (const bool rtcp : {false, true}) {
    // (W 300 mm below the tip at home: the positioning from home comes from far above the part)
    const PostRun p = post_cl(cl,
                              "--machine " + source("machines/gantry-bc-head.toml") + " --tool-length 100" +
                                  " --workpiece-origin 0,0,-300" + (rtcp ? " --rtcp" : "") + " --tolerance none",
                              rtcp ? "head_rtcp" : "head_axes");
    INFO(p.log);
    REQUIRE(p.exit_code == 0);
    const Executor ex(source("machines/gantry-bc-head.toml"), ExecJob{V3(0, 0, -300), 100.0}, p.program);
    const auto [off, seen] = worst_rapid_off_axis(ex, V3::Zero(), V3(s, 0, c), 0.0, 50.0, 30.0);
    CHECK(seen >= 1);
    CHECK(off < 2e-3);  // 16 mm off the line before the fix
  }
}

TEST_CASE("inverse time: a G93 block runs for its tip path length over the feed", "[post][g93]") {
  // the tip moves 10 mm along X at F500 while the tool turns 30 deg in XZ (10 -> 40 deg): B turns
  // 30 deg, C stays; by the rule the block takes (executed tip path) / 500 min, about 10/500
  const double a0 = 10 * M_PI / 180, a1 = 40 * M_PI / 180;
  const V3 u0(std::sin(a0), 0, std::cos(a0)), u1(std::sin(a1), 0, std::cos(a1));
  const std::string cl = "UNITS/MM\nMULTAX/ON\nLOADTL/1\nRAPID\n" + fmt_point(V3(0, 0, 30), u0) + "FEDRAT/MMPM,500\n" +
                         fmt_point(V3(0, 0, 0), u0) + fmt_point(V3(10, 0, 0), u1) + "FINI\n";
  const PostRun p = post_cl(cl, "--machine " + source("machines/haas-umc750.toml") + " --tolerance none", "g93");
  INFO(p.log);
  INFO(p.program);
  REQUIRE(p.exit_code == 0);
  const Executor ex(source("machines/haas-umc750.toml"), ExecJob{}, p.program);
  int g93_blocks = 0;
  for (const ExecBlock& b : ex.blocks) {
    if (b.kind == ExecBlock::Kind::rapid || !b.inverse_time) continue;
    ++g93_blocks;
    const double path_mm = ex.tip_path_mm(b);
    CHECK(path_mm == Approx(10.0).epsilon(0.05));            // about the 10 mm of the CL (the tip bows a little)
    CHECK(b.feed == Approx(500.0 / path_mm).epsilon(2e-5));  // 1/min; F16.6667 (30 deg / 500) before
  }
  CHECK(g93_blocks == 1);
}

TEST_CASE("inverse time: a pure reorientation runs its rotary travel at the feed in deg/min", "[post][g93]") {
  const double a1 = 20 * M_PI / 180;
  const V3 u0(0, 0, 1), u1(std::sin(a1), 0, std::cos(a1));
  // (start tilted a little so that C is determined; the tip stands still while the tool turns)
  const V3 us(std::sin(0.1), 0, std::cos(0.1));
  const std::string cl = "UNITS/MM\nMULTAX/ON\nLOADTL/1\nRAPID\n" + fmt_point(V3(0, 0, 30), us) + "FEDRAT/MMPM,400\n" +
                         fmt_point(V3(0, 0, 0), us) + fmt_point(V3(0, 0, 0), u1) + "FINI\n";
  (void)u0;
  const PostRun p = post_cl(cl, "--machine " + source("machines/haas-umc750.toml") + " --tolerance none", "g93_turn");
  INFO(p.log);
  INFO(p.program);
  REQUIRE(p.exit_code == 0);
  const Executor ex(source("machines/haas-umc750.toml"), ExecJob{}, p.program);
  const double travel_deg = 20.0 - 0.1 * 180 / M_PI;
  int g93_blocks = 0;
  for (const ExecBlock& b : ex.blocks) {
    if (b.kind == ExecBlock::Kind::rapid || !b.inverse_time) continue;
    ++g93_blocks;
    CHECK(b.feed == Approx(400.0 / travel_deg).epsilon(1e-3));
  }
  CHECK(g93_blocks == 1);
}

namespace {

/// Two tools cutting the same tilted point on the BC head, with the CL lengths given.
std::string two_tools(double length1_mm, double length2_mm) {
  const V3 u(std::sin(0.4), 0, std::cos(0.4));
  const std::string cut = "RAPID\n" + fmt_point(V3(0, 0, 50) + 50 * u, u) + "FEDRAT/MMPM,300\n" +
                          fmt_point(V3(0, 0, 0), u) + "RAPID\n" + fmt_point(60 * u, u);
  return fmt::format("UNITS/MM\nMULTAX/ON\nLOADTL/1,LENGTH,{}\n", length1_mm) + cut +
         fmt::format("LOADTL/2,LENGTH,{}\n", length2_mm) + cut + "FINI\n";
}

}  // namespace

TEST_CASE("LOADTL lengths: used where they agree with the solved length, refused where they do not", "[post][tool]") {
  const std::string head = "--machine " + source("machines/gantry-bc-head.toml") + " --tool-length 100";
  SECTION("another length on a head machine is refused, naming the tool and both lengths") {
    const PostRun p = post_cl(two_tools(100, 150), head, "two_lengths");
    CHECK(p.exit_code != 0);
    CHECK(p.program.empty());
    CHECK(p.log.find("tool 2 is 150.0000 mm long") != std::string::npos);
    CHECK(p.log.find("--tool-length 150.0000") != std::string::npos);
  }
  SECTION("the same length: every cut point reached by the tool of that length") {
    const PostRun p = post_cl(two_tools(100, 100), head, "same_length");
    INFO(p.log);
    REQUIRE(p.exit_code == 0);
    const Executor ex(source("machines/gantry-bc-head.toml"), ExecJob{V3::Zero(), 100.0}, p.program);
    int at_cut = 0;
    for (const ExecBlock& b : ex.blocks)
      if (b.kind == ExecBlock::Kind::linear && ex.at(b, 1.0).tip_W.norm() < 1e-3) ++at_cut;
    CHECK(at_cut == 2);
    CHECK(p.program.find("T2 length 100.0000 mm from the CL data: the axes are solved for it") != std::string::npos);
  }
  SECTION("a table machine: the control's register applies the length, said in the program") {
    const PostRun p =
        post_cl(two_tools(100, 150), "--machine " + source("machines/ac-trunnion.toml") + " --workpiece-origin 0,0,50",
                "table_lengths");
    INFO(p.log);
    REQUIRE(p.exit_code == 0);
    CHECK(p.program.find("T2 length 150.0000 mm from the CL data: the control's length register applies it") !=
          std::string::npos);
  }
}

TEST_CASE("small tilts away from a vertical tool axis are posted, the tip held on the CL point", "[post][singular]") {
  for (const double tilt : {1e-5, 1e-3, 0.01, 0.02, 0.2}) {
    CAPTURE(tilt);
    const V3 u = V3(tilt, 0, 1).normalized();
    const std::string cl = "UNITS/MM\nMULTAX/ON\nLOADTL/1\nRAPID\n" + fmt_point(V3(20, 0, 30), V3(0, 0, 1)) +
                           "FEDRAT/MMPM,500\n" + fmt_point(V3(20, 0, 0), V3(0, 0, 1)) + fmt_point(V3(20, 0, 0), u) +
                           "FINI\n";
    const PostRun p =
        post_cl(cl, "--machine " + source("machines/ac-trunnion.toml") + " --workpiece-origin 0,0,50", "small_tilt");
    INFO(p.log);
    REQUIRE(p.exit_code == 0);
    const Executor ex(source("machines/ac-trunnion.toml"), ExecJob{V3(0, 0, 50), 0.0}, p.program);
    double worst = 0.0;
    ExecPose last;
    for (const ExecBlock& b : ex.blocks) {
      if (b.kind == ExecBlock::Kind::rapid || (ex.at(b, 0.0).tip_W - V3(20, 0, 0)).norm() > 1e-3) continue;
      for (int i = 0; i <= 100; ++i) worst = std::max(worst, (ex.at(b, i / 100.0).tip_W - V3(20, 0, 0)).norm());
      last = ex.at(b, 1.0);
    }
    CHECK(worst <= 0.01 + 1e-9);  // the tolerance of the post (the default, 0.01 mm)
    CHECK(std::acos(std::min(1.0, last.axis_W.dot(u))) < 2e-4);
  }
}

TEST_CASE("a CUTCOM radius register that the dialect cannot write is refused, not dropped", "[post][cutcom]") {
  const std::string cl =
      "UNITS/MM\nLOADTL/1\nRAPID\nGOTO/0,0,10\nFEDRAT/MMPM,300\nGOTO/0,0,-1\n"
      "CUTCOM/LEFT,14\nGOTO/10,0,-1\nGOTO/10,10,-1\nCUTCOM/OFF\nFINI\n";
  const std::string machine = "--machine " + source("machines/vmcl600.toml");
  SECTION("sinumerik: G41 takes the edge of the tool call (D1): register 14 would be lost") {
    const PostRun p = post_cl(cl, machine + " --dialect sinumerik", "cutcom_sinumerik");
    CHECK(p.exit_code == 2);
    CHECK(p.program.empty());
    CHECK(p.log.find("radius register 14 cannot be written in the sinumerik dialect") != std::string::npos);
  }
  SECTION("fanuc writes the register") {
    const PostRun p = post_cl(cl, machine + " --dialect fanuc", "cutcom_fanuc");
    INFO(p.log);
    CHECK(p.exit_code == 0);
    CHECK(p.program.find("G41 D14") != std::string::npos);
  }
}

TEST_CASE("a G-code move that ends at the singular pose with another free angle posts: it arrives, then turns",
          "[post][singular]") {
  // from A10 C15 to A0 C0: the tool axis reaches +Z on the great circle of azimuth C15, where C is
  // free; the source programs C0 there, so C turns in place at the end (was: exit 3, 'error at t = 1')
  const std::string source_nc =
      "%\nO0001\nG90 G21 G94 G17\nT1 M6\nG43 H1\nG0 X10 Y0 Z60 A10 C15\nG1 Z50 F500\n"
      "Y5 A0 C0\nM30\n%\n";
  const std::string dir = make_temp_dir("singular_end");
  const std::string in = write_text_file(dir + "/s.nc", source_nc), out = dir + "/o.nc", log = dir + "/o.log";
  const int rc = run_ncpost(
      "post --machine " + source("machines/ac-trunnion.toml") + " --workpiece-origin 0,0,50 -o " + out + " " + in, log);
  INFO(read_text_file(log));
  REQUIRE(rc == 0);
  const ExecJob job{V3(0, 0, 50), 0.0};
  const Executor src(source("machines/ac-trunnion.toml"), job, source_nc);
  const Executor ex(source("machines/ac-trunnion.toml"), job, read_text_file(out));
  const ExecBlock& last_src = src.blocks.back();
  const V3 a = src.at(last_src, 0.0).tip_W, b = src.at(last_src, 1.0).tip_W;
  double worst = 0.0;
  bool in_move = false;
  for (const ExecBlock& blk : ex.blocks) {
    if (blk.kind == ExecBlock::Kind::rapid) continue;
    if (!in_move && (ex.at(blk, 0.0).tip_W - a).norm() > 1e-3) continue;
    in_move = true;
    for (int i = 0; i <= 50; ++i) worst = std::max(worst, from_segment(ex.at(blk, i / 50.0).tip_W, a, b));
  }
  CHECK(in_move);
  CHECK(worst <= 0.01 + 1e-6);
  const ExecPose end = ex.at(ex.blocks.back(), 1.0), want = src.at(last_src, 1.0);
  CHECK((end.tip_W - want.tip_W).norm() < 1e-3);
  CHECK((end.axis_W - want.axis_W).norm() < 1e-4);
  CHECK(ex.blocks.back().to.at('C') == Approx(0.0).margin(1e-4));  // the programmed C at the end
}
