// SPDX-License-Identifier: Apache-2.0
// The words of a program are the dialect file's (issue 16 item 4): Heidenhain Klartext and ISO
// G-code are two sets of data for one writer. Exact programs for: the Klartext spindle speed in
// TOOL CALL with M3 on the next block (and TOOL CALL Z S.. for a speed alone), the documented
// CYCL DEF 9 dwell, the safe Fanuc/Haas end, a user's file that numbers blocks its own way and
// writes non-modal motion words, and the refusal keyed on an empty [motion] inverse_time.
#include <catch2/catch.hpp>

#include <sstream>
#include <string>

#include "cli_run.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/read/apt/apt_reader.hpp"
#include "ncpost/postproc/write/cycle_words.hpp"
#include "ncpost/postproc/post.hpp"
#include "ncpost/postproc/solve/unreachable.hpp"
#include "temp_dir.hpp"
#include "test_paths.hpp"
#include "text_edit.hpp"

using namespace ncpost;

using ncpost::test::replaced;

namespace {

const std::string kFanuc = test::read_text_file(test::source("postproc/dialects/fanuc.toml"));

/// `cl` (APT) posted in `dialect` on `machine` (no header comments, program name T).
std::string post_apt(const std::string& cl, const Dialect& dialect, const std::string& machine = "vmcl600",
                     bool rtcp = false) {
  const Machine m = load_machine(test::source("machines/" + machine + ".toml"));
  std::istringstream in(cl);
  cl::AptReader reader(in, "t.apt");
  const std::string path = test::make_temp_dir("dialect_words") + "/t.nc";
  {
    AtomicFile out(path);
    std::string letters;
    for (const Axis& a : m.axes) letters += a.letter;
    NcWriter writer(out, dialect, letters);
    PostOptions o;
    o.program_name = "T";
    o.rtcp = rtcp;
    Setup setup;
    if (machine == "ac-trunnion") setup.workpiece_origin_mm = Vec3d(0, 0, 80);
    post_program(reader, "t.apt", NominalSolver(m, setup), writer, o);
    out.commit();
  }
  return test::read_text_file(path);
}

// two tools, a spindle speed after each tool change and one without, a drilled hole with a dwell
// (expanded where the dialect has no cycles), coolant
const std::string kCl =
    "UNITS/MM\nLOADTL/1\nSPINDL/2000,CLW\nCOOLNT/ON\nFEDRAT/MMPM,500\nRAPID\nGOTO/10,20,25\n"
    "CYCLE/DRILL,FEDTO,5.,MMPM,100.,RAPTO,3.,DWELL,1.5\nGOTO/10,20,0\nCYCLE/OFF\n"
    "SPINDL/1500,CCLW\nGOTO/20,20,25\nSPINDL/OFF\nCOOLNT/OFF\n"
    "LOADTL/2\nRAPID\nGOTO/20,30,25\nSPINDL/3000,CLW\nFEDRAT/MMPM,200\nGOTO/20,30,0\nFINI\n";

}  // namespace

TEST_CASE("Klartext: the speed in TOOL CALL, M3 after it, CYCL DEF 9 dwell, L blocks", "[dialect][words]") {
  CHECK(post_apt(kCl, dialect_named("heidenhain")) ==
        "0 BEGIN PGM T MM\n"
        "1 TOOL CALL 1 Z S2000\n"  // the SPINDL's speed goes into the call ...
        "2 M3\n"                   // ... and the direction on the next block
        "3 M8\n"
        "4 L X+10.0000 Y+20.0000 Z+25.0000 FMAX\n"
        "5 L Z+3.0000 FMAX\n"
        "6 L Z-5.0000 F100\n"
        "7 CYCL DEF 9.0 DWELL TIME\n"
        "8 CYCL DEF 9.1 DWELL 1.500\n"
        "9 L Z+3.0000 FMAX\n"
        "10 TOOL CALL Z S1500\n"  // a speed without a tool change
        "11 M4\n"
        "12 L X+20.0000 Z+25.0000 F500\n"
        "13 M5\n"
        "14 M9\n"
        "15 TOOL CALL 2 Z S1500\n"                   // a motion before the next SPINDL: the speed in force
        "16 L X+20.0000 Y+30.0000 Z+25.0000 FMAX\n"  // after the change every word again
        "17 TOOL CALL Z S3000\n"
        "18 M3\n"
        "19 L Z+0.0000 F200\n"
        "20 M30\n"
        "21 END PGM T MM\n");
  // the documented form of the dwell (CYCL DEF 9.1 DWELL, a space, seconds)
  CHECK(dwell_blocks(dialect_named("heidenhain"), 0.25) ==
        std::vector<std::string>{"CYCL DEF 9.0 DWELL TIME", "CYCL DEF 9.1 DWELL 0.250"});
}

TEST_CASE("Fanuc and Haas: the same CL in G-code words, ending with spindle and coolant off and Z home",
          "[dialect][words]") {
  const std::string body =
      "G90 G21 G94 G17 G40 G49 G80\n"
      "T1 M6\nG43 H1\nS2000 M3\nM8\n"
      "G0 X10.0000 Y20.0000 Z25.0000\n"
      "Z3.0000\n"
      "G94 G99 G82 X10.0000 Y20.0000 Z-5.0000 R3.0000 P1500 F100.0\n"
      "G80\n"
      "S1500 M4\n"
      "G1 X20.0000 Z25.0000 F500.0\n"
      "M5\nM9\n"
      "T2 M6\nG43 H2\n"
      "G0 X20.0000 Y30.0000 Z25.0000\n"  // after a tool change every word again (the changer moved the axes)
      "S3000 M3\n"
      "G1 Z0.0000 F200.0\n";
  CHECK(post_apt(kCl, dialect_named("fanuc")) == "%\nO0001 (T)\n" + body + "M5\nM9\nG91 G28 Z0\nG90\nM30\n%\n");
  CHECK(post_apt(kCl, dialect_named("haas")) == "%\nO0001 (T)\n" + body + "M5\nM9\nG28 G91 Z0\nG90\nM30\n%\n");
}

TEST_CASE("a user's dialect: its own block numbers, motion word on every block, F on every feed block",
          "[dialect][words]") {
  std::string text = replaced(kFanuc, "line_numbers = false", "line_numbers = true");
  text = replaced(text, "number_start = 10", "number_start = 100");
  text = replaced(text, "number_step = 10", "number_step = 5");
  text = replaced(text, "modal = true ", "modal = false");
  text = replaced(text, "feed_modal = true", "feed_modal = false");
  text = replaced(text, "rapid_feed = \"\"", "rapid_feed = \"(RAPID)\"");
  const std::string cl = "UNITS/MM\nLOADTL/4\nRAPID\nGOTO/0,0,50\nFEDRAT/MMPM,400\nGOTO/10,0,50\nGOTO/10,5,50\nFINI\n";
  CHECK(post_apt(cl, parse_dialect(text, "mine.toml")) ==
        "%\n"
        "N100 O0001 (T)\n"
        "N105 G90 G21 G94 G17 G40 G49 G80\n"
        "N110 T4 M6\n"
        "N115 G43 H4\n"
        "N120 G0 X0.0000 Y0.0000 Z50.0000 (RAPID)\n"
        "N125 G94 G1 X10.0000 F400.0\n"
        "N130 G1 Y5.0000 F400.0\n"
        "N135 M5\nN140 M9\nN145 G91 G28 Z0\nN150 G90\nN155 M30\n"
        "%\n");
}

TEST_CASE("no inverse-time word in the dialect: a simultaneous cut is refused, with RTCP it is posted",
          "[dialect][words]") {
  const std::string cl =
      "UNITS/MM\nMULTAX/ON\nLOADTL/1\nRAPID\nGOTO/0,0,50,0,0,1\nFEDRAT/MMPM,800\n"
      "GOTO/0,10,50,0,0.5,0.8660254\nFINI\n";
  const Dialect no_g93 =
      parse_dialect(replaced(kFanuc, "inverse_time = \"G93\"", "inverse_time = \"\""), "no-g93.toml");
  CHECK_THROWS_WITH(post_apt(cl, no_g93, "ac-trunnion"),
                    Catch::Contains("t.apt:7:") &&
                        Catch::Contains("the fanuc dialect has no inverse-time feed (G93)") &&
                        Catch::Contains("[motion] inverse_time is empty in no-g93.toml") && Catch::Contains("--rtcp"));
  CHECK_THAT(post_apt(cl, no_g93, "ac-trunnion", true), Catch::Contains("\nG94 G1 Y10.0000 A30.0000 F800.0\n"));
  // the built-in fanuc file has G93
  CHECK_THAT(post_apt(cl, dialect_named("fanuc"), "ac-trunnion"), Catch::Contains("\nG93 G1 "));
}
