// SPDX-License-Identifier: Apache-2.0
// The corpus's real CYCLE800 program (tests/data/real/ncpb_Demo_1.mpf, NC-PB's 3+2 demo part for a DMG with
// a SINUMERIK 840D, issue 28) re-posted on the head-table-bc machine for Fanuc with a tool table. The program
// retracts with G53 (machine coordinates) and CYCLE800 _FR=1 before each swivel and then programs X and Y
// alone: on the control the tool stands where the machine position puts it, seen in the new plane. The INPUT
// is run by the tests' own small Sinumerik interpreter (sinumerik_mini.hpp with sinumerik_mini_swivel.hpp: G53
// from the machine file's reference data, _FR to its swivel_retract, the control's angles for each plane), the
// written OUTPUT by the tests' executor (nc_executor.hpp); at every input block end after the program's first
// position the tool tip agrees within 1 µm and the tool axis within the written angles' resolution, and for
// each CYCLE800 the output's B and C are the angles the tests compute for the plane (_MODE 27: Rz(_A) Ry(_B)
// Rx(_C), the _DIR=-1 branch), themselves checked by hand.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <memory>
#include <regex>
#include <sstream>

#include "nc_executor.hpp"
#include "sinumerik_mini.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/machine/serial_post_machine.hpp"
#include "ncpost/postproc/post_request.hpp"
#include "ncpost/postproc/read/tool_table.hpp"
#include "ncpost/postproc/write/dialect.hpp"
#include "test_paths.hpp"
#include "text_file.hpp"

using namespace ncpost;

namespace {

constexpr const char* kFile = "ncpb_Demo_1.mpf";

std::string machine_file() { return test::source("machines/head-table-bc.toml"); }

test::ExecJob demo_job() {
  test::ExecJob j;
  j.workpiece_origin_mm = test::V3(0, 0, -300);  // the corpus entry's origin
  j.tool_length_mm = 100;
  return j;
}

/// The program without its last block `N1570 HOME` (DMG's home-position cycle, whose target is the machine's
/// data: refused), kept as a comment so that the line numbers stay.
std::string demo_without_home() {
  std::string text = test::read_text_file(test::data(std::string("real/") + kFile));
  const std::size_t at = text.find("N1570 HOME");
  REQUIRE(at != std::string::npos);
  text.insert(at, ";");
  return text;
}

/// `text` posted for Fanuc on the machine `machine_text` with the job `job` (and the tool table `tools`, if any).
std::string post_on(const std::string& text, const std::string& name, const std::string& machine_text,
                    const test::ExecJob& job, const std::string& tools, const std::string& dialect = "fanuc") {
  PostRequest r;
  r.machine = serial_post_machine(parse_machine(machine_text, "machine.toml"));
  r.setup.workpiece_origin_mm = job.workpiece_origin_mm;
  r.setup.tool_length_mm = job.tool_length_mm;
  r.dialect = dialect_named(dialect);
  if (!tools.empty())
    r.tool_table = std::make_shared<const ToolTable>(parse_tool_table(test::read_text_file(tools), tools));
  r.threads = 1;
  r.input_name = name;
  std::ostringstream written;
  std::istringstream in(text);
  post(in, written, r);
  return written.str();
}

std::string post_demo(const std::string& text, const std::string& machine_text) {
  return post_on(text, kFile, machine_text, demo_job(), test::data("real/ncpb_tools.toml"));
}

/// The written angles have 4 decimals of a degree: the axis they give is within 1e-4 deg (1.7e-6).
constexpr double kAxisTolerance = 5e-6;

struct Plane {
  int line = 0;
  test::V3 normal;
  int dir = 0;
};

/// The CYCLE800 calls with a parameter list (axis by axis, without shifts): the line, the plane's Z, _DIR.
std::vector<Plane> planes_of(const std::string& text) {
  static const std::regex call(R"(CYCLE800\(([^)]*)\))");
  std::vector<Plane> out;
  std::istringstream in(text);
  int no = 0;
  for (std::string line; std::getline(in, line);) {
    ++no;
    std::smatch m;
    if (!std::regex_search(line, m, call) || m[1].str().empty()) continue;  // CYCLE800(): the reset
    std::vector<double> a;
    std::stringstream args(m[1].str());
    for (std::string s; std::getline(args, s, ',');) a.push_back(s.empty() || s[0] == '"' ? 0.0 : std::stod(s));
    REQUIRE(a.size() >= 14);
    REQUIRE(a[3] < 64.0);
    const int mode = static_cast<int>(a[3]);
    out.push_back({no, test::sin_axis_by_axis(mode, a[7], a[8], a[9]) * test::V3::UnitZ(), static_cast<int>(a[13])});
  }
  return out;
}

/// The input run by the tests' Sinumerik interpreter, the output by their executor: every input block end from
/// line `first_line` on reached by an output block end, in order (tip within 1 µm, tool axis within the written
/// angles); at the first end after each CYCLE800 the output's rotary words are the tests' angles for its plane.
/// The number of ends compared.
std::size_t ends_and_angles(const std::string& text, const std::string& nc, const std::string& machine_path,
                            const test::ExecJob& job, int first_line) {
  const test::ExecMachine m = test::ExecMachine::load(machine_path);
  const std::vector<test::SinumerikEnd> ends = test::sinumerik_block_ends(text, m, job);
  const test::Executor ex(machine_path, job, nc);
  const std::vector<Plane> planes = planes_of(text);
  std::map<char, double> angles_now;
  for (char c : m.rotary_letters) angles_now[c] = 0.0;
  std::size_t at = 0, plane = 0, compared = 0;
  for (const test::SinumerikEnd& e : ends) {
    if (e.line < first_line) continue;
    INFO("input line " << e.line << ": expected tip " << e.tip_W.transpose() << " axis " << e.axis_W.transpose());
    bool found = false;
    for (; at < ex.blocks.size() && !found; ++at) {
      const test::ExecPose p = ex.at(ex.blocks[at], 1.0);
      found = (p.tip_W - e.tip_W).norm() < 1e-3 && (p.axis_W - e.axis_W).norm() < kAxisTolerance;
    }
    REQUIRE(found);
    ++compared;
    if (plane < planes.size() && e.line > planes[plane].line) {  // the first end after a CYCLE800
      const auto want = test::sin_control_angles(m, job, planes[plane].normal, planes[plane].dir, angles_now);
      REQUIRE(want);
      const std::map<char, double>& got = ex.blocks[at - 1].to;
      for (char c : m.rotary_letters) {
        INFO("plane of line " << planes[plane].line << ": " << c << " written " << got.at(c) << ", the tests' "
                              << want->at(c));
        if (m.all_axes.at(c).limit_max)
          CHECK(got.at(c) == Approx(want->at(c)).margin(1e-4));
        else  // a continuous axis: the same angle, any turn
          CHECK(std::abs(std::remainder(got.at(c) - want->at(c), 360.0)) < 1e-4);
      }
      angles_now = *want;
      ++plane;
    }
  }
  CHECK(plane == planes.size());
  return compared;
}

}  // namespace

TEST_CASE("sinumerik CYCLE800 angles of the tests on head-table-bc: NC-PB Demo_1's planes, checked by hand") {
  // axis_W = Rz(-C) Ry(B) e_z = (sinB cosC, -sinB sinC, cosB); the plane Rz(_A) Ry(45) e_z has cosB = cos 45;
  // B is rotary axis 1 (the head's): _DIR=-1 takes B = -45, then C from the plane's X and Y
  const test::ExecMachine m = test::ExecMachine::load(machine_file());
  REQUIRE(test::sin_rotary_axis_1(m) == 'B');
  const std::vector<Plane> planes = planes_of(test::read_text_file(test::data(std::string("real/") + kFile)));
  REQUIRE(planes.size() == 5);
  const double want_c[5] = {0.0, 180.0, -90.0, 0.0, 90.0};  // the first plane is flat: C stays at 0
  const double want_b[5] = {0.0, -45.0, -45.0, -45.0, -45.0};
  std::map<char, double> now{{'B', 0.0}, {'C', 0.0}};
  for (std::size_t i = 0; i < planes.size(); ++i) {
    INFO("CYCLE800 at line " << planes[i].line);
    const auto got = test::sin_control_angles(m, demo_job(), planes[i].normal, planes[i].dir, now);
    REQUIRE(got);
    CHECK(got->at('B') == Approx(want_b[i]).margin(1e-9));
    CHECK(std::abs(std::remainder(got->at('C') - want_c[i], 360.0)) < 1e-9);
    now = *got;
  }
}

TEST_CASE("sinumerik real CYCLE800 (NC-PB Demo_1): re-posted, every block end and each plane's B and C the control's") {
  const std::string text = demo_without_home();
  const std::string nc = post_demo(text, test::read_text_file(machine_file()));
  INFO(nc.substr(0, 3000));
  CHECK(nc.find("T1 M6") != std::string::npos);  // the tool table's number for T="TEST_KOM"
  // the posted program starts at the program's first position (docs/formats.md, G-code input: G53 before it
  // moves nothing, and X Y Z not programmed before the first motion are taken from their first values): N110
  // X-34 Y89.9 (line 28) and N120 Z104 (line 29); every end from there on is compared
  CHECK(ends_and_angles(text, nc, machine_file(), demo_job(), 29) > 90);
}

TEST_CASE(
    "sinumerik real CYCLE800 (NC-PB Demo_1): re-posted for a Sinumerik, the tool by its name, every end reached") {
  // the sinumerik dialect keeps T="TEST_KOM" (no tool table) and writes machine axes: its program is run by the
  // same small Sinumerik interpreter as the input
  const std::string text = demo_without_home();
  const std::string out = post_on(text, kFile, test::read_text_file(machine_file()), demo_job(), "", "sinumerik");
  INFO(out.substr(0, 2000));
  CHECK(out.find("T=\"TEST_KOM\" M6") != std::string::npos);
  CHECK(out.find("CYCLE800") == std::string::npos);  // machine axes, not the plane again
  const test::ExecMachine m = test::ExecMachine::load(machine_file());
  const std::vector<test::SinumerikEnd> in = test::sinumerik_block_ends(text, m, demo_job());
  const std::vector<test::SinumerikEnd> written = test::sinumerik_block_ends(out, m, demo_job());
  std::size_t at = 0, compared = 0;
  for (const test::SinumerikEnd& e : in) {
    if (e.line < 29) continue;  // the start, as for Fanuc
    INFO("input line " << e.line << ": expected tip " << e.tip_W.transpose());
    bool found = false;
    for (; at < written.size() && !found; ++at)
      found = (written[at].tip_W - e.tip_W).norm() < 1e-3 && (written[at].axis_W - e.axis_W).norm() < kAxisTolerance;
    REQUIRE(found);
    ++compared;
  }
  CHECK(compared > 90);
}

TEST_CASE("sinumerik CYCLE800 after SUPA on a table-table machine: X Y alone move at the Z where the tool stands") {
  // tests/data/machines/ac-trunnion-references.toml: SUPA counts from X -400, Y 450, Z 550; _FR=0 (no retraction),
  // the plane Rx(30) with _DIR=+1 (A, rotary axis 1 of the table pair, on its plus side)
  const std::string text =
      "N10 G17 G90 G71 G94\n"
      "N20 T1 D1 M6\n"
      "N30 G0 X0 Y0 Z100 A0 C0 S3000 M3\n"
      "N40 SUPA G0 Z-420\n"
      "N50 SUPA X410 Y-455\n"
      "N60 CYCLE800(0,\"TC1\",200000,57,0,0,0,30,0,0,0,0,0,1)\n"
      "N70 G0 X10 Y5\n"
      "N80 G1 Z2 F300\n"
      "N90 X30\n"
      "N100 G0 Z60\n"
      "N110 CYCLE800()\n"
      "N120 SUPA G0 Z-420\n"
      "N130 CYCLE800(0,\"TC1\",200000,57,0,0,0,0,-20,0,0,0,0,1)\n"
      "N140 G0 X-10 Y-5\n"
      "N150 G1 Z-1 F300\n"
      "N160 G0 Z60\n"
      "N170 CYCLE800()\n"
      "N180 M30\n";
  const std::string machine_path = test::data("machines/ac-trunnion-references.toml");
  test::ExecJob job;
  job.workpiece_origin_mm = test::V3(10, -20, 50);
  job.tool_length_mm = 120;
  const std::string nc = post_on(text, "t.mpf", test::read_text_file(machine_path), job, "");
  INFO(nc);
  CHECK(ends_and_angles(text, nc, machine_path, job, 1) == 11);  // N30-N50, N70-N100, N120, N140-N160
  // without the SUPA blocks the Z at N70 is not known: refused there
  std::string unknown = text;
  unknown.replace(unknown.find("N40 SUPA G0 Z-420"), 17, "N40");
  unknown.replace(unknown.find("N50 SUPA X410 Y-455"), 19, "N50");
  unknown.replace(unknown.find("N30 G0 X0 Y0 Z100"), 17, "N30 G0 X0 Y0");
  try {
    post_on(unknown, "t.mpf", test::read_text_file(machine_path), job, "");
    FAIL("posted");
  } catch (const InputError& e) {
    CHECK_THAT(e.what(), Catch::StartsWith("t.mpf:7:") && Catch::Contains("Z is not known here"));
  }
}

TEST_CASE("sinumerik real CYCLE800 (NC-PB Demo_1): without swivel_retract, or with HOME, refused at the line") {
  // without [axes.Z] swivel_retract where _FR=1 leaves Z is the control's data: X Y alone after it is refused
  std::string machine = test::read_text_file(machine_file());
  const std::size_t key = machine.find("\nswivel_retract");
  REQUIRE(key != std::string::npos);
  machine.erase(key, machine.find('\n', key + 1) - key);
  REQUIRE(machine.find("\nswivel_retract") == std::string::npos);
  const auto refusal = [&](const std::string& text, const std::string& machine_text) -> std::string {
    try {
      post_demo(text, machine_text);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  CHECK_THAT(refusal(demo_without_home(), machine),
             Catch::StartsWith(std::string(kFile) + ":64:") && Catch::Contains("X is not known here"));
  // the whole file: DMG's HOME cycle (where it goes is the machine's data) is refused by name
  CHECK_THAT(
      refusal(test::read_text_file(test::data(std::string("real/") + kFile)), test::read_text_file(machine_file())),
      Catch::StartsWith(std::string(kFile) + ":186:") && Catch::Contains("HOME"));
}

TEST_CASE("machine file: swivel_retract on a linear axis, within its travel; elsewhere refused at its line") {
  const std::string head =
      "[machine]\nname = \"t\"\nchain = \"w C' b X Y Z B t\"\n"
      "[axes.X]\ntype = \"linear\"\n[axes.Y]\ntype = \"linear\"\n"
      "[axes.B]\ntype = \"rotary\"\ndirection = [0, 1, 0]\npivot = [0, 0, 180]\n"
      "[axes.C]\ntype = \"rotary\"\ndirection = [0, 0, 1]\npivot = [0, 0, 0]\n";
  const Machine m =
      parse_machine(head + "[axes.Z]\ntype = \"linear\"\nlimits = [-700, 500]\nswivel_retract = 480\n", "t");
  const Axis& z = m.axes[static_cast<std::size_t>(m.index_of('Z'))];
  REQUIRE(z.swivel_retract);
  CHECK(*z.swivel_retract == 480.0);
  CHECK_FALSE(m.axes[static_cast<std::size_t>(m.index_of('X'))].swivel_retract);
  const auto error_of = [&](const std::string& text) -> std::string {
    try {
      parse_machine(text, "t");
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  CHECK_THAT(error_of(head + "[axes.Z]\ntype = \"linear\"\nlimits = [-700, 500]\nswivel_retract = 520\n"),
             Catch::Contains("swivel_retract: 520 lies outside the axis's limits"));
  CHECK_THAT(error_of(head + "[axes.Z]\ntype = \"linear\"\nswivel_retract = \"top\"\n"),
             Catch::Contains("swivel_retract: expected a finite number"));
  std::string rotary = head + "[axes.Z]\ntype = \"linear\"\n";
  rotary.insert(rotary.find("pivot = [0, 0, 0]"), "swivel_retract = 5\n");
  CHECK_THAT(error_of(rotary), Catch::Contains("a rotary axis takes none"));
}

TEST_CASE("sinumerik CYCLE800 after G75: X Y alone move at the Z of the fixed point, not of the SUPA before it") {
  // tests/data/machines/ac-trunnion-references.toml: Z's fixed point 1 is 580 in M (SUPA Z-420 put it at 130); the
  // G75 block moves Z there, and the plane's first block programs X and Y only
  const std::string text =
      "N10 G17 G90 G71 G94\n"
      "N20 T1 D1 M6\n"
      "N30 G0 X0 Y0 Z100 A0 C0 S3000 M3\n"
      "N40 SUPA G0 Z-420\n"
      "N50 SUPA X410 Y-455\n"
      "N55 G75 Z0\n"
      "N60 CYCLE800(0,\"TC1\",200000,57,0,0,0,30,0,0,0,0,0,1)\n"
      "N70 G0 X10 Y5\n"
      "N80 G1 Z2 F300\n"
      "N90 X30\n"
      "N100 G0 Z60\n"
      "N110 CYCLE800()\n"
      "N180 M30\n";
  const std::string machine_path = test::data("machines/ac-trunnion-references.toml");
  test::ExecJob job;
  job.workpiece_origin_mm = test::V3(10, -20, 50);
  job.tool_length_mm = 120;
  const std::string nc = post_on(text, "t.mpf", test::read_text_file(machine_path), job, "");
  INFO(nc);
  CHECK(ends_and_angles(text, nc, machine_path, job, 1) == 8);  // N30-N55, N70-N100
  // N70 moves X and Y in the plane at the tool's Z: the output block that reaches its end is followed by the feed
  // of N80 and nothing between (ends_and_angles skips output blocks between ends: a Z from the SUPA before G75 was
  // written there, a rapid 450 mm down in M)
  const test::ExecMachine m = test::ExecMachine::load(machine_path);
  const std::vector<test::SinumerikEnd> ends = test::sinumerik_block_ends(text, m, job);
  const test::Executor ex(machine_path, job, nc);
  const auto output_block_of = [&](int input_line) {
    for (const test::SinumerikEnd& e : ends)
      if (e.line == input_line)
        for (std::size_t b = 0; b < ex.blocks.size(); ++b)
          if ((ex.at(ex.blocks[b], 1.0).tip_W - e.tip_W).norm() < 1e-3) return static_cast<long>(b);
    return -1L;
  };
  const long n70 = output_block_of(8), n80 = output_block_of(9);
  REQUIRE(n70 >= 0);
  CHECK(n80 == n70 + 1);
}

TEST_CASE(
    "sinumerik CYCLE800 after a tool change: where the tool change left the axes is not known, X Y alone refused") {
  // the SUPA blocks place the axes, then M6 moves them as the machine's tool change does (its data, not the
  // program's); CYCLE800 _FR=0 does not retract: the first block in the plane must give X, Y and Z
  const std::string text =
      "N10 G17 G90 G71 G94\n"
      "N20 T1 D1 M6\n"
      "N30 G0 X0 Y0 Z100 A0 C0 S3000 M3\n"
      "N40 SUPA G0 Z-420\n"
      "N50 SUPA X410 Y-455\n"
      "N55 T2 D1 M6\n"
      "N60 CYCLE800(0,\"TC1\",200000,57,0,0,0,30,0,0,0,0,0,1)\n"
      "N70 G0 X10 Y5\n"
      "N80 M30\n";
  test::ExecJob job;
  job.workpiece_origin_mm = test::V3(10, -20, 50);
  job.tool_length_mm = 120;
  try {
    post_on(text, "t.mpf", test::read_text_file(test::data("machines/ac-trunnion-references.toml")), job, "");
    FAIL("posted");
  } catch (const InputError& e) {
    CHECK_THAT(e.what(), Catch::StartsWith("t.mpf:8:") && Catch::Contains("is not known here"));
  }
}
