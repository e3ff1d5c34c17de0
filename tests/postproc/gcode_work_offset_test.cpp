// SPDX-License-Identifier: Apache-2.0
// Issue 24.3: work offsets G54-G59, G54.1 P<n>, G59.1-G59.3 with their values from --work-offsets
// (TOML or a LinuxCNC var file) or the program's G10 L2/L20, each operation posted in the frame of
// the first. Every posting case executes the INPUT with the tests' own control interpreter
// (tests/support/control_interpreter.hpp: machine coordinates = words + the active offset's value)
// and the written OUTPUT with tests/support/nc_executor.hpp, and compares the tool tip at every
// input block end (1 µm): the output's frame is the first offset's, so the input's machine
// coordinates minus that offset's value are the posted program's words (docs/formats.md "Work
// offsets").
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <sstream>
#include <string>

#include "cli_run.hpp"
#include "input_output_tips.hpp"
#include "shipped_machines.hpp"
#include "temp_dir.hpp"
#include "test_paths.hpp"
#include "text_file.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/postproc/read/gcode/gcode_cl_reader.hpp"
#include "ncpost/postproc/read/gcode/work_offsets.hpp"

using namespace ncpost;
using namespace ncpost::test;

namespace {

/// `ncpost post` of the G-code `input` on `machine` (a file under machines/) with the work
/// offsets file `offsets` ("": none) and `extra` options.
PostRun post_program(const std::string& input, const std::string& machine, const std::string& offsets,
                     const std::string& extra, const std::string& offsets_name = "offsets.toml") {
  const std::string dir = make_temp_dir("work_offsets");
  const std::string in = write_text_file(dir + "/in.nc", input);
  std::string args = "--machine " + source("machines/" + machine) + " --tolerance none " + extra;
  if (!offsets.empty()) args += " --work-offsets " + write_text_file(dir + "/" + offsets_name, offsets);
  return run_post(args, in, dir + "/out.nc", dir + "/log");
}

InputError reader_error(const std::string& text, std::shared_ptr<const gcode::WorkOffsetTable> table,
                        cl::ControlFamily control = cl::ControlFamily::fanuc) {
  std::istringstream in(text);
  gcode::GcodeReaderOptions o;
  o.work_offsets = std::move(table);
  o.control = control;
  gcode::GcodeClReader r(in, "t.nc", vmcl600(), Setup{}, o);
  try {
    while (r.next()) {
    }
  } catch (const InputError& e) {
    return e;
  }
  FAIL("no error for: " << text);
  throw;
}

const char* const kThreeOffsets =
    "units = \"mm\"\n[G54]\nX = -250.0\nY = -120.0\nZ = -310.0\n[G55]\nX = -100.0\nY = -120.0\nZ = -310.0\n"
    "[G58]\nX = 40.5\nY = 30.25\nZ = -305.0\n";

const char* const kThreeOperations =
    "%\nO1000\nG21 G90 G17 G94\nT1 M6\nG43 H1\nS8000 M3\n"
    "G54 G0 X10 Y10 Z20\nG1 Z-2 F300\nX40\nY30\nG0 Z20\n"
    "G55 G0 X10 Y10\nG1 Z-2\nG91 X25 Y5\nG90 G0 Z20\n"
    "G58 G0 X0 Y0\nG1 Z-1\nX-15 Y-10\nG0 Z20\n"
    "G54 G0 X5 Y5\nM30\n%\n";

ControlSpec spec_of(std::map<std::string, std::map<char, double>> offsets, bool linuxcnc = false,
                    std::string axes = "XYZ") {
  ControlSpec s;
  s.offsets = std::move(offsets);
  s.linuxcnc = linuxcnc;
  s.axes = std::move(axes);
  return s;
}

}  // namespace

TEST_CASE("work offsets: G54, G55 and G58 from a TOML file, each operation in its own frame") {
  const PostRun p = post_program(kThreeOperations, "vmcl600.toml", kThreeOffsets, "");
  INFO(p.log);
  REQUIRE(p.exit_code == 0);
  CHECK_THAT(p.log, Catch::Contains("G55: its coordinates are placed in the frame of G54"));
  const ControlSpec spec = spec_of({{"G54", {{'X', -250.0}, {'Y', -120.0}, {'Z', -310.0}}},
                                    {"G55", {{'X', -100.0}, {'Y', -120.0}, {'Z', -310.0}}},
                                    {"G58", {{'X', 40.5}, {'Y', 30.25}, {'Z', -305.0}}}});
  CHECK(compare_tips(kThreeOperations, spec, "G54", "vmcl600.toml", p.program) == 14);
  // the G55 cut at X10 Y10 lies 150 mm further in +X than G54's X10 Y10: posted as X160
  CHECK_THAT(p.program, Catch::Contains("X160"));
}

TEST_CASE("work offsets: a LinuxCNC var file gives G54 .. G59.3 (5221 .. 5389)") {
  // G55 (5241..) and G59.1 (5341..): X Y Z; 5220 (the active system) and U V W are not read
  const std::string var =
      "5220\t1.000000\n5221\t-250.0\n5222\t-120.0\n5223\t-310.0\n5227\t99\n"
      "5241\t-100.000000\n5242\t-120.000000\n5243\t-310.000000\n"
      "5341\t12.5\n5342\t-7.25\n5343\t-300.0\n";
  const std::string input = "G21 G90 G17 G94\nG54 G0 X10 Y10 Z20\nG1 Z0 F200\nG55 G1 X20\nG59.1 G1 Y5\nG0 Z20\nM2\n";
  const PostRun p = post_program(input, "vmcl600.toml", var, "--dialect linuxcnc", "linuxcnc.var");
  INFO(p.log);
  REQUIRE(p.exit_code == 0);
  const ControlSpec spec = spec_of({{"G54", {{'X', -250.0}, {'Y', -120.0}, {'Z', -310.0}}},
                                    {"G55", {{'X', -100.0}, {'Y', -120.0}, {'Z', -310.0}}},
                                    {"G59.1", {{'X', 12.5}, {'Y', -7.25}, {'Z', -300.0}}}},
                                   true);
  CHECK(compare_tips(input, spec, "G54", "vmcl600.toml", p.program) == 5);
  const gcode::WorkOffsetTable t = gcode::parse_work_offsets(var, "v.var");
  CHECK(t.offsets.size() == 3);
  CHECK(*t.offsets.at("G59.1")[1] == -7.25);
  CHECK_FALSE(t.offsets.at("G54")[3].has_value());
}

TEST_CASE("work offsets: G54.1 P<n> and G59.3 from the file; inch values converted") {
  const std::string toml =
      "units = \"inch\"\n[G57]\nX = 1\nY = 2\nZ = -10\n[\"G54.1 P7\"]\nX = 3\nY = 2\nZ = -10\n"
      "[\"g59.3\"]\nX = -1\nY = 0.5\nZ = -9.5\n";
  const std::string input = "G21 G90 G17 G94\nG57 G0 X0 Y0 Z10\nG1 Z0 F100\nG54.1 P7 G1 X5\nG59.3 G1 Y5\nG0 Z10\nM30\n";
  const PostRun p = post_program(input, "vmcl600.toml", toml, "");
  INFO(p.log);
  REQUIRE(p.exit_code == 0);
  const ControlSpec spec = spec_of({{"G57", {{'X', 25.4}, {'Y', 50.8}, {'Z', -254.0}}},
                                    {"G54.1 P7", {{'X', 76.2}, {'Y', 50.8}, {'Z', -254.0}}},
                                    {"G59.3", {{'X', -25.4}, {'Y', 12.7}, {'Z', -241.3}}}});
  CHECK(compare_tips(input, spec, "G57", "vmcl600.toml", p.program) == 5);
}

TEST_CASE("work offsets: the program's own G10 L2 (Mastercam's #501 = 1 / G10 L2 P#501) sets them") {
  // no file: G54 and G55 are set by the program before use; G54's value is not needed to place
  // G55 once both are the program's
  const std::string input =
      "%\nO0100\nG21 G90 G17 G94\n#501 = 1\n#510 = -200.\n#511 = -100.\n#512 = -300.\n"
      "G10 L2 P#501 X#510 Y#511 Z#512\nG10 L2 P2 X[#510 + 80.] Y#511 Z[#512 + 5.]\n"
      "G54 G0 X0 Y0 Z10\nG1 Z0 F100\nX20\nG55 G1 X20\nY15\nG0 Z10\nM30\n%\n";
  const PostRun p = post_program(input, "vmcl600.toml", "", "");
  INFO(p.log);
  REQUIRE(p.exit_code == 0);
  const ControlSpec spec = spec_of({});
  CHECK(compare_tips(input, spec, "G54", "vmcl600.toml", p.program) == 6);
}

TEST_CASE("work offsets: LinuxCNC G10 L20 makes the current position read the words") {
  // G55's zero put where the tool stands (X30 Y20 of G54), without knowing G54's value
  const std::string input =
      "G21 G90 G17 G94\nG54 G0 X30 Y20 Z10\nG10 L20 P2 X0 Y0 Z10\nG55 G1 X5 F100\nY5\n"
      "G10 L20 P0 X100\nG1 X110\nG54 G0 X0 Y0\nM2\n";
  const PostRun p = post_program(input, "vmcl600.toml", "", "--dialect linuxcnc");
  INFO(p.log);
  REQUIRE(p.exit_code == 0);
  ControlSpec spec = spec_of({{"G54", {{'X', -123.0}, {'Y', 45.0}, {'Z', -222.0}}}}, true);
  CHECK(compare_tips(input, spec, "G54", "vmcl600.toml", p.program) == 5);
  // the same program for a Fanuc control: G10 L20 P2 sets G54.1 P2, not G55; G55 is then unknown
  const PostRun fanuc = post_program(input, "vmcl600.toml", "", "--dialect fanuc");
  CHECK(fanuc.exit_code == 2);
  CHECK_THAT(fanuc.log, Catch::Contains("--work-offsets"));
}

TEST_CASE("work offsets: Fanuc G10 L20 P<n> sets G54.1 P<n>") {
  const std::string input =
      "G21 G90 G17 G94\nG10 L20 P3 X-40 Y-50 Z-200\nG10 L2 P1 X-90 Y-50 Z-200\n"
      "G54 G0 X0 Y0 Z10\nG1 Z0 F100\nG54.1 P3 G1 X0\nG0 Z10\nM30\n";
  const PostRun p = post_program(input, "vmcl600.toml", "", "--dialect fanuc");
  INFO(p.log);
  REQUIRE(p.exit_code == 0);
  CHECK(compare_tips(input, spec_of({}), "G54", "vmcl600.toml", p.program) == 4);
}

TEST_CASE("work offsets: a five-axis program with a rotary value in the offset (AC trunnion, machine axes)") {
  const std::string toml = "[G54]\nX = 0\nY = 0\nZ = 0\nA = 0\nC = 0\n[G55]\nX = 12\nY = -8\nZ = 5\nA = 0\nC = 30\n";
  const std::string input =
      "G21 G90 G17 G94\nG54 G0 X10 Y0 Z60 A0 C0\nG1 Z50 F500\nA20 C45\n"
      "G55 G1 X10 Y0 Z50 A15 C10\nX20 C-20\nG0 Z80\nM30\n";
  const PostRun p = post_program(input, "ac-trunnion.toml", toml, "");
  INFO(p.log);
  REQUIRE(p.exit_code == 0);
  const ControlSpec spec = spec_of({{"G54", {{'X', 0}, {'Y', 0}, {'Z', 0}, {'A', 0}, {'C', 0}}},
                                    {"G55", {{'X', 12}, {'Y', -8}, {'Z', 5}, {'A', 0}, {'C', 30}}}},
                                   false, "XYZAC");
  CHECK(compare_tips(input, spec, "G54", "ac-trunnion.toml", p.program) == 6);
}

TEST_CASE("work offsets: refusals name --work-offsets, the axis and the line") {
  const std::string two = "G21 G90\nG54 G0 X0 Y0 Z10\nG1 Z0 F100\nG55 G1 X10\nM30\n";
  const InputError none = reader_error(two, nullptr);
  CHECK(none.where().line == 4);
  CHECK_THAT(none.detail(), Catch::Contains("--work-offsets FILE"));
  CHECK_THAT(none.detail(), Catch::Contains("X, Y, Z"));
  auto partial = std::make_shared<gcode::WorkOffsetTable>(
      gcode::parse_work_offsets("[G54]\nX = 0\nY = 0\nZ = 0\n[G55]\nX = 5\nY = 0\n", "o.toml"));
  const InputError missing = reader_error(two, partial);
  CHECK_THAT(missing.detail(), Catch::Contains("the work offsets file o.toml does not give Z"));
  // the control decides G10 L20 and G10 L2 P0: unknown, they are refused naming --dialect
  const InputError l20 =
      reader_error("G21 G90\nG0 X0 Y0 Z0\nG10 L20 P2 X0\nM30\n", nullptr, cl::ControlFamily::unknown);
  CHECK(l20.where().line == 3);
  CHECK_THAT(l20.detail(), Catch::Contains("--dialect"));
  const InputError p0 = reader_error("G21 G90\nG10 L2 P0 X0\nM30\n", nullptr, cl::ControlFamily::unknown);
  CHECK_THAT(p0.detail(), Catch::Contains("external offset on Fanuc"));
  const InputError g91 = reader_error("G21 G91\nG10 L2 P1 X5\nM30\n", nullptr);
  CHECK_THAT(g91.detail(), Catch::Contains("G10 under G91"));
  const InputError p_missing = reader_error("G21 G90\nG54.1 G0 X0 Y0 Z0\nM30\n", nullptr);
  CHECK_THAT(p_missing.detail(), Catch::Contains("G54.1 needs P1 .. P300"));
  // LinuxCNC G10 L20 before the axis was ever programmed
  const InputError unknown = reader_error("G21 G90\nG10 L20 P2 X0\nM30\n", nullptr, cl::ControlFamily::linuxcnc);
  CHECK_THAT(unknown.detail(), Catch::Contains("where X stands is not known yet"));
}

TEST_CASE("work offsets: without a file one offset posts as before, and the CLI names the option") {
  const std::string one = "G21 G90\nG56 G0 X0 Y0 Z10\nG1 Z0 F100\nX10\nM30\n";
  const PostRun p = post_program(one, "vmcl600.toml", "", "");
  CHECK(p.exit_code == 0);
  const PostRun two = post_program("G21 G90\nG54 G0 X0 Y0 Z10\nG1 Z0 F100\nG55 G1 X10\nM30\n", "vmcl600.toml", "", "");
  CHECK(two.exit_code == 2);
  CHECK_THAT(two.log, Catch::Contains("--work-offsets"));
}

TEST_CASE("work offsets: the file's errors name the line and what was expected") {
  const auto error_of = [](const std::string& text) {
    try {
      gcode::parse_work_offsets(text, "w.toml");
    } catch (const InputError& e) {
      return e;
    }
    FAIL("no error for " << text);
    throw;
  };
  const InputError axis = error_of("[G54]\nX = 1\nU = 2\n");
  CHECK(axis.where().line == 3);
  CHECK_THAT(axis.detail(), Catch::Contains("unknown axis 'U'"));
  CHECK_THAT(error_of("[G60]\nX = 1\n").detail(), Catch::Contains("'G60' is no work offset"));
  CHECK_THAT(error_of("[\"G54.1 P301\"]\nX = 1\n").detail(), Catch::Contains("is no work offset"));
  CHECK_THAT(error_of("units = \"cm\"\n").detail(), Catch::Contains("\"mm\" or \"inch\""));
  CHECK_THAT(error_of("[G54]\nX = \"a\"\n").detail(), Catch::Contains("expected a number"));
  const InputError var = error_of("5221 1.0\n5222\n");
  CHECK(var.where().line == 2);
  CHECK(gcode::work_offset_name("g54.1 p03") == std::optional<std::string>("G54.1 P3"));
  CHECK(gcode::work_offset_of_register(7) == std::optional<std::string>("G59.1"));
  CHECK_FALSE(gcode::work_offset_of_register(10));
}
