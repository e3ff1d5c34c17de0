// SPDX-License-Identifier: Apache-2.0
// Program stops, dwells and machine functions that were passed through as comments (the machine no
// longer stopped, coolant stayed off, a surface speed became rpm): G-code M0/M1 and APT STOP,
// OPSTOP, AUXFUN/0 and /1 are cl::Stop records written as the dialect's [program] stop /
// optional_stop; APT DELAY is a dwell; SPINDL/v,SMM|SFM is turned into rpm with the CUTTER
// diameter; AUXFUN/3 4 5 7 8 9 are spindle and coolant records, every other AUXFUN and PREFUN is
// refused. After a stop the spindle and coolant that were on start again before the next motion
// (Heidenhain's M0 stops both). Expected programs reviewed by hand.
#include <catch2/catch.hpp>

#include "nc_executor.hpp"

#include <sstream>

#include "shipped_machines.hpp"
#include "cl_records.hpp"
#include "cli_run.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/read/apt/apt_reader.hpp"
#include "ncpost/postproc/write/dialect.hpp"
#include "ncpost/postproc/read/gcode/gcode_cl_reader.hpp"
#include "ncpost/postproc/machine/serial_post_machine.hpp"
#include "ncpost/postproc/post_request.hpp"
#include "temp_dir.hpp"
#include "test_paths.hpp"
#include "text_edit.hpp"

using namespace ncpost;
using test::only;

namespace {

std::vector<cl::Record> gcode_records(const std::string& text) {
  std::istringstream in(text);
  gcode::GcodeClReader r(in, "t.ngc", test::ac_trunnion(), Setup{}, gcode::GcodeReaderOptions{});
  return test::all_records(r);
}

struct AptRead {
  std::vector<cl::Record> records;
  std::vector<std::string> notices;
};

AptRead apt_records(const std::string& text) {
  std::istringstream in(text);
  cl::AptReader r(in, "t.cls");
  AptRead out;
  out.records = test::all_records(r);
  out.notices = r.take_notices();
  return out;
}

/// The message of the InputError that reading `text` (APT) throws.
std::string apt_error(const std::string& text) {
  try {
    apt_records(text);
  } catch (const InputError& e) {
    return e.what();
  }
  FAIL("no input error for: " << text);
  return {};
}

/// Index of the first record of `line` that holds a T (or records.size()).
template <class T>
std::size_t index_of(const std::vector<cl::Record>& records, int line) {
  for (std::size_t i = 0; i < records.size(); ++i)
    if (const T* x = std::get_if<T>(&records[i]); x && x->where.line == line) return i;
  return records.size();
}

PostRequest request(const std::string& dialect) {
  PostRequest r;
  r.machine = serial_post_machine(test::ac_trunnion());
  r.machine_source = "machines/ac-trunnion.toml";
  r.setup.workpiece_origin_mm = Vec3d(0, 0, 80);
  r.dialect = dialect_named(dialect);
  r.threads = 1;
  r.input_name = "stops.cls";
  return r;
}

std::string post_text(const std::string& input, const PostRequest& r, PostResult* result = nullptr) {
  std::istringstream in(input);
  std::ostringstream out;
  const PostResult res = post(in, out, r);
  if (result) *result = res;
  return out.str();
}

/// `program` from the first line that starts with `first` on (the header names paths and versions).
std::string from_line(const std::string& program, const std::string& first) {
  const std::size_t at = program.find("\n" + first);
  REQUIRE(at != std::string::npos);
  return program.substr(at + 1);
}

bool any_contains(const std::vector<std::string>& list, const std::string& what) {
  for (const auto& s : list)
    if (s.find(what) != std::string::npos) return true;
  return false;
}

// Every stop, dwell and machine function of the brief in one APT program: surface speed with a
// CUTTER, DELAY in seconds and revolutions, OPSTOP, STOP with an operator message (CATIA), AUXFUN.
const std::string kStops =
    "PARTNO/STOPS\n"
    "UNITS/MM\n"
    "CUTTER/10\n"
    "LOADTL/1\n"
    "SPINDL/200,SMM,CLW\n"
    "COOLNT/FLOOD\n"
    "RAPID\n"
    "GOTO/0,0,10\n"
    "FEDRAT/MMPM,200\n"
    "GOTO/0,0,-1\n"
    "DELAY/2\n"
    "GOTO/10,0,-1\n"
    "OPSTOP\n"
    "GOTO/10,0,10\n"
    "STOP/(TURN THE PART)\n"
    "SPINDL/RPM,1000,CLW\n"
    "GOTO/20,0,10\n"
    "AUXFUN/0\n"
    "AUXFUN/9\n"
    "GOTO/30,0,10\n"
    "DELAY/REV,10\n"
    "AUXFUN/5\n"
    "FINI\n";

}  // namespace

// (M60, a pallet change with a stop, is refused: gcode_control_test)
TEST_CASE("G-code: M0 and M1 are program stops after the block's motion", "[stop]") {
  const auto rs =
      gcode_records("G21 G90\nG0 X0 Y0 Z10 A0 C0\nG1 Z-1 F100 M0\nM1 (CHECK THE DEPTH)\nG2 X10 Y0 I5 J0 M00\nM30\n");
  const auto stops = only<cl::Stop>(rs);
  REQUIRE(stops.size() == 3);
  CHECK(stops[0].where.line == 3);
  CHECK(stops[0].where.column == 13);
  CHECK_FALSE(stops[0].optional);
  CHECK(stops[1].where.line == 4);
  CHECK(stops[1].optional);
  CHECK(stops[1].text.empty());  // the block's comment stays a comment, before the stop
  CHECK(index_of<cl::Comment>(rs, 4) < index_of<cl::Stop>(rs, 4));
  CHECK(stops[2].where.line == 5);
  CHECK_FALSE(stops[2].optional);
  // the stop comes after the block's motion (RS274NGC order), also after every chord of an arc
  const std::size_t stop3 = index_of<cl::Stop>(rs, 3), stop5 = index_of<cl::Stop>(rs, 5);
  REQUIRE(stop3 > 0);
  const auto* m3 = std::get_if<cl::Motion>(&rs[stop3 - 1]);
  REQUIRE(m3);
  CHECK(m3->where.line == 3);
  CHECK(m3->point.tip_mm.isApprox(Vec3d(0, 0, -1)));
  const auto* arc_end = std::get_if<cl::Motion>(&rs[stop5 - 1]);
  REQUIRE(arc_end);
  CHECK(arc_end->point.tip_mm.isApprox(Vec3d(10, 0, -1)));
  for (std::size_t i = stop5; i < rs.size(); ++i) CHECK_FALSE(std::holds_alternative<cl::Motion>(rs[i]));
  CHECK(only<cl::Unsupported>(rs).empty());
}

TEST_CASE("APT: STOP, OPSTOP, AUXFUN, DELAY and a surface speed as records", "[stop]") {
  const AptRead r = apt_records(kStops);
  const auto stops = only<cl::Stop>(r.records);
  REQUIRE(stops.size() == 3);
  CHECK(stops[0].where.line == 13);
  CHECK(stops[0].optional);
  CHECK(stops[1].where.line == 15);
  CHECK_FALSE(stops[1].optional);
  CHECK(stops[1].text == "TURN THE PART");
  CHECK(stops[2].where.line == 18);  // AUXFUN/0
  CHECK_FALSE(stops[2].optional);
  CHECK(stops[2].text.empty());
  const auto dwells = only<cl::Dwell>(r.records);
  REQUIRE(dwells.size() == 2);
  CHECK(dwells[0].seconds == 2.0);
  CHECK(dwells[1].seconds == Approx(0.6).epsilon(1e-12));  // 10 rev at 1000 rpm
  const auto spindles = only<cl::Spindle>(r.records);
  REQUIRE(spindles.size() == 3);
  CHECK(spindles[0].rpm == 6366.0);  // 1000 * 200 / (pi * 10) = 6366.2
  CHECK(spindles[0].direction == cl::Spindle::Direction::cw);
  CHECK(spindles[2].direction == cl::Spindle::Direction::off);  // AUXFUN/5
  const auto coolant = only<cl::Coolant>(r.records);
  REQUIRE(coolant.size() == 2);
  CHECK_FALSE(coolant[1].on);  // AUXFUN/9
  CHECK(coolant[1].where.line == 19);
  CHECK(only<cl::Unsupported>(r.records).empty());
  REQUIRE(r.notices.size() == 2);
  CHECK(r.notices[0] == "t.cls:5:1: SPINDL: 200 SMM on the 10 mm cutter (CUTTER at line 3) is posted as 6366 rpm");
  CHECK(r.notices[1] == "t.cls:21:1: DELAY/REV,10: 10 revolutions at 1000 rpm are posted as a dwell of 0.600 s");
}

TEST_CASE("APT: SFM with an inch CUTTER, AUXFUN spindle and coolant functions", "[stop]") {
  const AptRead r = apt_records(
      "UNITS/INCHES\nCUTTER/0.5,0.02\nSPINDL/500,SFM,CCLW\nAUXFUN/5\nAUXFUN/3\nAUXFUN/4\nAUXFUN/7\nAUXFUN/8\n"
      "AUXFUN/1\nFINI\n");
  const auto spindles = only<cl::Spindle>(r.records);
  REQUIRE(spindles.size() == 4);
  CHECK(spindles[0].rpm == 3820.0);  // 12 * 500 / (pi * 0.5) = 3819.7
  CHECK(spindles[0].direction == cl::Spindle::Direction::ccw);
  CHECK(spindles[1].direction == cl::Spindle::Direction::off);
  CHECK(spindles[2].direction == cl::Spindle::Direction::cw);
  CHECK(spindles[2].rpm == 3820.0);
  CHECK(spindles[3].direction == cl::Spindle::Direction::ccw);
  const auto coolant = only<cl::Coolant>(r.records);
  REQUIRE(coolant.size() == 2);
  CHECK(coolant[0].mode == "MIST");
  CHECK(coolant[1].mode == "FLOOD");
  CHECK(coolant[1].on);
  REQUIRE(only<cl::Stop>(r.records).size() == 1);
  CHECK(only<cl::Stop>(r.records)[0].optional);
  CHECK(r.notices.at(0) == "t.cls:3:1: SPINDL: 500 SFM on the 12.7 mm cutter (CUTTER at line 2) is posted as 3820 rpm");
}

TEST_CASE("APT: what cannot be posted as the CAM meant it is refused with its line", "[stop]") {
  CHECK_THAT(apt_error("UNITS/MM\nSPINDL/200,SMM,CLW\nFINI\n"),
             Catch::StartsWith("t.cls:2:1: SPINDL/200,SMM: surface speed needs the tool diameter (CUTTER/...)"));
  CHECK_THAT(apt_error("UNITS/MM\nDELAY/REV,5\nFINI\n"),
             Catch::StartsWith("t.cls:2:1: DELAY/REV: a dwell in spindle revolutions needs the spindle turning"));
  CHECK_THAT(apt_error("SPINDL/RPM,800,CLW\nSPINDL/OFF\nDELAY/REV,5\nFINI\n"),
             Catch::StartsWith("t.cls:3:1: DELAY/REV"));
  CHECK_THAT(apt_error("DELAY/-1\nFINI\n"), Catch::StartsWith("t.cls:1:1: DELAY: expected a dwell from 0 to 86400 s"));
  CHECK_THAT(apt_error("DELAY/2,3\nFINI\n"), Catch::StartsWith("t.cls:1:1: DELAY expects a time in seconds"));
  CHECK_THAT(
      apt_error("AUXFUN/3\nFINI\n"),
      Catch::StartsWith("t.cls:1:1: AUXFUN/3 (M3, spindle on) before any spindle speed: give SPINDL/n,CLW instead"));
  CHECK_THAT(apt_error("UNITS/MM\nAUXFUN/13\nFINI\n"),
             Catch::StartsWith("t.cls:2:1: AUXFUN/13 (M13) is not posted: its meaning depends on the machine"));
  CHECK_THAT(apt_error("AUXFUN/8.5\nFINI\n"), Catch::StartsWith("t.cls:1:1: AUXFUN expects one M function number"));
  CHECK_THAT(apt_error("PREFUN/17\nFINI\n"),
             Catch::StartsWith("t.cls:1:1: PREFUN/17 (a G function by number) is not posted"));
}

TEST_CASE("stops, dwells and machine functions in the Fanuc and Heidenhain programs", "[stop][post]") {
  const std::string fanuc = post_text(kStops, request("fanuc"));
  CHECK(from_line(fanuc, "T1 M6") ==
        "T1 M6\n"
        "G43 H1\n"
        "S6366 M3\n"
        "M8\n"
        "G0 X0.0000 Y0.0000 Z90.0000 A0.0000 C0.0000\n"
        "G94 G1 Z79.0000 F200.0\n"
        "G4 P2000\n"
        "X10.0000\n"
        "M1\n"
        "S6366 M3\n"  // M0/M1 may stop spindle and coolant: on again before the next motion
        "M8\n"
        "Z90.0000\n"
        "M0 (TURN THE PART)\n"
        "S1000 M3\n"  // the program's own SPINDL after the stop
        "M8\n"
        "X20.0000\n"
        "M0\n"
        "M9\n"  // AUXFUN/9: the coolant stays off
        "S1000 M3\n"
        "X30.0000\n"
        "G4 P600\n"
        "M5\n"
        "M5\n"
        "M9\n"
        "G91 G28 Z0\n"
        "G90\n"
        "M30\n"
        "%\n");
  const std::string heidenhain = post_text(kStops, request("heidenhain"));
  CHECK(from_line(heidenhain, "8 TOOL CALL") ==
        "8 TOOL CALL 1 Z S6366\n"
        "9 M3\n"
        "10 M8\n"
        "11 L X+0.0000 Y+0.0000 Z+90.0000 A+0.0000 C+0.0000 FMAX\n"
        "12 L Z+79.0000 F200\n"
        "13 CYCL DEF 9.0 DWELL TIME\n"
        "14 CYCL DEF 9.1 DWELL 2.000\n"
        "15 L X+10.0000 F200\n"
        "16 M1\n"
        "17 TOOL CALL Z S6366\n"  // the TNC's M0/M1 stop the spindle and the coolant
        "18 M3\n"
        "19 M8\n"
        "20 L Z+90.0000 F200\n"
        "21 M0 ; TURN THE PART\n"
        "22 TOOL CALL Z S1000\n"
        "23 M3\n"
        "24 M8\n"
        "25 L X+20.0000 F200\n"
        "26 M0\n"
        "27 M9\n"
        "28 TOOL CALL Z S1000\n"
        "29 M3\n"
        "30 L X+30.0000 F200\n"
        "31 CYCL DEF 9.0 DWELL TIME\n"
        "32 CYCL DEF 9.1 DWELL 0.600\n"
        "33 M5\n"
        "34 M30\n"
        "35 END PGM NCPOST MM\n");
}

TEST_CASE("after a stop the spindle and coolant start before a dwell (its run-up), not after it", "[stop][post]") {
  const std::string cl =
      "UNITS/MM\nLOADTL/1\nSPINDL/RPM,2000,CCLW\nCOOLNT/MIST\nRAPID\nGOTO/0,0,10\nSTOP\nDELAY/1.5\n"
      "FEDRAT/MMPM,300\nGOTO/0,0,-1\nFINI\n";
  CHECK_THAT(post_text(cl, request("fanuc")),
             Catch::Contains(
                 "G0 X0.0000 Y0.0000 Z90.0000 A0.0000 C0.0000\nM0\nS2000 M4\nM7\nG4 P1500\nG94 G1 Z79.0000 F300.0\n"));
  CHECK_THAT(post_text(cl, request("heidenhain")),
             Catch::Contains("FMAX\n10 M0\n11 TOOL CALL Z S2000\n12 M4\n13 M7\n14 CYCL DEF 9.0 DWELL TIME\n"
                             "15 CYCL DEF 9.1 DWELL 1.500\n16 L Z+79.0000 F300\n"));
}

TEST_CASE("G-code M0 (Fusion manual tool change) posted: the stop, then the program's own spindle start",
          "[stop][post]") {
  const std::string nc =
      "%\nO0004\nG90 G94 G17\nG21\n(2D Contour)\nM0\n(MANUAL TOOL CHANGE TO T14)\nS6000 M3\nG54\nG0 X-1.3 Y-4.85\nZ15\n"
      "G1 Z-1.35 F300\nM1\nX-45.5 F600\nZ15\nM5\nM30\n%\n";
  PostRequest r = request("fanuc");
  r.rtcp = true;
  r.setup.workpiece_origin_mm = Vec3d::Zero();  // the machine-axis program posted in the same numbers
  r.input_name = "fusion.nc";
  CHECK(from_line(post_text(nc, r), "(2D Contour)") ==
        "(2D Contour)\n"
        "M0\n"
        "(MANUAL TOOL CHANGE TO T14)\n"
        "S6000 M3\n"
        "G43.4 H1\n"
        "G0 X-1.3000 Y-4.8500 Z15.0000 A0.0000 C0.0000\n"
        "G94 G1 Z-1.3500 F300.0\n"
        "M1\n"
        "S6000 M3\n"
        "X-45.5000 F600.0\n"
        "Z15.0000\n"
        "M5\n"
        "G49\n"
        "M5\n"
        "M9\n"
        "G91 G28 Z0\n"
        "G90\n"
        "M30\n"
        "%\n");
  r.dialect = dialect_named("heidenhain");
  const std::string klartext = post_text(nc, r);
  CHECK_THAT(klartext,
             Catch::Contains("6 ; 2D Contour\n7 M0\n8 ; MANUAL TOOL CHANGE TO T14\n9 TOOL CALL Z S6000\n10 M3\n"));
  CHECK_THAT(klartext,
             Catch::Contains("13 L Z-1.3500 F300\n14 M1\n15 TOOL CALL Z S6000\n16 M3\n17 L X-45.5000 F600\n"));
}

TEST_CASE("a stop in a tilted work plane is written inside it; --verify and branch planning accept it",
          "[stop][post]") {
  std::string cl = test::read_text_file(test::data("tilted/two_planes.cls"));
  cl = test::replaced(cl, "GOTO/25,-20,30,0,-0.5,0.866025\n", "GOTO/25,-20,30,0,-0.5,0.866025\nOPSTOP\n");
  PostRequest r = request("fanuc");
  r.tilted_plane = true;
  r.tolerance_mm.reset();
  r.verify = true;
  PostResult res;
  const std::string program = post_text(cl, r, &res);
  CHECK(res.verified);
  // the plane holds across M1 (a modal frame): the in-plane X Y Z words go on, no G69 before the stop
  const std::size_t stop = program.find("\nM1\n");
  REQUIRE(stop != std::string::npos);
  const std::size_t plane_on = program.rfind("G68.2", stop), plane_off = program.rfind("G69", stop);
  REQUIRE(plane_on != std::string::npos);
  CHECK((plane_off == std::string::npos || plane_off < plane_on));
  CHECK(program.substr(stop, 40).rfind("\nM1\nS8000 M3\n", 0) == 0);
  // the same program without the stop differs by the stop and the spindle's restart only
  PostRequest plain = r;
  const std::string without = post_text(test::read_text_file(test::data("tilted/two_planes.cls")), plain);
  CHECK(test::replaced(program, "\nM1\nS8000 M3\n", "\n") == without);
}

TEST_CASE("a stop inside a run of five-axis feed motions: branch planning and the TRR-XY post", "[stop][post]") {
  const std::string dir = test::make_temp_dir("program_stop_run");
  const std::string cl = test::write_text_file(
      dir + "/hemi.cls", test::replaced(test::read_text_file(test::source("samples/hemisphere_5axis.cls")),
                                        "GOTO/3.5442,0.6249,39.8378,0.088606,0.015624,0.995944\n",
                                        "GOTO/3.5442,0.6249,39.8378,0.088606,0.015624,0.995944\nOPSTOP\n"));
  // the stop moves nothing: it stands between the feed motions of one planned run
  PostRequest r = request("fanuc");
  r.branch_choice = PostOptions::BranchChoice::lookahead;
  const std::string text = test::read_text_file(cl);
  const std::string planned = post_text(text, r);
  r.branch_choice = PostOptions::BranchChoice::greedy;
  CHECK(planned == post_text(text, r));
  CHECK_THAT(planned, Catch::Contains("\nM1\nS10000 M3\nM8\nX0.0000 Y-7.3104 Z119.6652 A5.2430 C75.0000 F"));
  // the feeds around the stop by the rule of inverse time (the tests' executor): F = 1200 / tip path
  const test::Executor ex(test::source("machines/ac-trunnion.toml"), test::ExecJob{Vec3d(0, 0, 80), 0.0}, planned);
  int g93 = 0;
  for (const test::ExecBlock& b : ex.blocks) {
    if (b.kind == test::ExecBlock::Kind::rapid || !b.inverse_time || ex.tip_path_mm(b) < 1e-3) continue;
    ++g93;
    CHECK(b.feed * ex.tip_path_mm(b) == Approx(1200.0).epsilon(2e-4));
  }
  CHECK(g93 > 100);
  // TRR-XY (X Y U V W), re-executed with --verify
  REQUIRE(test::run_ncpost("post --machine '" + test::source("machines/trr-xy.toml") +
                               "' --workpiece-origin 0,0,-300 --tolerance 0.005 --verify -o '" + dir + "/trr.nc' '" +
                               cl + "'",
                           dir + "/log.txt") == 0);
  CHECK_THAT(test::read_text_file(dir + "/trr.nc"),
             Catch::Contains("X40.4310 Y6.9233 U279.9080 V255.6136 W250.3464\nM1\nS10000 M3\nM8\nX40.2590 Y10.4810"));
}

TEST_CASE("dialect files: [program] stop and optional_stop are data, and never empty", "[stop][dialect]") {
  const std::string fanuc = test::read_text_file(test::source("postproc/dialects/fanuc.toml"));
  const Dialect d = parse_dialect(
      test::replaced(fanuc, "optional_stop = [\"M1\"]", "optional_stop = [\"M01\", \"M05\"]"), "mine.toml");
  CHECK(d.program_stop == std::vector<std::string>{"M0"});
  CHECK(d.program_optional_stop == std::vector<std::string>{"M01", "M05"});
  for (const char* name : {"fanuc", "haas", "linuxcnc", "sinumerik", "heidenhain"}) {
    INFO(name);
    CHECK(dialect_named(name).program_stop == std::vector<std::string>{"M0"});
    CHECK(dialect_named(name).program_optional_stop == std::vector<std::string>{"M1"});
  }
  try {
    parse_dialect(test::replaced(fanuc, "stop = [\"M0\"]", "stop = []"), "mine.toml");
    FAIL("an empty stop was accepted");
  } catch (const InputError& e) {
    CHECK_THAT(e.what(), Catch::StartsWith("mine.toml:12:8: stop in [program]: expected at least one block"));
  }
  try {
    parse_dialect(test::replaced(fanuc, "optional_stop = [\"M1\"]", "optional_stop = [\"M1 {tool}\"]"), "mine.toml");
    FAIL("a placeholder in optional_stop was accepted");
  } catch (const InputError& e) {
    CHECK_THAT(e.what(), Catch::Contains("unknown placeholder '{tool}' in optional_stop of [program]"));
  }
}

TEST_CASE("ncpost post: a surface speed without CUTTER exits 2 naming the line; M0 posts with --verify",
          "[stop][cli]") {
  const std::string dir = test::make_temp_dir("program_stop_cli");
  const std::string apt =
      test::write_text_file(dir + "/smm.apt", "UNITS/MM\nLOADTL/1\nSPINDL/200,SMM,CLW\nRAPID\nGOTO/0,0,10\nFINI\n");
  const std::string machine = "--machine '" + test::source("machines/ac-trunnion.toml") + "' ";
  CHECK(test::run_ncpost("post " + machine + "-o '" + dir + "/smm.nc' '" + apt + "'", dir + "/log.txt") == 2);
  CHECK_THAT(test::read_text_file(dir + "/log.txt"),
             Catch::Contains("smm.apt:3:1: SPINDL/200,SMM: surface speed needs the tool diameter (CUTTER/...)"));
  const std::string nc = test::write_text_file(
      dir + "/stop.nc", "G21 G90\nT1 M6\nS5000 M3\nG0 X0 Y0 Z10 A0 C0\nG1 Z-1 F500\nM0\nX10\nG0 Z10\nM30\n");
  CHECK(test::run_ncpost("post " + machine + "--verify -o '" + dir + "/out.nc' '" + nc + "'", dir + "/log2.txt") == 0);
  CHECK_THAT(test::read_text_file(dir + "/out.nc"),
             Catch::Contains("\nG94 G1 Z-1.0000 F500.0\nM0\nS5000 M3\nX10.0000\nG0 Z10.0000\n"));
  CHECK_THAT(test::read_text_file(dir + "/log2.txt"),
             Catch::Contains("after  (the written program re-executed, 2 blocks)"));
  CHECK(test::run_ncpost("preview " + machine + "'" + nc + "'", dir + "/log3.txt") == 0);
}
