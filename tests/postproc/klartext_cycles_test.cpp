// SPDX-License-Identifier: Apache-2.0
// The Heidenhain hole cycles 201, 203, 206, 207, 208, 240 and 241, the polar line LP and the corners RND
// and CHF (issue 28) re-posted for a Fanuc control and
// both sides executed independently: the Klartext input by the tests' interpreter
// (klartext_interpreter.hpp, the cycles' runs in klartext_cycles.hpp), the written program by
// nc_executor.hpp. Every end of an input move (each move of each cycle) must be reached by an
// output block end, in order, within 1 µm; every output feed block, sampled, must lie within the
// tolerance the output's header states of the input's cutting path.
#include <catch2/catch.hpp>

#include <sstream>

#include "input_output_tips.hpp"
#include "klartext_interpreter.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/machine/serial_post_machine.hpp"
#include "ncpost/postproc/post_request.hpp"
#include "ncpost/postproc/read/tool_table.hpp"
#include "ncpost/postproc/write/dialect.hpp"
#include "polyline_distance.hpp"
#include "test_paths.hpp"
#include "vmcl600_setup.hpp"

using namespace ncpost;

namespace {

const std::string kMachine = "machines/vmcl600.toml";

/// The programs call "DRILL8" by name; the fanuc dialect takes its number from the table.
std::string post_cycles(const std::string& text, const std::string& tool_table = "[tools]\nDRILL8 = 8\n") {
  PostRequest r;
  r.machine = serial_post_machine(load_machine(test::source(kMachine)));
  r.setup = test::vmcl600_setup();
  r.dialect = dialect_named("fanuc");
  r.threads = 1;
  r.input_name = "cycles.h";
  r.tool_table = std::make_shared<const ToolTable>(parse_tool_table(tool_table, "tools.toml"));
  r.reader.tool_table = r.tool_table;
  std::istringstream in(text);
  std::ostringstream out;
  post(in, out, r);
  return out.str();
}

/// The input's ends reached in order within 1 µm, and the output's feed blocks on the input's
/// cutting path within the stated tolerance. Returns the number of input ends.
std::size_t check_cycles(const std::string& text, const std::string& nc, double tool_diameter_mm = 0.0) {
  INFO(nc);
  test::ExecJob job;
  job.workpiece_origin_mm = test::vmcl600_setup().workpiece_origin_mm;
  job.tool_length_mm = test::vmcl600_setup().tool_length_mm;
  const test::ExecMachine m = test::ExecMachine::load(test::source(kMachine));
  test::KlartextInterpreter input(m, job, {});
  input.set_tool_diameter(tool_diameter_mm);
  const std::vector<test::KlartextEnd> want = input.run(text);
  const test::Executor out(test::source(kMachine), job, nc);
  std::size_t next = 0;
  for (const test::KlartextEnd& e : want) {
    INFO("input line " << e.line << " tip " << e.tip_W.transpose());
    while (next < out.blocks.size() && (out.at(out.blocks[next], 1.0).tip_W - e.tip_W).norm() > 1e-3) ++next;
    REQUIRE(next < out.blocks.size());
  }
  const double tolerance_mm = test::stated_tolerance_mm(nc, 1e-3) + 1e-6;
  const auto& path = input.path();
  for (const test::ExecBlock& b : out.blocks) {
    if (b.kind == test::ExecBlock::Kind::rapid) continue;
    for (int i = 1; i < 16; ++i) {
      const Vec3d p = out.at(b, i / 16.0).tip_W;
      double best = 1e9;
      for (std::size_t k = 1; k < path.size(); ++k)
        if (path[k].cut) best = std::min(best, test::segment_distance_mm(p, path[k - 1].tip_W, path[k].tip_W));
      INFO("output line " << b.line << ": " << b.text << " at " << i << "/16");
      REQUIRE(best <= tolerance_mm);
    }
  }
  return want.size();
}

std::string refusal(const std::string& text, const std::string& tool_table = "[tools]\nDRILL8 = 8\n") {
  try {
    post_cycles(text, tool_table);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(posted)";
}

/// Whether a block of the written program `nc` ends at the program point `p` (the VMC's program X Y Z
/// are W's plus the workpiece origin's), within 1 µm.
bool nc_reaches(const std::string& nc, const Eigen::Vector3d& p) {
  test::ExecJob job;
  job.workpiece_origin_mm = test::vmcl600_setup().workpiece_origin_mm;
  job.tool_length_mm = test::vmcl600_setup().tool_length_mm;
  const test::Executor out(test::source(kMachine), job, nc);
  for (const test::ExecBlock& b : out.blocks)
    if ((out.at(b, 1.0).tip_W + job.workpiece_origin_mm - p).norm() < 1e-3) return true;
  return false;
}

/// The Q lines rigid tapping cycles (207, 209) share, the depth 13 mm from the surface at 0, without the last line's
/// end.
std::string tap_parameters(const std::string& clearance, const std::string& pitch, const std::string& second) {
  return "  Q200=" + clearance + " ;SET-UP CLEARANCE ~\n  Q201=-13 ;DEPTH OF THREAD ~\n  Q239=" + pitch +
         " ;THREAD PITCH ~\n  Q203=+0 ;SURFACE COORDINATE ~\n  Q204=" + second + " ;2ND SET-UP CLEARANCE";
}

const std::string kHead =
    "0 BEGIN PGM CYCLES MM\n"
    "1 TOOL CALL \"DRILL8\" Z S2000 DL+0 DR+0\n"
    "2 L X+0 Y+0 Z+50 R0 FMAX M3\n";

}  // namespace

TEST_CASE("klartext CYCL DEF 203: shrinking pecks, chip breaks and retractions where the cycle run puts them") {
  const std::string text = kHead +
                           "3 CYCL DEF 203 UNIVERSAL DRILLING ~\n"
                           "  Q200=+2 ;SET-UP CLEARANCE ~\n"
                           "  Q201=-12 ;DEPTH ~\n"
                           "  Q206=+150 ;FEED RATE FOR PLNGNG ~\n"
                           "  Q202=+4 ;PLUNGING DEPTH ~\n"
                           "  Q210=+0 ;DWELL TIME AT TOP ~\n"
                           "  Q203=+1 ;SURFACE COORDINATE ~\n"
                           "  Q204=+20 ;2ND SET-UP CLEARANCE ~\n"
                           "  Q212=+1 ;DECREMENT ~\n"
                           "  Q213=+2 ;BREAKS ~\n"
                           "  Q205=+2 ;MIN. PLUNGING DEPTH ~\n"
                           "  Q211=+0.5 ;DWELL TIME AT DEPTH ~\n"
                           "  Q208=+2000 ;RETRACTION FEED RATE ~\n"
                           "  Q256=+0.2 ;DIST FOR CHIP BRKNG\n"
                           "4 L X+30 Y+20 R0 FMAX M99\n"
                           "5 L X+60 R0 FMAX M99\n"
                           "6 L Z+50 FMAX M5\n"
                           "7 END PGM CYCLES MM\n";
  const std::string nc = post_cycles(text);
  // plunges of 4, 3, 2, 2, 1 (the last to the depth): breaks after the 1st and 2nd, out after the
  // 3rd, breaks after the 4th ... per hole: 1 + 5 plunges + 2 breaks + 2 (out, back) + 1 break + out + 2nd
  CHECK(check_cycles(text, nc) >= 2 * 12);
  CHECK(nc.find("G4") != std::string::npos);  // the dwell at the depth
  CHECK(nc.find("F2000.") != std::string::npos);
  // Q208=MAX (as the TNC shows FMAX): the same moves, each retraction (3 breaks, the retraction
  // after the 3rd plunge and the last one out, per hole) a rapid instead of a move at Q208
  std::string fmax = text;
  fmax.replace(fmax.find("Q208=+2000"), 10, "Q208=MAX");
  const std::string nc_fmax = post_cycles(fmax);
  CHECK(nc_fmax.find("F2000.") == std::string::npos);
  test::ExecJob job;
  job.workpiece_origin_mm = test::vmcl600_setup().workpiece_origin_mm;
  job.tool_length_mm = test::vmcl600_setup().tool_length_mm;
  const test::Executor fed(test::source(kMachine), job, nc), rapid(test::source(kMachine), job, nc_fmax);
  REQUIRE(fed.blocks.size() == rapid.blocks.size());
  int became_rapid = 0;
  for (std::size_t i = 0; i < fed.blocks.size(); ++i) {
    CHECK((fed.at(fed.blocks[i], 1.0).tip_W - rapid.at(rapid.blocks[i], 1.0).tip_W).norm() < 1e-9);
    const bool was_feed = fed.blocks[i].kind == test::ExecBlock::Kind::linear;
    const bool now_rapid = rapid.blocks[i].kind == test::ExecBlock::Kind::rapid;
    if (was_feed && now_rapid) {
      ++became_rapid;
      CHECK(fed.blocks[i].feed == 2000.0);
    }
  }
  CHECK(became_rapid == 2 * 5);
}

TEST_CASE("klartext CYCL DEF 207: a rigid tap at pitch x speed, refused against the spindle's direction") {
  const std::string cycle = "3 CYCL DEF 207 RIGID TAPPING NEW ~\n" + tap_parameters("+3", "+1.25", "+28") +
                            "\n"
                            "4 L X+10 Y-15 R0 FMAX M99\n"
                            "5 L Z+50 FMAX M5\n"
                            "6 END PGM CYCLES MM\n";
  const std::string text = kHead + cycle;
  const std::string nc = post_cycles(text);
  check_cycles(text, nc);
  CHECK(nc.find("G84") != std::string::npos);
  CHECK(nc.find("F2500.") != std::string::npos);  // 1.25 mm x 2000 rpm
  std::string m4 = text;
  m4.replace(m4.find("FMAX M3"), 7, "FMAX M4");
  CHECK_THAT(refusal(m4), Catch::Contains("cycles.h:10:") && Catch::Contains("CYCL DEF 207 with a right-hand thread") &&
                              Catch::Contains("program M3"));
}

TEST_CASE("klartext CYCL DEF 206: a tap in a floating holder at Q206, its hand the spindle's direction") {
  const std::string text = kHead +
                           "3 CYCL DEF 206 TAPPING NEW ~\n"
                           "  Q200=+3 ;SET-UP CLEARANCE ~\n"
                           "  Q201=-13 ;DEPTH OF THREAD ~\n"
                           "  Q206=+2500 ;FEED RATE FOR PLNGNG ~\n"
                           "  Q211=+0 ;DWELL TIME AT DEPTH ~\n"
                           "  Q203=+0 ;SURFACE COORDINATE ~\n"
                           "  Q204=+28 ;2ND SET-UP CLEARANCE\n"
                           "4 L X+10 Y-15 R0 FMAX M99\n"
                           "5 L Z+50 FMAX M5\n"
                           "6 END PGM CYCLES MM\n";
  const std::string nc = post_cycles(text);
  check_cycles(text, nc);
  CHECK(nc.find("G84") != std::string::npos);     // M3: a right-hand thread
  CHECK(nc.find("F2500.") != std::string::npos);  // Q206 (the pitch 1.25 mm at 2000 rpm)
  std::string stopped = text;
  stopped.replace(stopped.find("FMAX M3"), 7, "FMAX M5");
  CHECK_THAT(refusal(stopped),
             Catch::Contains("cycles.h:11:") && Catch::Contains("CYCL DEF 206 called with the spindle stopped"));
}

TEST_CASE("klartext CYCL DEF 209 with chip removal (Q256=0): a tap Q257 deeper each time, out to Q200 in between") {
  // two holes (lines 4 and 5), the chip breaking's parameters after those 207 has
  const std::string chips =
      " ~\n  Q257=+4 ;DEPTH FOR CHIP BRKNG ~\n  Q256=+0 ;DIST FOR CHIP BRKNG ~\n"
      "  Q336=+0 ;ANGLE OF SPINDLE ~\n  Q403=+1 ;RPM FACTOR\n";
  const std::string holes = "4 L X+10 Y-15 R0 FMAX M99\n5 L X+30 R0 FMAX M99\n6 L Z+50 FMAX M5\n7 END PGM CYCLES MM\n";
  const std::string text =
      kHead + "3 CYCL DEF 209 TAPPING W/ CHIP BRKG ~\n" + tap_parameters("+2", "+1.5", "+2") + chips + holes;
  const std::string nc = post_cycles(text);
  // four L blocks; per hole: FMAX to Q200, taps to 4, 8, 12 and 13 mm each out to Q200: 1 + 2 x 4 ends
  CHECK(check_cycles(text, nc) == 4 + 2 * (1 + 2 * 4));
  CHECK(nc.find("G84") != std::string::npos);     // each infeed a rigid tap (M3: right-hand)
  CHECK(nc.find("F3000.") != std::string::npos);  // 1.5 mm x 2000 rpm
  // no chip breaking (Q257=0): one tap to the depth, as 207
  std::string whole = text;
  whole.replace(whole.find("Q257=+4"), 7, "Q257=+0");
  CHECK(check_cycles(whole, post_cycles(whole)) == 4 + 2 * 3);
  // the partial retraction inside the hole (Q256 > 0) and a faster retraction (Q403) are refused by name
  std::string breaking = text;
  breaking.replace(breaking.find("Q256=+0"), 7, "Q256=+0.5");
  CHECK_THAT(refusal(breaking), Catch::Contains("cycles.h:4:") && Catch::Contains("CYCL DEF 209: Q256=0.5") &&
                                    Catch::Contains("0.75 mm") && Catch::Contains("Q256=0 (out to the set-up"));
  std::string faster = text;
  faster.replace(faster.find("Q403=+1"), 7, "Q403=+2");
  CHECK_THAT(refusal(faster), Catch::Contains("cycles.h:4:") && Catch::Contains("Q403=2"));
  std::string m4 = text;
  m4.replace(m4.find("FMAX M3"), 7, "FMAX M4");
  CHECK_THAT(refusal(m4), Catch::Contains("CYCL DEF 209 with a right-hand thread") && Catch::Contains("program M3"));
}

TEST_CASE(
    "klartext CYCL DEF 208: the helix on the bore's circle less the tool, with the diameter from the tool table") {
  const std::string text = kHead +
                           "3 CYCL DEF 208 BORE MILLING ~\n"
                           "  Q200=+1 ;SET-UP CLEARANCE ~\n"
                           "  Q201=-6 ;DEPTH ~\n"
                           "  Q206=+600 ;FEED RATE FOR PLNGNG ~\n"
                           "  Q334=+1.5 ;PLUNGING DEPTH ~\n"
                           "  Q203=+0 ;SURFACE COORDINATE ~\n"
                           "  Q204=+30 ;2ND SET-UP CLEARANCE ~\n"
                           "  Q335=+20 ;NOMINAL DIAMETER ~\n"
                           "  Q342=+0 ;ROUGHING DIAMETER ~\n"
                           "  Q351=+1 ;CLIMB OR UP-CUT\n"
                           "4 L X+40 Y+30 R0 FMAX M99\n"
                           "5 L Z+50 FMAX M5\n"
                           "6 END PGM CYCLES MM\n";
  const std::string table = "[tools]\nDRILL8 = { number = 8, diameter = 8.0 }\n";
  const std::string nc = post_cycles(text, table);
  check_cycles(text, nc, 8.0);
  // climb milling with M3 inside a bore runs counter-clockwise: G3 arcs (r = (20 - 8) / 2 = 6)
  CHECK(nc.find("G3") != std::string::npos);
  CHECK(nc.find("G2 ") == std::string::npos);
  // a DR in the TOOL CALL widens the tool: the helix's radius shrinks by it
  std::string wider = text;
  wider.replace(wider.find("DR+0"), 4, "DR+1");
  check_cycles(wider, post_cycles(wider, table), 10.0);
  CHECK_THAT(refusal(text), Catch::Contains("cycles.h:14:") &&
                                Catch::Contains("CYCL DEF 208 with the tool \"DRILL8\"") &&
                                Catch::Contains("--tool-table"));
}

TEST_CASE("klartext CYCL DEF 241: pre-positioning into the pilot hole, its speeds in and out, the drilling speed") {
  const std::string text = kHead +
                           "3 CYCL DEF 241 SINGLE-LIP DEEP-HOLE DRILLING ~\n"
                           "  Q200=+3 ;SET-UP CLEARANCE ~\n"
                           "  Q201=-60 ;DEPTH ~\n"
                           "  Q206=+80 ;FEED RATE FOR PLUNGING ~\n"
                           "  Q211=+0 ;DWELL TIME AT BOTTOM ~\n"
                           "  Q203=+0 ;SURFACE COORDINATE ~\n"
                           "  Q204=+30 ;2ND SET-UP CLEARANCE ~\n"
                           "  Q379=+15 ;STARTING POINT ~\n"
                           "  Q253=+50 ;F PRE-POSITIONING ~\n"
                           "  Q208=+300 ;RETRACTION FEED TIME ~\n"
                           "  Q426=+4 ;DIR. OF SPINDLE ROT. ~\n"
                           "  Q427=+50 ;ROT. SPEED INFEED/OUT ~\n"
                           "  Q428=+1790 ;DRILLING SPEED ~\n"
                           "  Q429=+7 ;COOLANT ON ~\n"
                           "  Q430=+7 ;COOLANT OFF ~\n"
                           "  Q435=+0 ;DWELL DEPTH\n"
                           "4 L X-20 Y+7 R0 FMAX M99\n"
                           "5 L Z+50 FMAX M5\n"
                           "6 END PGM CYCLES MM\n";
  const std::string nc = post_cycles(text);
  check_cycles(text, nc);
  // in at 50 rpm counter-clockwise, the drilling at 1790 rpm clockwise (M3 before the cycle), out at 50 again
  const auto in = nc.find("S50 M4"), drill = nc.find("S1790 M3"), out = nc.rfind("S50 M4");
  CHECK(in != std::string::npos);
  CHECK(drill != std::string::npos);
  CHECK((in < drill && drill < out));
  std::string dwell_depth = text;
  dwell_depth.replace(dwell_depth.find("Q435=+0"), 7, "Q435=+5");
  CHECK_THAT(refusal(dwell_depth), Catch::Contains("cycles.h:4:") && Catch::Contains("CYCL DEF 241: Q435=5"));
}

TEST_CASE("klartext CYCL DEF 201 and 240: reaming out at its own feed, centering out at FMAX, each with its dwell") {
  const std::string text = kHead +
                           "3 CYCL DEF 201 REAMING ~\n"
                           "  Q200=+2 ;SET-UP CLEARANCE ~\n"
                           "  Q201=-15 ;DEPTH ~\n"
                           "  Q206=+100 ;FEED RATE FOR PLNGNG ~\n"
                           "  Q211=+0.5 ;DWELL TIME AT DEPTH ~\n"
                           "  Q208=+250 ;RETRACTION FEED RATE ~\n"
                           "  Q203=+0 ;SURFACE COORDINATE ~\n"
                           "  Q204=+25 ;2ND SET-UP CLEARANCE\n"
                           "4 L X+12 Y+8 R0 FMAX M99\n"
                           "5 CYCL DEF 240 CENTERING ~\n"
                           "  Q200=+2 ;SET-UP CLEARANCE ~\n"
                           "  Q343=+0 ;SELECT DEPTH/DIA. ~\n"
                           "  Q201=-3 ;DEPTH ~\n"
                           "  Q344=-9 ;DIAMETER ~\n"
                           "  Q206=+180 ;FEED RATE FOR PLNGNG ~\n"
                           "  Q211=+0.2 ;DWELL TIME AT DEPTH ~\n"
                           "  Q203=-1 ;SURFACE COORDINATE ~\n"
                           "  Q204=+40 ;2ND SET-UP CLEARANCE\n"
                           "6 L X+40 Y-6 R0 FMAX M99\n"
                           "7 L Z+50 FMAX M5\n"
                           "8 END PGM CYCLES MM\n";
  const std::string nc = post_cycles(text);
  // per hole: to Q200, to the depth, back to Q200, to Q204
  CHECK(check_cycles(text, nc) == 4 + 2 * 4);    // the four L blocks and four ends per hole
  CHECK(nc.find("F250.") != std::string::npos);  // 201's retraction feed
  CHECK(nc.find("F180.") != std::string::npos);
  CHECK(nc.find("G4") != std::string::npos);
  // 240 leaves the hole at FMAX: the block after the centering's bottom (Z-4 in the program) is a rapid
  test::ExecJob job;
  job.workpiece_origin_mm = test::vmcl600_setup().workpiece_origin_mm;
  job.tool_length_mm = test::vmcl600_setup().tool_length_mm;
  const test::Executor out(test::source(kMachine), job, nc);
  int rapids_out = 0, feeds_out = 0;  // (the program's Z is W's plus the origin's: the bottom Q203 + Q201 = -4)
  for (std::size_t i = 0; i + 1 < out.blocks.size(); ++i)
    if (std::abs(out.at(out.blocks[i], 1.0).tip_W.z() + job.workpiece_origin_mm.z() + 4.0) < 1e-6)
      (out.blocks[i + 1].kind == test::ExecBlock::Kind::rapid ? rapids_out : feeds_out) += 1;
  CHECK(rapids_out == 1);
  CHECK(feeds_out == 0);
  std::string by_diameter = text;
  by_diameter.replace(by_diameter.find("Q343=+0"), 7, "Q343=+1");
  CHECK_THAT(refusal(by_diameter),
             Catch::Contains("cycles.h:13:") && Catch::Contains("CYCL DEF 240: Q343=1") && Catch::Contains("T-ANGLE"));
}

TEST_CASE("klartext: a decimal comma (X+50,022, older TNC programs) is read as the decimal point") {
  // (in coordinates, feeds and Q formulas: Q5 = -0,625 * 2 is -1.25)
  const std::string commas =
      kHead + "3 Q5 = -0,625 * 2\n4 L X+50,022 Y+80,5 R0 FMAX\n5 L Z+Q5 F150,0\n6 END PGM CYCLES MM\n";
  const std::string points =
      kHead + "3 Q5 = -0.625 * 2\n4 L X+50.022 Y+80.5 R0 FMAX\n5 L Z+Q5 F150.0\n6 END PGM CYCLES MM\n";
  const std::string nc = post_cycles(commas);
  CHECK(nc == post_cycles(points));
  CHECK(nc_reaches(nc, Eigen::Vector3d(50.022, 80.5, -1.25)));
}

TEST_CASE("klartext M89: the cycle after every positioning block until M99 (which calls it once more)") {
  const std::string text = kHead +
                           "3 CYCL DEF 203 UNIVERSAL DRILLING ~\n"
                           "  Q200=+2 ;SET-UP CLEARANCE ~\n"
                           "  Q201=-6 ;DEPTH ~\n"
                           "  Q206=+150 ;FEED RATE FOR PLNGNG ~\n"
                           "  Q202=+6 ;PLUNGING DEPTH ~\n"
                           "  Q210=+0 ;DWELL TIME AT TOP ~\n"
                           "  Q203=+0 ;SURFACE COORDINATE ~\n"
                           "  Q204=+20 ;2ND SET-UP CLEARANCE ~\n"
                           "  Q212=+0 ;DECREMENT ~\n"
                           "  Q213=+0 ;BREAKS ~\n"
                           "  Q205=+0 ;MIN. PLUNGING DEPTH ~\n"
                           "  Q211=+0 ;DWELL TIME AT DEPTH ~\n"
                           "  Q208=+1000 ;RETRACTION FEED RATE ~\n"
                           "  Q256=+0.2 ;DIST FOR CHIP BRKNG\n"
                           "4 L X+10 Y+10 R0 FMAX M89\n"
                           "5 L X+20 R0 FMAX\n"
                           "6 L Y+20 R0 FMAX\n"
                           "7 L X+10 R0 FMAX M99\n"
                           "8 L X+0 Y+0 R0 FMAX\n"
                           "9 L Z+50 FMAX M5\n"
                           "10 END PGM CYCLES MM\n";
  const std::string nc = post_cycles(text);
  check_cycles(text, nc);
  // four holes (lines 4 to 7), none after M99 (line 8): the input's and the output's ends at the depth
  test::ExecJob job;
  job.workpiece_origin_mm = test::vmcl600_setup().workpiece_origin_mm;
  job.tool_length_mm = test::vmcl600_setup().tool_length_mm;
  const test::ExecMachine m = test::ExecMachine::load(test::source(kMachine));
  test::KlartextInterpreter input(m, job, {});
  const std::vector<test::KlartextEnd> ends = input.run(text);
  double deepest = 1e9;
  for (const test::KlartextEnd& e : ends) deepest = std::min(deepest, e.tip_W.z());
  int in_bottoms = 0, out_bottoms = 0;
  for (const test::KlartextEnd& e : ends) in_bottoms += std::abs(e.tip_W.z() - deepest) < 1e-9;
  const test::Executor out(test::source(kMachine), job, nc);
  for (const test::ExecBlock& b : out.blocks) out_bottoms += std::abs(out.at(b, 1.0).tip_W.z() - deepest) < 1e-6;
  CHECK(in_bottoms == 4);
  CHECK(out_bottoms == 4);
}

TEST_CASE("klartext LP: lines in polar coordinates about CC, absolute and incremental PR / PA, with Z") {
  const std::string text = kHead +
                           "3 L X+30 Y+10 Z+2 FMAX\n"
                           "4 CC X+10 Y+10\n"
                           "5 LP PR+20 PA+0 Z-3 F300\n"
                           "6 LP PA+90\n"
                           "7 LP IPR-5 IPA+45\n"
                           "8 CC IX+5 IY+0\n"
                           "9 LP PR+8 PA-30 IZ-1\n"
                           "10 L Z+50 FMAX M5\n"
                           "11 END PGM CYCLES MM\n";
  const std::string nc = post_cycles(text);
  CHECK(check_cycles(text, nc) == 7);
  // by hand: PA+90 about (10, 10) at 20 is (10, 30); then 15 at 135 deg; the pole 5 further along X
  const double r135 = 15.0 / std::sqrt(2.0);
  const Eigen::Vector3d pole2(10.0 - r135 + 5.0, 10.0 + r135, 0.0);
  const Eigen::Vector3d want[] = {{10, 30, -3},
                                  {10 - r135, 10 + r135, -3},
                                  pole2 + Eigen::Vector3d(8 * std::cos(M_PI / 6), -8 * std::sin(M_PI / 6), -4)};
  for (const Eigen::Vector3d& w : want) CHECK(nc_reaches(nc, w));
  CHECK_THAT(refusal(kHead + "3 LP PR+5 PA+0\n4 END PGM CYCLES MM\n"),
             Catch::Contains("cycles.h:4:") && Catch::Contains("LP without a CC"));
}

TEST_CASE("klartext RND and CHF: the corner rounded by an arc tangent to both lines, or cut by a chamfer") {
  const std::string text = kHead +
                           "3 L X+0 Y+0 Z+2 FMAX\n"
                           "4 L Z-2 F200\n"
                           "5 L X+40 F400\n"
                           "6 RND R5\n"
                           "7 L Y+30\n"
                           "8 CHF 4\n"
                           "9 L X+10 Y+40\n"
                           "10 RND R3 F100\n"
                           "11 L X+0 Y+0\n"
                           "12 L Z+50 FMAX M5\n"
                           "13 END PGM CYCLES MM\n";
  const std::string nc = post_cycles(text);
  CHECK(check_cycles(text, nc) == 11);
  // by hand: the left turn at (40, 0) rounded from (35, 0) to (40, 5) about (35, 5), counter-clockwise;
  // the chamfer at (40, 30) from 4 mm before it to 4 mm along (-30, 10) after it
  const double k = 4.0 / std::sqrt(1000.0);
  const Eigen::Vector3d reached[] = {{35, 0, -2}, {40, 5, -2}, {40, 26, -2}, {40 - 30 * k, 30 + 10 * k, -2}};
  const Eigen::Vector3d corners[] = {{40, 0, -2}, {40, 30, -2}, {10, 40, -2}};
  for (const Eigen::Vector3d& p : reached) CHECK(nc_reaches(nc, p));
  for (const Eigen::Vector3d& p : corners) CHECK_FALSE(nc_reaches(nc, p));
  CHECK_THAT(nc, Catch::Contains("G3") && Catch::Contains("F100.") && Catch::Contains("I0.0000 J5.0000"));
  CHECK_THAT(refusal(kHead + "3 L X+0 Y+0 Z+2 FMAX\n4 L X+5 F100\n5 RND R6\n6 L Y+20\n7 END PGM CYCLES MM\n"),
             Catch::Contains("cycles.h:6:") && Catch::Contains("RND 6: the rounding needs 6.0000 mm of each line"));
  CHECK_THAT(refusal(kHead + "3 L X+0 Y+0 Z+2 FMAX\n4 L X+5 F100\n5 CHF 1\n6 CC X+0 Y+0\n7 END PGM CYCLES MM\n"),
             Catch::Contains("cycles.h:7:") && Catch::Contains("'CC' after CHF (line 6)"));
}
