// SPDX-License-Identifier: Apache-2.0
// Issue 24.2: the power-on modal state from the dialect file ([input] power_on, as LinuxCNC's
// RS274NGC_STARTUP_CODE): `G43 Z30. H8` and axis words before any motion word read on Fanuc
// (G00 from power-on), the posted header names the state assumed, the units of the power-on state
// are a default the user's --units overrides, and a dialect file naming a code outside the modal
// state is refused. The posting case executes the INPUT with the tests' own control interpreter
// (its power-on motion mode is G0) and the OUTPUT with nc_executor.hpp, 1 µm at every block end.
#include <catch2/catch.hpp>

#include <sstream>
#include <string>

#include "cl_records.hpp"
#include "cli_run.hpp"
#include "input_output_tips.hpp"
#include "shipped_machines.hpp"
#include "temp_dir.hpp"
#include "test_paths.hpp"
#include "text_file.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/read/gcode/gcode_cl_reader.hpp"
#include "ncpost/postproc/read/gcode/work_offsets.hpp"
#include "ncpost/postproc/write/dialect.hpp"

using namespace ncpost;
using namespace ncpost::test;

namespace {

gcode::GcodeReaderOptions with_power_on(const std::string& codes) {
  gcode::GcodeReaderOptions o;
  o.power_on = codes;
  o.power_on_source = "test power-on";
  return o;
}

std::vector<cl::Motion> motions(const std::string& text, const gcode::GcodeReaderOptions& o) {
  std::istringstream in(text);
  gcode::GcodeClReader r(in, "t.nc", vmcl600(), Setup{}, o);
  return only<cl::Motion>(all_records(r));
}

// NX posts for Mori Seiki and Okuma: the tool's first positioning and its length call carry no
// motion word; the control's power-on G00 moves them
const char* const kNoMotionWord =
    "%\nO0001\nG21 G90 G17\nT8 M6\nX10. Y10. Z40. S1000 M3\nG43 Z30. H8\nG1 Z0 F200\n"
    "X40.\nG0 Z30.\nM30\n%\n";

}  // namespace

TEST_CASE("power-on: G43 Z30. H8 before any motion word posts on Fanuc, and the header says why") {
  const std::string dir = make_temp_dir("power_on");
  const std::string in = write_text_file(dir + "/in.nc", kNoMotionWord);
  const int rc = run_ncpost("post --machine " + source("machines/vmcl600.toml") +
                                " --tolerance none --dialect fanuc -o " + dir + "/out.nc " + in,
                            dir + "/log");
  INFO(read_text_file(dir + "/log"));
  REQUIRE(rc == 0);
  const std::string out = read_text_file(dir + "/out.nc");
  CHECK_THAT(out, Catch::Contains("G-code input read from the power-on state G0 G17 G90 G94 G54"));
  ControlSpec spec;
  spec.offsets["G54"] = {{'X', 0.0}, {'Y', 0.0}, {'Z', 0.0}};
  CHECK(compare_tips(kNoMotionWord, spec, "G54", "vmcl600.toml", out) == 5);
}

TEST_CASE("power-on: without a power-on state the same program is refused at its first axis words") {
  std::istringstream in(kNoMotionWord);
  gcode::GcodeClReader r(in, "t.nc", vmcl600(), Setup{});
  try {
    while (r.next()) {
    }
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.where().line == 5);
    CHECK_THAT(e.detail(), Catch::Contains("[input] power_on"));
  }
  const auto ms = motions(kNoMotionWord, with_power_on("G0 G17 G90 G94 G54"));
  REQUIRE(ms.size() == 5);
  CHECK(ms[0].rapid);
  CHECK(ms[1].point.tip_mm.isApprox(Vec3d(10, 10, 30)));
  CHECK_FALSE(ms[2].rapid);  // G1 Z0
}

TEST_CASE("power-on: its units are a default that --units overrides; its distance mode applies") {
  // G20 G91 from power-on: X1 then X1 again is 25.4 then 50.8 mm (incremental, from the first 0)
  const std::string program = "G0 X0 Y0 Z1\nX1\nX1\nM30\n";
  const auto inch = motions(program, with_power_on("G0 G20 G91 G17 G94"));
  REQUIRE(inch.size() == 3);
  CHECK(inch[2].point.tip_mm.x() == Approx(50.8));
  CHECK(inch[2].point.tip_mm.z() == Approx(25.4));
  gcode::GcodeReaderOptions mm = with_power_on("G0 G20 G91 G17 G94");
  mm.units_given = true;  // --units mm
  const auto given = motions(program, mm);
  REQUIRE(given.size() == 3);
  CHECK(given[2].point.tip_mm.x() == Approx(2.0));
}

TEST_CASE("power-on: its work offset is the base frame; a second offset is placed from it") {
  // moves before any offset word are in G54 (power-on); G55 lies 100 mm further in X
  auto table = std::make_shared<gcode::WorkOffsetTable>(
      gcode::parse_work_offsets("[G54]\nX = 0\nY = 0\nZ = 0\n[G55]\nX = 100\nY = 0\nZ = 0\n", "o.toml"));
  gcode::GcodeReaderOptions o = with_power_on("G0 G17 G90 G94 G54");
  o.work_offsets = table;
  const auto ms = motions("G21\nX0 Y0 Z10\nG55 X5\nM30\n", o);
  REQUIRE(ms.size() == 2);
  CHECK(ms[1].point.tip_mm.isApprox(Vec3d(105, 0, 10)));
  // a power-on G56 is the base instead: G55 lies 100 - 30 mm further in X than G56
  auto with_g56 = std::make_shared<gcode::WorkOffsetTable>(*table);
  with_g56->offsets["G56"] = {30.0, 0.0, 0.0, std::nullopt, std::nullopt, std::nullopt};
  gcode::GcodeReaderOptions g56 = with_power_on("G0 G17 G90 G94 G56");
  g56.work_offsets = with_g56;
  const auto from_g56 = motions("G21\nX0 Y0 Z10\nG55 X5\nM30\n", g56);
  REQUIRE(from_g56.size() == 2);
  CHECK(from_g56[1].point.tip_mm.isApprox(Vec3d(75, 0, 10)));
  // without a table the same program is refused at G55, naming the base
  CHECK_THROWS_WITH(motions("G21\nX0 Y0 Z10\nG55 X5\nM30\n", with_power_on("G0 G17 G90 G94 G56")),
                    Catch::Contains("G55: a second work offset (the program moved in G56)"));
}

TEST_CASE("power-on: a dialect file names only G codes of the modal state") {
  std::string fanuc = read_text_file(source("postproc/dialects/fanuc.toml"));
  const std::string line = "power_on = \"G0 G17 G90 G94 G54\"";
  REQUIRE(fanuc.find(line) != std::string::npos);
  CHECK(parse_dialect(fanuc, "fanuc.toml").input_power_on == "G0 G17 G90 G94 G54");
  CHECK(parse_dialect(fanuc, "fanuc.toml").input_control == cl::ControlFamily::fanuc);
  fanuc.replace(fanuc.find(line), line.size(), "power_on = \"G0 G68 G90\"");
  try {
    parse_dialect(fanuc, "mine.toml");
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.where().file == "mine.toml");
    CHECK(e.where().line > 0);
    CHECK_THAT(e.detail(), Catch::Contains("got \"G68\""));
  }
}
