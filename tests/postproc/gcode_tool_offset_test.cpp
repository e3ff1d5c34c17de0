// SPDX-License-Identifier: Apache-2.0
// Issue 24: tool offsets set in the program (G10 L1 / L10 / L12, docs/formats.md "Tool offsets").
// What each L sets comes from the dialect's [input] tool_offsets: Fanuc L10 the length, L12 the
// radius; Haas L12 the diameter; LinuxCNC L1 the tool table (Z, R). The posted program sets the
// same register to the same value in its dialect's words ([tool] set_offset) before the G43 that
// uses it; wear, LinuxCNC's L10 and a dialect that cannot write them are refused. Every posting
// case executes the INPUT with the tests' control interpreter and the OUTPUT with nc_executor.hpp.
#include <catch2/catch.hpp>

#include <regex>
#include <sstream>
#include <string>

#include "cli_run.hpp"
#include "input_output_tips.hpp"
#include "temp_dir.hpp"
#include "test_paths.hpp"
#include "text_file.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/read/gcode/gcode_cl_reader.hpp"

using namespace ncpost;
using namespace ncpost::test;

namespace {

PostRun post(const std::string& input, const std::string& dialect, const std::string& name = "in.nc") {
  const std::string dir = make_temp_dir("tool_offsets");
  const std::string in = write_text_file(dir + "/" + name, input);
  return run_post("--machine " + source("machines/vmcl600.toml") + " --tolerance none --dialect " + dialect, in,
                  dir + "/out.nc", dir + "/log");
}

/// The value of `letter` in the first line of `program` that starts with `head` (e.g. "G10 L12 P1").
std::optional<double> word_after(const std::string& program, const std::string& head, char letter) {
  std::istringstream in(program);
  for (std::string line; std::getline(in, line);) {
    const auto at = line.find(head);
    if (at == std::string::npos) continue;
    const auto w = line.find(std::string(" ") + letter, at + head.size());
    if (w == std::string::npos) return std::nullopt;
    return std::stod(line.substr(w + 2));
  }
  return std::nullopt;
}

std::size_t line_of(const std::string& program, const std::string& text) {
  const auto at = program.find(text);
  return at == std::string::npos
             ? std::string::npos
             : static_cast<std::size_t>(std::count(program.begin(), program.begin() + static_cast<long>(at), '\n'));
}

ControlSpec g54_zero(bool linuxcnc) {
  ControlSpec spec;
  spec.linuxcnc = linuxcnc;
  spec.offsets["G54"] = {{'X', 0.0}, {'Y', 0.0}, {'Z', 0.0}};
  return spec;
}

}  // namespace

TEST_CASE("tool offsets: Fanuc G10 L10 / L12 are written again before the G43 H that uses them") {
  const std::string input =
      "%\nO0001\nG21 G90 G17 G94\nG10 L10 P1 R152.5\nG10 L12 P1 R4.\nT1 M6\nG43 H1 Z50.\nG0 X0 Y0\nG1 Z-2. F200\n"
      "G41 D1 X20.\nY20.\nG40 X0 Y0\nG0 Z50.\nM30\n%\n";
  const PostRun p = post(input, "fanuc");
  INFO(p.log);
  REQUIRE(p.exit_code == 0);
  // the values as the program gives them (mm): the length 152.5, the radius 4
  REQUIRE(word_after(p.program, "G10 L10 P1", 'R'));
  CHECK(*word_after(p.program, "G10 L10 P1", 'R') == Approx(152.5).margin(1e-9));
  REQUIRE(word_after(p.program, "G10 L12 P1", 'R'));
  CHECK(*word_after(p.program, "G10 L12 P1", 'R') == Approx(4.0).margin(1e-9));
  CHECK(line_of(p.program, "G10 L10 P1") < line_of(p.program, "H1"));
  CHECK(compare_tips(input, g54_zero(false), "G54", "vmcl600.toml", p.program) == 6);
}

TEST_CASE("tool offsets: LinuxCNC G10 L1 in inches is the tool table's entry in mm; Haas L12 is a diameter") {
  // R.125 in = 3.175 mm radius; the length Z0
  const std::string linuxcnc =
      "G20 G90 G17\nG10 L1 P1 Z0.0 R.125\nT1 M6\nG43\nG0 X0 Y0 Z.5\nG1 Z-.1 F10\nX1.\nG0 Z.5\nM2\n";
  const PostRun l = post(linuxcnc, "linuxcnc", "in.ngc");
  INFO(l.log);
  REQUIRE(l.exit_code == 0);
  REQUIRE(word_after(l.program, "G10 L1 P1", 'R'));
  CHECK(*word_after(l.program, "G10 L1 P1", 'R') == Approx(3.175).margin(1e-9));
  REQUIRE(word_after(l.program, "G10 L1 P1", 'Z'));
  CHECK(*word_after(l.program, "G10 L1 P1", 'Z') == Approx(0.0).margin(1e-9));
  CHECK(compare_tips(linuxcnc, g54_zero(true), "G54", "vmcl600.toml", l.program) == 4);
  // Haas: G10 L12 R10. is a 10 mm diameter, written again as the diameter; the radius alone
  // (LinuxCNC's form) keeps the length: no Z word
  const std::string haas = "G21 G90 G17\nG10 L12 P3 R10.\nT3 M6\nG43 H3 Z20.\nG0 X5 Y5\nG1 Z0 F100\nG0 Z20.\nM30\n";
  const PostRun h = post(haas, "haas");
  INFO(h.log);
  REQUIRE(h.exit_code == 0);
  REQUIRE(word_after(h.program, "G10 L12 P3", 'R'));
  CHECK(*word_after(h.program, "G10 L12 P3", 'R') == Approx(10.0).margin(1e-9));
  CHECK(h.program.find("G10 L10 P3") == std::string::npos);
  CHECK(compare_tips(haas, g54_zero(false), "G54", "vmcl600.toml", h.program) == 3);
  const PostRun radius_only = post("G21 G90\nG10 L1 P2 R3.\nG0 X0 Y0 Z5\nM2\n", "linuxcnc", "r.ngc");
  REQUIRE(radius_only.exit_code == 0);
  REQUIRE(word_after(radius_only.program, "G10 L1 P2", 'R'));
  CHECK(*word_after(radius_only.program, "G10 L1 P2", 'R') == Approx(3.0).margin(1e-9));
  CHECK_FALSE(word_after(radius_only.program, "G10 L1 P2", 'Z'));
}

TEST_CASE("tool offsets: wear, LinuxCNC's L10, no dialect and a dialect without set_offset are refused") {
  const PostRun wear = post("G21 G90\nG10 L11 P1 R-.02\nG0 X0 Y0 Z5\nM30\n", "fanuc");
  CHECK(wear.exit_code == 2);
  CHECK_THAT(wear.log, Catch::Contains("in.nc:2:1") && Catch::Contains("length wear of register 1"));
  const PostRun reading = post("G21 G90\nG0 X0 Y0 Z5\nG10 L10 P1 Z0\nM2\n", "linuxcnc", "in.ngc");
  CHECK(reading.exit_code == 2);
  CHECK_THAT(reading.log, Catch::Contains("from where Z stands"));
  const PostRun unknown = post("G21 G90\nG10 L10 P1 R100.\nG0 X0 Y0 Z5\nM30\n", "heidenhain");
  CHECK(unknown.exit_code == 2);
  CHECK_THAT(unknown.log, Catch::Contains("tool table") && Catch::Contains("[input] tool_offsets"));
  // a copy of the fanuc dialect without [tool] set_offset reads the block but cannot write it
  const std::string dir = make_temp_dir("tool_offsets_dialect");
  std::string fanuc = read_text_file(source("postproc/dialects/fanuc.toml"));
  const auto at = fanuc.find("set_offset = ");
  REQUIRE(at != std::string::npos);
  fanuc.erase(at, fanuc.find('\n', at) - at);
  const std::string dialect = write_text_file(dir + "/no-set.toml", fanuc);
  const PostRun cannot = post("G21 G90\nG10 L10 P1 R100.\nG0 X0 Y0 Z5\nM30\n", dialect);
  CHECK(cannot.exit_code == 2);
  CHECK_THAT(cannot.log, Catch::Contains("cannot write") && Catch::Contains("set_offset"));
  CHECK(cannot.program.empty());
}

TEST_CASE("tool offsets: on a head machine the length set must be the reading's --tool-length") {
  const Machine m = load_machine(source("machines/head-table-bc.toml"));
  Setup s;
  s.tool_length_mm = 150.0;
  gcode::GcodeReaderOptions o;
  o.kind = gcode::InputKind::machine;
  o.control = cl::ControlFamily::fanuc;
  o.tool_offset_writes = {{10, cl::ToolOffsetWrite::length}, {12, cl::ToolOffsetWrite::radius}};
  o.check_limits = false;  // the reading is what is tested, not whether Z100 fits
  const auto read = [&](const std::string& text) {
    std::istringstream in(text);
    gcode::GcodeClReader r(in, "h.nc", m, s, o);
    while (r.next()) {
    }
  };
  try {
    read("G21 G90\nG10 L10 P1 R100.\nT1 M6\nG0 G43 H1 Z100.\nX0 Y0 B0 C0\nM30\n");
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.where().line == 4);
    CHECK_THAT(e.detail(), Catch::Contains("--tool-length 100.0000"));
  }
  CHECK_NOTHROW(read("G21 G90\nG10 L10 P1 R150.\nT1 M6\nG0 G43 H1 Z100.\nX0 Y0 B0 C0\nM30\n"));
}
