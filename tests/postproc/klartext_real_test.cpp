// SPDX-License-Identifier: Apache-2.0
// Real Klartext programs (tests/data/real/heidenhain_*.h, GPL-3.0 and MIT, see SOURCES.md: written by the
// AptPostProcessor project's own post from SOLIDWORKS CAM APT, by hand for its TNC 310, by NX posts of the
// Unigraphics/NX.Postprocessor library, a training program kept beside them, and an unnamed CAM system's output
// published in NC-PB/gEdit and NC-PB/NCXchange_, MIT). Each is read by the Klartext reader
// (machines/head-table-bc.toml, or the machine the case names) and must post, or be refused at the line whose statement
// the reader does not take, with a message naming it. The expected line is found here in the file itself (the first
// line holding that statement), not taken from the reader's output.
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

#include "cl_records.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/postproc/read/klartext/klartext_reader.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "test_paths.hpp"

using namespace ncpost;

namespace {

std::string text_of(const std::string& name) {
  std::ifstream in(test::data("real/" + name), std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The 1-based number of the first line of `text` that contains `what`, or 0.
int line_with(const std::string& text, const std::string& what) {
  std::istringstream in(text);
  int n = 0;
  for (std::string line; std::getline(in, line);) {
    ++n;
    if (line.find(what) != std::string::npos) return n;
  }
  return 0;
}

/// The reader's message for the file read on machines/<machine_name>.toml, or "" when it reads to the end.
std::string outcome(const std::string& name, const std::string& machine_name) {
  std::istringstream in(text_of(name));
  const Machine machine = load_machine(test::source("machines/" + machine_name + ".toml"));
  Setup setup;
  setup.tool_length_mm = 100.0;
  setup.workpiece_origin_mm = Vec3d(0, 0, -400);
  klartext::KlartextReader r(in, name, machine, setup, {});
  try {
    test::all_records(r);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("real Klartext programs post or are refused at the statement they use") {
  const char* const kAcWithReferences = "../tests/data/machines/ac-trunnion-references";  // (machines/<name>.toml)
  struct Expected {
    const char* file;
    const char* statement;  ///< as written in the file ("" : posts)
    const char* message;    ///< what the refusal must say
    /// the machine (machines/<name>.toml): one whose file gives reference points (the programs retract with M91),
    /// with the rotary axes the program writes
    const char* machine = "head-table-bc";
  };
  const Expected cases[] = {
      {"heidenhain_aptpp_profile.h", "FN18: SYSREAD", "FN 18 is not read"},
      {"heidenhain_aptpp_dem_target2_11.h", "CYCLE DEF 9.0", "'CYCLE DEF 9.0 DWELL TIME' is not a Klartext statement"},
      {"heidenhain_aptpp_xdial.h", "CYCL DEF 7.1  X + 0", "CYCL DEF 7: expected one axis word per block"},
      {"heidenhain_aptpp_boss_12.h", "L Z 25.000", "Z without a value"},
      {"heidenhain_aptpp_sacrifice_912.h", "CYCL DEF 7.1 Xnan", "CYCL DEF 7: a shift of XNAN is not read"},
      {"heidenhain_aptpp_dem_target2_11setup.h", "", ""},
      // NX posts write the unit of an inch program as IN (the TNC's word is INCH): both refused as inch programs,
      // whose F the TNC 426 B / 430 manual has entered ten times larger (0.1 inch/min) and CAM posts do not
      {"heidenhain_nx_bridgeport412.h", "BEGIN PGM 100 IN", "BEGIN PGM ... IN: an inch program is not read"},
      {"heidenhain_nx_dmc70v.h", "BEGIN PGM T IN", "BEGIN PGM ... IN: an inch program is not read"},
      {"heidenhain_nx_dmc100.h", "BEGIN PGM PROGRAM IN", "BEGIN PGM ... IN: an inch program is not read"},
      // A and C: an A-axis machine; CYCL DEF 19.1 A+0 (the reset) is read, A-90 is not: CYCL DEF 19's
      // angles depend on a machine parameter. Before it (line 44), M91 Z-1 needs the machine's reference
      {"heidenhain_training_dmc75v.h", "M91", "M91 Z-1: machine coordinates count from the axis's reference point",
       "ac-trunnion"},
      // CAM output for an A/C table (NC-PB/gEdit, MIT; CAM system not named), on the A/C trunnion with reference
      // points (they retract with M91): decimal commas (X241,781), M128 F, Q208=MAX and CYCL DEF 206 are read; the
      // demo part goes to the M92 datum with A and C in the same block (the manuals give no rule for a rotary axis
      // under M92), the drilling program taps with 209 breaking chips inside the hole (Q256 > 0; Q256=0 is read)
      {"heidenhain_ncpb_Demo_1.h", "L X0 A0 C0 FMAX M92",
       "M92 with A0: a rotary axis in machine coordinates is not read", kAcWithReferences},
      {"heidenhain_ncpb_2.5D_MILLING.h", "", "", kAcWithReferences},
      {"heidenhain_ncpb_5X_MILLING.h", "", "", kAcWithReferences},
      {"heidenhain_ncpb_DRILLING.h", "CYCL DEF 209", "CYCL DEF 209: Q256=0.733 (chip breaking inside the hole",
       kAcWithReferences},
      // The same style of CAM output in NC-PB/NCXchange_ (MIT): cycles 200, 203 (chip breaking with Q213=24 and 3,
      // pecking with Q213=0, Q208=MAX), 207 and 201, each called by CYCL CALL and then M99 at four more holes
      {"heidenhain_ncx_BOHREN.h", "", "", kAcWithReferences},
      // M136 (F in mm per spindle revolution): posted with exit 0 and F as mm/min before it was refused
      {"heidenhain_ncx_2.5D_FRAESEN.h", "M136", "M136: a feed in mm per spindle revolution", kAcWithReferences},
  };
  for (const Expected& c : cases) {
    INFO(c.file);
    const std::string e = outcome(c.file, c.machine);
    if (std::string(c.statement).empty()) {
      CHECK(e.empty());
      continue;
    }
    const int line = line_with(text_of(c.file), c.statement);
    REQUIRE(line > 0);
    CHECK_THAT(e, Catch::StartsWith(std::string(c.file) + ":" + std::to_string(line) + ":"));
    CHECK_THAT(e, Catch::Contains(c.message));
  }
}

TEST_CASE("real Klartext NC-PB DRILLING: its CYCL DEF 209 with chip removal (Q256=0) read, on to CYCL DEF 202") {
  // the file's first 209 (line 157) breaks chips inside the hole (Q256=0,733): with that one set to 0 (chip
  // removal, as the file's other two 209s), the three 209s are read and the file is refused at the boring cycle
  // 202, the next statement the reader does not take
  std::string text = text_of("heidenhain_ncpb_DRILLING.h");
  const std::size_t q256 = text.find("Q256=0,733");
  REQUIRE(q256 != std::string::npos);
  text.replace(q256, 10, "Q256=0");
  const Machine machine = load_machine(test::data("machines/ac-trunnion-references.toml"));
  Setup setup;
  setup.tool_length_mm = 100.0;
  setup.workpiece_origin_mm = Vec3d(0, 0, -400);
  std::istringstream in(text);
  klartext::KlartextReader r(in, "DRILLING.h", machine, setup, {});
  std::string e;
  try {
    test::all_records(r);
  } catch (const InputError& x) {
    e = x.what();
  }
  CHECK_THAT(e, Catch::StartsWith("DRILLING.h:" + std::to_string(line_with(text, "CYCL DEF 202")) + ":") &&
                    Catch::Contains("CYCL DEF 202"));
  CHECK(line_with(text, "CYCL DEF 202") > line_with(text, "CYCL DEF 209"));
}
