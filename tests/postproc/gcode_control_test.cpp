// SPDX-License-Identifier: Apache-2.0
// G-code input of issue 13 item 12 and issue 14 item 11: cutter compensation records, control
// mode words, Sinumerik units and keywords, G10 refusals, and the machine's axis limits.
#include <catch2/catch.hpp>

#include <sstream>

#include "shipped_machines.hpp"
#include "cl_records.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/kinematics/inverse.hpp"
#include "ncpost/postproc/read/gcode/gcode_cl_reader.hpp"

using namespace ncpost;
using namespace ncpost::gcode;
using ncpost::gcode::InputKind;  // (ncpost::InputKind is the CL input's kind)

namespace {

struct Read {
  std::vector<cl::Record> records;
  std::vector<std::string> notices;
};

Read read_all(const std::string& text, GcodeReaderOptions o = {}, Setup s = {}) {
  std::istringstream in(text);
  GcodeClReader r(in, "t.ngc", test::ac_trunnion(), s, o);
  Read out;
  while (auto x = r.next()) {
    out.records.push_back(std::move(*x));
    for (auto& n : r.take_notices()) out.notices.push_back(std::move(n));
  }
  for (auto& n : r.take_notices()) out.notices.push_back(std::move(n));
  return out;
}

using test::only;

InputError input_error(const std::string& text) {
  try {
    read_all(text);
  } catch (const InputError& e) {
    return e;
  }
  FAIL("no input error for: " << text);
  throw;
}

std::string infeasible(const std::string& text, InputKind kind, Setup s = {}) {
  GcodeReaderOptions o;
  o.kind = kind;
  try {
    read_all(text, o, s);
  } catch (const Infeasible& e) {
    return e.what();
  }
  FAIL("no Infeasible for: " << text);
  return {};
}

bool any_contains(const std::vector<std::string>& notices, const std::string& part) {
  for (const auto& n : notices)
    if (n.find(part) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST_CASE("gcode control: G41/G42 with D and G40 become CutterComp records before the block's motion") {
  const Read r = read_all("G21 G90 G0 X0 Y0 Z5\nG41 D7 G1 X10 F100\nG3 X20 Y10 I5 J5\nG42 G1 X30\nG40 G0 Z50\nM30\n");
  const auto comps = only<cl::CutterComp>(r.records);
  REQUIRE(comps.size() == 3);
  CHECK(comps[0].side == cl::CutterComp::Side::left);
  REQUIRE(comps[0].offset_register);
  CHECK(*comps[0].offset_register == 7);
  CHECK(comps[0].where.line == 2);
  CHECK(comps[0].where.column == 1);
  CHECK(comps[0].text == "G41 D7");
  CHECK(comps[1].side == cl::CutterComp::Side::right);
  CHECK_FALSE(comps[1].offset_register);  // no D: the control's current tool radius
  CHECK(comps[1].where.line == 4);
  CHECK(comps[2].side == cl::CutterComp::Side::off);
  CHECK(comps[2].where.line == 5);
  // the record precedes the motion of its block
  std::size_t comp_at = 0, motion_at = 0;
  for (std::size_t i = 0; i < r.records.size(); ++i) {
    if (const auto* c = std::get_if<cl::CutterComp>(&r.records[i]); c && c->where.line == 2) comp_at = i;
    if (const auto* m = std::get_if<cl::Motion>(&r.records[i]); m && m->where.line == 2 && !motion_at) motion_at = i;
  }
  CHECK(comp_at < motion_at);
  CHECK(input_error("G41 D-1 G1 X1 F1\n").where().column == 5);
  CHECK_THAT(input_error("G41.1 D6 G1 X1 F1\n").detail(), Catch::Contains("dynamic cutter radius compensation"));
}

TEST_CASE(
    "gcode control: the real LinuxCNC cutter-compensation sample reads its two G41 (lines 37, 77) and two G40 (lines "
    "11, 52)") {
  GcodeReaderOptions o;
  o.kind = InputKind::rtcp;
  Setup s;
  s.workpiece_origin_mm = Vec3d(-60, -50, -100);
  const Machine vmc = load_machine(NCPOST_SOURCE_DIR "/machines/vmcl600.toml");
  auto reader = open_gcode(NCPOST_SOURCE_DIR "/tests/data/real/linuxcnc_gmoccapy_2_tools_cutcom.ngc", vmc, s, o);
  std::vector<int> left_lines, off_lines;
  while (auto r = reader->next())
    if (const auto* c = std::get_if<cl::CutterComp>(&*r))
      (c->side == cl::CutterComp::Side::left ? left_lines : off_lines).push_back(c->where.line);
  CHECK(left_lines == std::vector<int>{37, 77});
  CHECK(off_lines == std::vector<int>{11, 52});
}

TEST_CASE("gcode control: look-ahead mode words are dropped with a notice, splines are still refused") {
  const Read r = read_all("G21 G90\nG05.1 Q1\nG0 X1 Y2 Z3\nG5.1 Q0\nG05 P10000\nG08 P1\nG1 X4 F100\nM30\n");
  const auto ms = only<cl::Motion>(r.records);
  REQUIRE(ms.size() == 2);
  CHECK(ms[1].point.tip_mm.x() == Approx(4.0));
  CHECK(only<cl::Unsupported>(r.records).empty());
  CHECK(any_contains(r.notices, "t.ngc:2:1: G05.1 Q1 (Fanuc AI contour control: look-ahead)"));
  CHECK(any_contains(r.notices, "t.ngc:5:1: G05 P10000"));
  CHECK(any_contains(r.notices, "t.ngc:6:1: G08 P1"));
  CHECK_THAT(input_error("G0 X0 Y0\nG5.1 X10 Y5 I2 J2\n").detail(), Catch::Contains("quadratic B-spline"));
  CHECK_THAT(input_error("G0 X0 Y0\nG5 X10 Y5 I2 J2 P1 Q1\n").detail(), Catch::Contains("cubic spline"));
}

// Safe-start lines cancel modes the reader refuses (G15 G50 G50.1 G69); Haas writes G187 P E and
// G103 P in every program: none of them moves anything (they were refused as scaling, rotation, E)
TEST_CASE("gcode control: cancel words and Haas smoothing words are read, G76 fine boring refused as such") {
  const Read r = read_all(
      "G21 G90\nG0 G17 G40 G49 G50 G69 G80 G15 G50.1\nG187 P1 E0.002\nG103 P1\nG0 X1 Y2 Z3\n"
      "G97 S1200 M3\nG1 X4 F100\nM30\n");
  const auto ms = only<cl::Motion>(r.records);
  REQUIRE(ms.size() == 2);
  CHECK(ms[1].point.tip_mm.isApprox(Vec3d(4, 2, 3)));
  CHECK(only<cl::Unsupported>(r.records).empty());
  CHECK(any_contains(r.notices, "t.ngc:3:1: G187 (Haas smoothness and corner rounding) is a control mode word"));
  CHECK(any_contains(r.notices, "t.ngc:4:1: G103 (Haas block look-ahead limit)"));
  CHECK_FALSE(any_contains(r.notices, "G50"));  // a cancel of what was never on says nothing
  // the modes themselves stay refused; an E word elsewhere too
  REQUIRE(only<cl::Spindle>(r.records).size() == 1);
  CHECK(only<cl::Spindle>(r.records)[0].rpm == 1200.0);
  CHECK_THAT(input_error("G21\nG96 S200 M3\n").detail(), Catch::Contains("G96 (constant surface speed"));
  CHECK_THAT(input_error("G21\nG51 X0 Y0 P2\n").detail(), Catch::Contains("G51 (scaling) is not supported"));
  CHECK_THAT(input_error("G21\nG68 X0 Y0 R30\n").detail(), Catch::Contains("G68 (coordinate rotation)"));
  CHECK_THAT(input_error("G21\nG0 X1 E2\n").detail(), Catch::Contains("E words are not supported"));
  CHECK_THAT(input_error("G21\nG50 X100 Z50\n").detail(), Catch::Contains("lathe's coordinate setting"));
  CHECK_THAT(input_error("G21 G0 X0 Y0 Z10 A0 C0\nG76 X5 Y5 Z-10 R2 Q0.1 F100\n").detail(),
             Catch::Contains("G76 (fine boring with a spindle orientation and shift on Fanuc and Haas mills"));
}

// A second work offset whose values are not known would put the next set-up's coordinates on the
// first part (gcode_work_offset_test.cpp posts them with their values)
TEST_CASE("gcode control: a second work offset without its values is refused, naming --work-offsets") {
  const std::string head = "G21 G90\nG54 G0 X0 Y0 Z10 A0 C0\nG1 Z-1 F100\n";
  const InputError e = input_error(head + "G0 Z10\nG55 G0 X20 Y0\nM30\n");
  CHECK(e.where().line == 5);
  CHECK(e.where().column == 1);
  CHECK_THAT(e.detail(), Catch::Contains("G55: a second work offset (the program moved in G54)"));
  CHECK_THAT(e.detail(), Catch::Contains("--work-offsets FILE"));
  CHECK_THAT(e.detail(), Catch::Contains("(selected at line 2)"));
  CHECK_THAT(input_error(head + "G54.1 P2 X1\nM30\n").detail(), Catch::Contains("G54.1 P2: a second work offset"));
  CHECK_THAT(input_error("G21 G90 G54.1 P1\nG0 X0 Y0 Z10 A0 C0\nG54.1 P2\nM30\n").detail(),
             Catch::Contains("G54.1 P2: a second work offset (the program moved in G54.1 P1)"));
  // the same offset again (each operation's safe-start line), or a choice before any motion: read
  CHECK(only<cl::Motion>(read_all(head + "G0 Z10\nG90 G54 G0 X20\nM30\n").records).size() == 4);
  CHECK(only<cl::Motion>(read_all("G21 G90 G54\nG91 G28 Z0\nG90 G55 G0 X0 Y0 Z10 A0 C0\nM30\n").records).size() >= 1);
  // moves before any offset word are in G54 (the power-on offset; a dialect's [input] power_on may
  // name another)
  CHECK(only<cl::Motion>(read_all("G21 G90\nG0 X0 Y0 Z10 A0 C0\nG54 X5\nM30\n").records).size() == 2);
  CHECK_THAT(input_error("G21 G90\nG0 X0 Y0 Z10 A0 C0\nG56 X5\nM30\n").detail(),
             Catch::Contains("G56: a second work offset (the program moved in G54)"));
}

// M60 (pallet change + stop) was a comment with a notice: the next pallet's cuts on this one
TEST_CASE("gcode control: M60 is refused naming the pallet change") {
  const InputError e = input_error("G21 G90\nG0 X0 Y0 Z10 A0 C0\nG0 Z50 M60\nM30\n");
  CHECK(e.where().line == 3);
  CHECK(e.where().column == 8);
  CHECK_THAT(e.detail(), Catch::Contains("M60 (pallet change and program stop) is not supported"));
}

TEST_CASE("gcode control: blocks with '/' are left out with a notice") {
  const Read r = read_all("G21 G90\nG0 X0 Y0 Z10 A0 C0\n/G1 Z-5 F100\n/M0\nG1 X5 F100\nM30\n");
  const auto ms = only<cl::Motion>(r.records);
  REQUIRE(ms.size() == 2);
  CHECK(ms[1].point.tip_mm.isApprox(Vec3d(5, 0, 10)));
  CHECK(any_contains(r.notices, "t.ngc:3: blocks that start with '/' (block delete) are left out"));
}

TEST_CASE("gcode control: Sinumerik G70/G71 set length units, G700/G710 lengths and feeds") {
  {
    const Read r = read_all("G70 G0 X1 Y2 Z0.5\nG1 X2 F100\nG71 X10\nM30\n");
    const auto ms = only<cl::Motion>(r.records);
    REQUIRE(ms.size() == 3);
    CHECK(ms[0].point.tip_mm.x() == Approx(25.4));
    CHECK(ms[0].point.tip_mm.z() == Approx(12.7));
    CHECK(ms[1].point.tip_mm.x() == Approx(50.8));
    REQUIRE(ms[1].feed);
    CHECK(*ms[1].feed == Approx(100.0));  // G70 leaves feeds in the basic unit (mm/min)
    CHECK(ms[2].point.tip_mm.x() == Approx(10.0));
    CHECK(any_contains(r.notices, "t.ngc:1:1: G70 (Sinumerik): lengths are read in inch"));
  }
  {
    const Read r = read_all("G700 G0 X1 Y0 Z0\nG1 X2 F10\nG710 X10 F100\nM30\n");
    const auto ms = only<cl::Motion>(r.records);
    REQUIRE(ms.size() == 3);
    CHECK(ms[1].point.tip_mm.x() == Approx(50.8));
    REQUIRE(ms[1].feed);
    CHECK(*ms[1].feed == Approx(254.0));
    CHECK(ms[2].point.tip_mm.x() == Approx(10.0));
    CHECK(*ms[2].feed == Approx(100.0));
  }
  CHECK_THAT(input_error("G21 G70 X1\n").detail(), Catch::Contains("both set the units"));
  CHECK_THAT(input_error("G71 P10 Q20\n").detail(), Catch::Contains("lathe roughing cycle"));
}

TEST_CASE("gcode control: Sinumerik keywords and G10 are refused naming what they are and what to do") {
  const InputError mcall = input_error("G0 X1 Y1 Z1\nMCALL CYCLE81(10,0,2,-5)\n");
  CHECK(mcall.where().line == 2);
  CHECK(mcall.where().column == 1);
  CHECK_THAT(mcall.detail(), Catch::Contains("MCALL (a Sinumerik modal subprogram call"));
  CHECK_THAT(input_error("  CYCLE83(1,2)\n").detail(), Catch::Contains("CYCLE83 (a Sinumerik cycle call)"));
  CHECK(input_error("  CYCLE83(1,2)\n").where().column == 3);
  CHECK_THAT(input_error("TRANS X10\n").detail(), Catch::Contains("programmable work offset"));
  const InputError g10 = input_error("G90 G21\nG0 X0 Y0 Z5\n\nG10 L1 P3 R5\n");
  CHECK(g10.where().line == 4);
  CHECK(g10.where().column == 1);
  CHECK_THAT(g10.detail(), Catch::Contains("tool table"));
  CHECK_THAT(input_error("G10 L3 P1\n").detail(), Catch::Contains("G10 (writing offsets or parameters"));
}

// Sinumerik MSG("...") is an operator message: a comment (it was "expected a number after 'M'")
TEST_CASE("gcode control: Sinumerik MSG(\"text\") is a comment; MSG() clears it") {
  const Read r = read_all("G71 G90\nMSG(\"ROUGHING T3\")\nG0 X1 Y2 Z3 msg ( \"second\" )\nMSG()\nM30\n");
  const auto comments = only<cl::Comment>(r.records);
  REQUIRE(comments.size() == 2);
  CHECK(comments[0].text == "ROUGHING T3");
  CHECK(comments[0].where.line == 2);
  CHECK(comments[0].where.column == 1);
  CHECK(comments[1].text == "second");
  REQUIRE(only<cl::Motion>(r.records).size() == 1);
  CHECK_THAT(input_error("G71\nMSG(\"open\"\n").detail(), Catch::Contains("expected"));
}

TEST_CASE("gcode control: the real CAMotics botomata program sets G54 and G55 with G10 L2 and moves in G55") {
  GcodeReaderOptions o;
  o.kind = InputKind::rtcp;
  Setup s;
  s.workpiece_origin_mm = Vec3d(-100, -40, -100);  // G10 L2 P2 Y-101.6 (line 1945) puts a second part at Y-101.6
  const Machine vmc = load_machine(NCPOST_SOURCE_DIR "/machines/vmcl600.toml");
  auto reader = open_gcode(NCPOST_SOURCE_DIR "/tests/data/real/camotics_botomata_bottom.nc", vmc, s, o);
  std::vector<cl::Record> records;
  while (auto r = reader->next()) records.push_back(*r);
  const std::vector<cl::Motion> ms = only<cl::Motion>(records);
  CHECK(ms.size() > 3000);
  // line 1952 goes to Y3.752 of G55 after line 1945 set G55 101.6 mm lower: Y-97.848 of the posted frame
  bool shifted = false;
  for (const cl::Motion& m : ms)
    if (m.where.line == 1952) shifted = std::abs(m.point.tip_mm.y() - (3.752 - 101.6)) < 1e-9;
  CHECK(shifted);
  // the posted frame is G55's, whose values (0, 0, 0) the program's G10 sets: the notice says so
  bool said = false;
  for (const std::string& n : reader->take_notices())
    said = said || n.find("frame of G55, whose values the input's G10 at line 10 sets") != std::string::npos;
  CHECK(said);
}

TEST_CASE("gcode control: motions beyond the machine's axis limits are Infeasible in every input kind") {
  const std::string program = "G21 G90\nG0 X0 Y0 Z10 A0 C0\nG1 X10 Z5000 A150 F100\nM30\n";
  for (InputKind kind : {InputKind::machine, InputKind::rtcp, InputKind::automatic}) {
    const std::string what = infeasible(program, kind);
    INFO(what);
    // the rotary axis first: the linear commands of an RTCP program follow from it
    CHECK(what ==
          "t.ngc:3:1: A 150.000 deg, beyond the A axis limit 120.000 deg (travel -120.000 .. 120.000 deg) of "
          "machine ac-trunnion: the program does not fit the machine; check the program's angles against the "
          "machine file");
  }
  CHECK(infeasible("G0 X0 Y0 Z10 A0 C0\nG1 X10 Z5000 F100\n", InputKind::machine) ==
        "t.ngc:2:1: Z 5000.000 mm, beyond the Z axis limit 600.000 mm (travel -600.000 .. 600.000 mm) of machine "
        "ac-trunnion: the program does not fit the machine; check --workpiece-origin, or the machine file");
  Setup s;
  s.workpiece_origin_mm = Vec3d(0, 0, 80);
  // RTCP: tip Z 5000 in W is machine Z 5080 at A0 C0 (W origin 80 mm above M's)
  CHECK_THAT(infeasible("G0 X0 Y0 Z10 A0 C0\nG1 X10 Z5000 F100\n", InputKind::rtcp, s),
             Catch::StartsWith("t.ngc:2:1: the programmed tool tip needs machine Z 5080.000 mm, beyond the Z axis "
                               "limit 600.000 mm"));
  CHECK_THAT(infeasible("G0 X0 Y0 Z10 A0 C0\nG1 X10 Z-700 F100\n", InputKind::machine),
             Catch::StartsWith("t.ngc:2:1: Z -700.000 mm, beyond the Z axis limit -600.000 mm"));
  // an arc whose middle leaves the travel: Y reaches 510 mm between end points within it
  CHECK_THAT(infeasible("G0 X-10 Y500 Z0 A0 C0\nG2 X10 Y500 I10 J0 F100\n", InputKind::machine),
             Catch::StartsWith("t.ngc:2:1: Y 50"));
  // within the limits (A exactly at 120, C continuous at 720): no error
  const Read ok = read_all("G0 X0 Y0 Z10 A0 C0\nG1 X10 Z600 A120 C720 F100\nM30\n");
  CHECK(only<cl::Motion>(ok.records).size() == 2);
}

namespace {

std::vector<cl::Record> read_vmc(const std::string& text) {
  static const Machine vmc = load_machine(NCPOST_SOURCE_DIR "/machines/vmcl600.toml");
  GcodeReaderOptions o;
  o.kind = InputKind::rtcp;  // tips in W as written
  std::istringstream in(text);
  GcodeClReader r(in, "t.ngc", vmc, Setup{}, o);
  std::vector<cl::Record> out = test::all_records(r);
  return out;
}

void check_tip(const cl::Motion& m, double x, double y, double z) {
  INFO("line " << m.where.line);
  CHECK(m.point.tip_mm.x() == Approx(x).margin(1e-12));
  CHECK(m.point.tip_mm.y() == Approx(y).margin(1e-12));
  CHECK(m.point.tip_mm.z() == Approx(z).margin(1e-12));
}

}  // namespace

TEST_CASE("gcode control: the program starts at its first programmed position, not with a rapid to 0") {
  {  // rapids only until every axis is programmed: they take the first values
    const auto rs = read_vmc("G21 G90\nG0 Z10\nT1 M6\nG0 Y100\nG0 X-25\nG1 Z0 F100\nM30\n");
    const auto ms = only<cl::Motion>(rs);
    REQUIRE(ms.size() == 4);
    check_tip(ms[0], -25, 100, 10);
    check_tip(ms[1], -25, 100, 10);
    check_tip(ms[2], -25, 100, 10);
    check_tip(ms[3], -25, 100, 0);
    CHECK(ms[0].where.line == 2);
    // the tool change keeps its place between the held rapids
    std::vector<int> order;
    for (const auto& r : rs) {
      if (const auto* m = std::get_if<cl::Motion>(&r)) order.push_back(m->where.line);
      if (std::holds_alternative<cl::ToolChange>(r)) order.push_back(-3);
    }
    CHECK(order == std::vector<int>{2, -3, 4, 5, 6});
  }
  {  // a feed motion comes first for Y (CAMotics cds.gcode): Y is 0 there, as at a control's program zero
    const auto ms = only<cl::Motion>(read_vmc("G21\nF400\nG0 Z3\nG0 X-26.9938\nG1 Z-1.5\nG1 X0 Y-26.9938\nM30\n"));
    REQUIRE(ms.size() == 4);
    check_tip(ms[0], -26.9938, 0, 3);
    check_tip(ms[1], -26.9938, 0, 3);
    check_tip(ms[2], -26.9938, 0, -1.5);
    check_tip(ms[3], 0, -26.9938, -1.5);
  }
  {  // the feed motion that programs X and Y first starts from 0 in them
    const auto ms = only<cl::Motion>(read_vmc("G0 Z10\nG1 X5 Y5 F100\nM30\n"));
    REQUIRE(ms.size() == 2);
    check_tip(ms[0], 0, 0, 10);
    check_tip(ms[1], 5, 5, 10);
  }
  {  // the end before the other axes: 0
    const auto ms = only<cl::Motion>(read_vmc("G0 Z10\nM30\n"));
    REQUIRE(ms.size() == 1);
    check_tip(ms[0], 0, 0, 10);
  }
  {  // rotary axes the program never writes: 0 on the five-axis machine, from the first feed motion on
    const Read r = read_all("G0 Z10\nG0 X1 Y2\nG1 X3 F100\nM30\n");
    const auto ms = only<cl::Motion>(r.records);
    REQUIRE(ms.size() == 3);
    for (const auto& m : ms) {
      REQUIRE(m.rotary_rad);
      CHECK(m.rotary_rad->norm() == 0.0);
    }
    CHECK(any_contains(r.notices, "t.ngc:1:4: X, Y, A, C not programmed before the first motion"));
  }
}

TEST_CASE("gcode control: a rollover C turns the short way across 0, and G93 blocks keep the source's time") {
  const Read r = read_all("G21 G90\nG0 X0 Y0 Z50 A0 C350\nG93 G1 C10 F60\nG1 C359.857 F60\nG1 C7.501 F30\nM30\n");
  const auto ms = only<cl::Motion>(r.records);
  REQUIRE(ms.size() == 4);
  const double expected_c_deg[] = {350.0, 370.0, 359.857, 367.501};
  for (std::size_t i = 0; i < 4; ++i) {
    REQUIRE(ms[i].rotary_rad);
    CHECK((*ms[i].rotary_rad)[1] * 180.0 / kPi == Approx(expected_c_deg[i]).margin(1e-9));
  }
  // feed = rotary travel (deg) x F (1/min): the post's time max(length, travel) / feed is 1/F
  const auto feeds = only<cl::Feed>(r.records);
  REQUIRE(feeds.size() == 3);
  CHECK(feeds[0].value == Approx(20.0 * 60));
  CHECK(feeds[1].value == Approx(10.143 * 60));
  CHECK(feeds[2].value == Approx(7.644 * 30));
  CHECK(feeds[2].where.line == 5);
  CHECK(any_contains(r.notices, "t.ngc:3: C 350.000 -> 10.000 deg read the short way (+20.000 deg"));
  // a program that counts turns (a value outside 0 .. 360) is followed as written
  const auto counted = only<cl::Motion>(read_all("G0 X0 Y0 Z50 A0 C-10\nG1 C350 F100\nG1 C10\nM30\n").records);
  REQUIRE(counted.size() == 3);
  CHECK((*counted[1].rotary_rad)[1] * 180.0 / kPi == Approx(350.0));
  CHECK((*counted[2].rotary_rad)[1] * 180.0 / kPi == Approx(10.0));
  // A has limits: never unwrapped (a jump beyond them is the limits' business)
  const auto a_axis = only<cl::Motion>(read_all("G0 X0 Y0 Z50 A100 C0\nG1 A-100 F100\nM30\n").records);
  CHECK((*a_axis[1].rotary_rad)[0] * 180.0 / kPi == Approx(-100.0));
}

// A program without G20/G21 runs in the control's default units: read as mm unless it speaks
// inches (it was posted as mm with at most a notice: a part 25.4 times too small, exit 0)
TEST_CASE("gcode control: a program without G20/G21 that looks or speaks inch is refused unless --units says") {
  const std::string square =
      "G90\nG0 X0.1250 Y0.2500 Z1.0000\nG1 Z-0.1000 F10.\nX1.2500\nY0.7500\nX0.1250\nY0.2500\nM30\n";
  const InputError e = input_error(square);
  CHECK_THAT(e.what(),
             Catch::Contains("t.ngc:1: the program has no G20/G21 (units) and looks like inches (8 of 8 X/Y/Z "
                             "words with 4 decimals, all positions within 1.125 x 0.5 x 1.1)") &&
                 Catch::Contains("post with --units inch or --units mm"));
  CHECK(only<cl::Motion>(read_all("G21\n" + square).records)[1].point.tip_mm.z() == Approx(-0.1));
  CHECK(only<cl::Motion>(read_all("G20\n" + square).records)[1].point.tip_mm.z() == Approx(-2.54));
  GcodeReaderOptions inch;
  inch.default_inch = inch.units_given = true;
  CHECK(only<cl::Motion>(read_all(square, inch).records)[1].point.tip_mm.z() == Approx(-2.54));
  GcodeReaderOptions mm;
  mm.units_given = true;  // --units mm: the user's word
  CHECK(only<cl::Motion>(read_all(square, mm).records)[1].point.tip_mm.z() == Approx(-0.1));
  // mm-sized positions, or 3-decimal words: read as mm
  CHECK(only<cl::Motion>(read_all("G0 X10.1250 Y80.2500 Z1.0000\nG1 Z-0.1000 F10.\nX1.2500\nY0.7500\nX0.1250\n"
                                  "Y0.2500\nM30\n")
                             .records)
            .size() == 6);
  CHECK(only<cl::Motion>(read_all("G0 X0.125 Y0.25 Z1.0\nG1 Z-0.1 F10.\nX1.25\nY0.75\nX0.125\nY0.25\nM30\n").records)
            .size() == 6);
  // comments that speak inches and never millimetres (a Haas program written by hand)
  const std::string haas =
      "%\nO01000\n(TOOL 1 = .500IN ENDMILL)\nT1 M6\nG90 G54 G0 X1. Y-.5\nS2000 M3\nG43 H1 Z1.\n"
      "G1 Z-.75 F16.\nX3.\nG0 Z1.\nM30\n%\n";
  const InputError h = input_error(haas);
  CHECK(h.where().line == 3);
  CHECK_THAT(h.what(), Catch::Contains("its comments speak inches ('.500IN' at line 3"));
  for (const char* c : {"(1/4-20 UNC TAP)", "(FEED 16 IPM)", "(0.5 INCH DRILL)", "(1/2\" ENDMILL)"})
    CHECK_THAT(input_error(std::string(c) + "\nG0 X1. Y1. Z1.\nM30\n").what(), Catch::Contains("speak inches"));
  // a millimetre named anywhere, or English words only: read as mm
  for (const char* c : {"(D10MM ENDMILL, 0.5 IN STEP)", "(TOOL IN SPINDLE)", "(6 MM DRILL)", "(INSIDE CONTOUR)"}) {
    CAPTURE(c);
    CHECK(only<cl::Motion>(read_all(std::string(c) + "\nG0 X1. Y1. Z1.\nM30\n").records).size() == 1);
  }
}

TEST_CASE("gcode control: with `circles`, a single-turn arc (planar or helical) is a Circle and its end motion") {
  GcodeReaderOptions o;
  o.circles = true;
  o.kind = InputKind::rtcp;
  Setup s;
  s.workpiece_origin_mm = Vec3d(0, 0, 80);
  const Read r = read_all(
      "G21 G90 G17\nG0 X0 Y0 Z10 A0 C0\nG1 Z0 F100\nG2 I-45\nG3 X20 Y20 I10 J10\n"
      "G3 X0 Y0 Z-1 I-10 J-10\nM30\n",
      o, s);
  const auto circles = only<cl::Circle>(r.records);
  REQUIRE(circles.size() == 3);  // the helix too: its centre at the start's height, the end motion gives Z
  CHECK(circles[0].where.line == 4);
  CHECK((circles[0].center_mm - Vec3d(-45, 0, 0)).norm() < 1e-12);
  CHECK((circles[0].axis - Vec3d(0, 0, -1)).norm() < 1e-12);  // G2: counter-clockwise about -Z
  CHECK(circles[0].radius_mm == Approx(45.0));
  CHECK((circles[1].center_mm - Vec3d(10, 10, 0)).norm() < 1e-12);
  CHECK((circles[1].axis - Vec3d(0, 0, 1)).norm() < 1e-12);
  CHECK(circles[1].radius_mm == Approx(std::sqrt(200.0)));
  CHECK(circles[2].where.line == 6);
  CHECK((circles[2].center_mm - Vec3d(10, 10, 0)).norm() < 1e-12);
  CHECK((circles[2].axis - Vec3d(0, 0, 1)).norm() < 1e-12);
  const auto ms = only<cl::Motion>(r.records);
  REQUIRE(ms.size() == 5);
  CHECK((ms[4].point.tip_mm - Vec3d(0, 0, -1)).norm() < 1e-12);  // the helix ends 1 mm lower
  CHECK(ms[2].where.line == 4);                                  // the full circle's end motion, back at the start
  CHECK(ms[2].point.tip_mm.norm() < 1e-12);
  CHECK((ms[3].point.tip_mm - Vec3d(20, 20, 0)).norm() < 1e-12);
  // without the option (the default) every arc is points
  CHECK(only<cl::Circle>(read_all("G0 X0 Y0 Z10 A0 C0\nG1 Z0 F100\nG2 I-45\nM30\n").records).empty());
}

// G28/G30 and G53 move the machine in its own coordinates: a program that retracts with them and
// then moves on must be posted with the retract, never with the tool left at depth.
TEST_CASE("G-code: G28 Z mid-program retracts Z to the top of its travel, and the next moves stay there") {
  const Read r = read_all("G21 G90\nG0 X10 Y10 Z5\nG1 Z-2 F100\nX20\nG91 G28 Z0\nG90 G0 X50 Y50\nG1 Z-2\nM30\n");
  const auto m = only<cl::Motion>(r.records);
  REQUIRE(m.size() == 6);  // the intermediate point of G91 G28 Z0 is where the tool stands: no move
  CHECK(m[3].point.tip_mm.isApprox(Vec3d(20, 10, 600)));  // ac-trunnion: Z -600 .. 600 mm
  CHECK(m[3].rapid);
  CHECK(m[4].point.tip_mm.isApprox(Vec3d(50, 50, 600)));  // X Y move at the top, not at Z-2
  CHECK(m[4].rapid);
  CHECK(m[5].point.tip_mm.isApprox(Vec3d(50, 50, -2)));
  CHECK(any_contains(r.notices, "t.ngc:5:5: G28: Z goes to 600.000 mm, at the top of its travel"));
}

TEST_CASE("G-code: G90 G28 Z50 goes through the intermediate point first") {
  // (G30 goes to the machine file's reference2: gcode_reference_test.cpp; ac-trunnion has none)
  for (const char* code : {"G28"}) {
    INFO(code);
    const Read r = read_all(std::string("G21 G90\nG0 X10 Y10 Z5\nG1 Z-2 F100\n") + code + " Z50\nG0 X0 Y0\nM30\n");
    const auto m = only<cl::Motion>(r.records);
    REQUIRE(m.size() == 5);
    CHECK(m[2].point.tip_mm.isApprox(Vec3d(10, 10, 50)));
    CHECK(m[3].point.tip_mm.isApprox(Vec3d(10, 10, 600)));
    CHECK(m[4].point.tip_mm.isApprox(Vec3d(0, 0, 600)));
  }
}

TEST_CASE("G-code: G53 moves to machine coordinates, not to program coordinates") {
  // machine coordinates count from the reference point, Z's the top of its travel (600 mm):
  // tool-tip reading with A turned: machine Z alone goes to 590, the tip moves along machine Z
  GcodeReaderOptions o;
  o.kind = InputKind::rtcp;
  Setup s;
  s.workpiece_origin_mm = Vec3d(0, 0, 80);
  const Read r = read_all("G21 G90\nG0 X10 Y10 Z5 A30 C0\nG53 G0 Z-10\nG0 X0\nM30\n", o, s);
  const auto m = only<cl::Motion>(r.records);
  REQUIRE(m.size() == 3);
  const Eigen::Vector2d rotary(deg_to_rad(30.0), 0.0);
  const Vec3d before = linear_for(test::ac_trunnion(), rotary, m[0].point.tip_mm, s);
  const Vec3d after = linear_for(test::ac_trunnion(), rotary, m[1].point.tip_mm, s);
  CHECK(after.isApprox(Vec3d(before.x(), before.y(), 590.0)));
  CHECK(m[1].rapid);
  // the next move programs X only: Y and Z keep the program coordinates the G53 move reached
  CHECK(m[2].point.tip_mm.y() == Approx(m[1].point.tip_mm.y()));
  CHECK(m[2].point.tip_mm.z() == Approx(m[1].point.tip_mm.z()));
  CHECK(m[2].point.tip_mm.x() == Approx(0.0).margin(1e-12));
  // machine reading: the machine coordinate is the program coordinate of that axis
  const auto m2 = only<cl::Motion>(read_all("G21 G90\nG0 X10 Y10 Z5 A0 C0\nG53 G0 Z-10\nM30\n").records);
  REQUIRE(m2.size() == 2);
  CHECK(m2[1].point.tip_mm.isApprox(Vec3d(10, 10, 590)));
  CHECK(any_contains(read_all("G21 G90\nG0 X10 Y10 Z5 A0 C0\nG53 G0 Z-10\nM30\n").notices,
                     "G53: Z goes to 590.000 mm, -10.000 mm from the top of its travel"));
  // G53 X: counted from a reference the machine file does not give: the next motion must program X
  CHECK_THAT(input_error("G21 G90\nG0 X10 Y10 Z5 A0 C0\nG53 G0 X-100\nG0 Z20\nM30\n").what(),
             Catch::Contains("X stands at its reference point since line 3"));
}

TEST_CASE("G-code: after G28 X Y the next motion must program X and Y; before the start nothing moves") {
  const InputError e = input_error("G21 G90\nG0 X10 Y10 Z5 A0 C0\nG91 G28 X0 Y0\nG90 G0 Z20\nM30\n");
  CHECK(e.where().line == 4);
  CHECK_THAT(e.what(), Catch::Contains("X stands at its reference point since line 3"));
  // programmed absolutely: posted
  CHECK(only<cl::Motion>(read_all("G21 G90\nG0 X10 Y10 Z5 A0 C0\nG91 G28 X0 Y0\nG90 G0 X1 Y2 Z20\nM30\n").records)
            .size() == 2);
  // G53 Z0 and G28 before any programmed position: the first programmed values place the tool
  const Read r = read_all("G21 G90\nG53 G0 Z0\nG91 G28 Z0\nG90 G0 X10 Y10 Z5\nM30\n");
  const auto m = only<cl::Motion>(r.records);
  REQUIRE(m.size() >= 1);
  CHECK(m.back().point.tip_mm.isApprox(Vec3d(10, 10, 5)));
  for (const auto& x : m) CHECK(x.point.tip_mm.z() == Approx(5.0));  // never to Z0, the program's surface
  CHECK(any_contains(r.notices, "G53 before the first programmed position moves nothing"));
}

// G4: Fanuc's `G04 X1.5` is a dwell of 1.5 s, not a move of X (it was posted as a cut to X1.5).
// A time without a decimal point is ms on Fanuc and Haas, s on LinuxCNC: guessed only where the
// other reading is absurd (P2000 as seconds: 33 min), else refused unless the user says which.
TEST_CASE("G-code: G4 dwells in X or P; a time without a decimal point is ms, s, or refused") {
  const Read r =
      read_all("G21 G90\nG0 X10 Y10 Z5 A0 C0\nG1 Z-2 F100\nG04 X1.5\nG4 P0.5\nG4 P2000\nG4 P0\nG1 Z5\nM30\n");
  const auto m = only<cl::Motion>(r.records);
  REQUIRE(m.size() == 3);
  CHECK(m[1].point.tip_mm.isApprox(Vec3d(10, 10, -2)));
  CHECK(m[2].point.tip_mm.isApprox(Vec3d(10, 10, 5)));  // X stayed at 10
  const auto d = only<cl::Dwell>(r.records);
  REQUIRE(d.size() == 4);
  CHECK(d[0].seconds == 1.5);
  CHECK(d[0].where.line == 4);
  CHECK(d[1].seconds == 0.5);
  CHECK(d[2].seconds == 2.0);
  CHECK(d[2].where.line == 6);
  CHECK(d[3].seconds == 0.0);
  CHECK(only<cl::Unsupported>(r.records).empty());
  CHECK(any_contains(r.notices, "t.ngc:6:4: G4 P2000 (no decimal point) is read as 2000 ms"));
  // 1 to 99 without a decimal point: 5 ms or 5 s are both plausible, so the user says which
  const std::string ambiguous = "G21 G90\nG0 X10 Y10 Z5 A0 C0\nG4 P5\nG04 X20\nM30\n";
  const InputError refused = input_error(ambiguous);
  CHECK(refused.where().line == 3);
  CHECK(refused.where().column == 4);
  CHECK_THAT(refused.what(),
             Catch::Contains("G4 P5 (no decimal point) is 5 ms on Fanuc and Haas but 5 s on LinuxCNC") &&
                 Catch::Contains("--dwell-p ms or --dwell-p s"));
  GcodeReaderOptions ms;
  ms.integer_dwell = IntegerDwell::milliseconds;
  const auto in_ms = only<cl::Dwell>(read_all(ambiguous, ms).records);
  REQUIRE(in_ms.size() == 2);
  CHECK(in_ms[0].seconds == Approx(0.005));
  CHECK(in_ms[1].seconds == Approx(0.020));  // Fanuc: X without a decimal point counts ms too
  GcodeReaderOptions s;
  s.integer_dwell = IntegerDwell::seconds;
  const auto in_s = only<cl::Dwell>(read_all(ambiguous, s).records);
  REQUIRE(in_s.size() == 2);
  CHECK(in_s[0].seconds == 5.0);
  CHECK(in_s[1].seconds == 20.0);
  CHECK(only<cl::Dwell>(read_all("G21 G90\nG4 P2.5\nM30\n", ms).records).at(0).seconds == 2.5);  // a point: seconds
  // a dwell moves nothing: axis words other than its X time are refused
  const InputError e = input_error("G21 G90\nG0 X1 Y1 Z1 A0 C0\nG4 X1 Y2\nM30\n");
  CHECK(e.where().line == 3);
  CHECK_THAT(e.what(), Catch::Contains("Y in a G4 (dwell) block"));
  CHECK_THAT(input_error("G21 G90\nG4 P-1\nM30\n").what(), Catch::Contains("expected a dwell time from 0"));
}

// The P of G82/G89 is the same dwell time as G4's: P500 on a Fanuc drilling cycle is 0.5 s (it
// was read as 500 s and written back as P500000)
TEST_CASE("G-code: the dwell P of G82 and G89 is read by the G4 rule") {
  const std::string head = "G21 G90 G94\nG0 X10 Y10 Z20 A0 C0\nS1000 M3\n";
  const auto c =
      only<cl::Cycle>(read_all(head + "G99 G82 X10 Y10 Z-5 R2 P500 F100\nX20 P1.5\nX30\nG80\nM30\n").records);
  REQUIRE(c.size() == 4);
  CHECK(c[3].kind == cl::Cycle::Kind::off);  // G80
  CHECK(c[0].dwell_s == Approx(0.5));
  CHECK(c[1].dwell_s == Approx(1.5));
  CHECK(c[2].dwell_s == Approx(1.5));  // modal within the cycle
  const InputError e = input_error(head + "G98 G89 X10 Y10 Z-5 R2 P2 F100\nG80\nM30\n");
  CHECK(e.where().line == 4);
  CHECK_THAT(e.what(), Catch::Contains("G89 P2 (no decimal point) is 2 ms on Fanuc and Haas but 2 s on LinuxCNC"));
}

// NX's Mazak Nexus 4-axis sample: no G20/G21, X Y Z words 100 mm, 25 mm, 90 mm ... divided by
// 25.4 (Y3.937 Z.9843 Y3.5433): a metric design posted in inches, read as mm 25.4 times too small
// with exit 0. Refused unless --units says; a millimetre program with 3-4 decimals is not.
TEST_CASE("gcode control: a metric design written in inches without G20/G21 is refused unless --units says") {
  const std::string strips =
      "G90 G0 X0.0 Y3.937 Z1.9685\nG1 Z.9843 F9.8\nY3.5433\nY3.1496\nY2.7559\nY2.3622\nY1.9685\nG0 Z1.9685\nM30\n";
  const InputError e = input_error(strips);
  CHECK_THAT(e.what(),
             Catch::Contains("t.ngc:1: the program has no G20/G21 (units) and its positions look like a metric "
                             "design written in inches (9 of its 9 X/Y/Z words with 3 or 4 decimals are whole "
                             "half-millimetres divided by 25.4, e.g. Y3.937 at line 1 = 100.000 mm)") &&
                 Catch::Contains("post with --units inch or --units mm"));
  GcodeReaderOptions inch;
  inch.default_inch = inch.units_given = true;
  const auto ms = only<cl::Motion>(read_all(strips, inch).records);
  REQUIRE(ms.size() == 8);
  CHECK(ms[0].point.tip_mm.y() == Approx(100.0).margin(0.001));  // 3.937 in
  CHECK(ms[1].point.tip_mm.z() == Approx(25.0).margin(0.002));   // .9843 in
  // millimetres with 3 decimals that are no such fractions: read as mm, no refusal
  const auto mm = only<cl::Motion>(
      read_all("G90 G0 X0.0 Y12.345 Z5.0\nG1 Z-1.234 F300\nY17.891\nY23.456\nY31.017\nY40.123\nG0 Z5.0\nM30\n")
          .records);
  REQUIRE(mm.size() == 7);
  CHECK(mm[2].point.tip_mm.y() == Approx(17.891));
}

// NX's Mazak sample again: after G91 G28 Z0, 'X0.0 Y0.0' (still G91: no move) is the first rapid
// and Z comes first in the G1 that follows. The held rapid was taken to Z0 (the work offset's
// zero: a rapid onto the part's face) with exit 0. Refused now; a program that never programs Z
// (a plasma cutter's) stays at Z0 as before.
TEST_CASE("gcode control: a rapid before Z is known, released by a cut that programs Z, is refused") {
  const InputError e = input_error("G21 G90 G0 X10 Y10\nG1 X20 Y10 Z-1 F100\nM30\n");
  CHECK_THAT(e.what(),
             Catch::Contains("t.ngc:1:") &&
                 Catch::Contains("this rapid does not say where Z goes, and Z is first programmed by the "
                                 "cutting motion at line 2: taken as Z0 it would run to the work offset's zero"));
  const auto plasma = only<cl::Motion>(read_vmc("G21 G90\nG0 X10 Y10\nG1 X20 F500\nY20\nM30\n"));
  REQUIRE(plasma.size() == 3);
  check_tip(plasma[0], 10, 10, 0);
  const auto z_first = only<cl::Motion>(read_vmc("G21 G90\nG0 Z5\nG0 X10 Y10\nG1 Z-1 F100\nM30\n"));
  REQUIRE(z_first.size() == 3);
  check_tip(z_first[1], 10, 10, 5);
}

// nxpost_Micron_WF21D (Heidenhain ISO): `N0070 G90 Z-25. M91` moves Z in machine coordinates; read
// as W it would put the tool 25 mm below the part's zero
TEST_CASE("gcode control: M91/M92 beside axis words are refused (Heidenhain machine coordinates)") {
  const InputError m91 = input_error("G21 G90\nG0 X0 Y0 Z10 A0 C0\nG0 Z-25. M91\nM30\n");
  CHECK(m91.where().line == 3);
  CHECK(m91.where().column == 10);
  CHECK(m91.detail() ==
        "M91 with axis words: on Heidenhain controls the block's coordinates are then machine coordinates (M91: from "
        "the machine datum, M92: from a machine-defined position), which the reader does not place, and elsewhere "
        "M91/M92 are the machine builder's; post the CL data, or move in machine coordinates with G53");
  CHECK_THAT(input_error("G21 G90\nG0 X0 Y0 Z10 A0 C0\nM92 G0 X5\nM30\n").detail(), Catch::StartsWith("M92 with axis"));
  // alone it moves nothing: passed through as other M codes are
  const Read alone = read_all("G21 G90\nG0 X0 Y0 Z10 A0 C0\nM91\nG0 X5\nM30\n");
  CHECK(only<cl::Motion>(alone.records).size() == 2);
  CHECK(any_contains(alone.notices, "M91 is not acted on; passed through as a comment"));
}

TEST_CASE("gcode control: axis words before any motion mode stay refused, saying why") {
  const InputError e = input_error("G21 G90\nG43 Z100. H1\nG0 X0 Y0 A0 C0\nM30\n");
  CHECK(e.where().line == 2);
  CHECK(e.where().column == 5);
  CHECK(e.detail() ==
        "axis words without a motion mode (expected G0, G1, G2 or G3): the control's power-on mode (G0 "
        "or G1, a machine parameter on Fanuc) is not in the program; write G0 or G1 in the block, or post "
        "with a dialect whose [input] power_on names it (fanuc, haas: G0)");
}
