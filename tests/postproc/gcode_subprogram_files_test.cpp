// SPDX-License-Identifier: Apache-2.0
// Issue 24: subprograms in other files (docs/formats.md "Subprograms in other files"): M98 P<n>
// finds O<n> in a file O<n>.nc, <n>.nc, ... beside the program or in --subprogram-dir; LinuxCNC
// `o<name> call` finds name.ngc there; messages name each file of the call chain. Also Fanuc's
// M99 P<n> (back to block N<n> of the caller) and Haas G154 P<n> (= G54.1 P<n>). Every posting
// case executes the INPUT with the tests' control interpreter (the files given to it as well) and
// the OUTPUT with nc_executor.hpp, the tip within 1 µm at every input block end.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "cli_run.hpp"
#include "input_output_tips.hpp"
#include "temp_dir.hpp"
#include "test_paths.hpp"
#include "text_file.hpp"

using namespace ncpost;
using namespace ncpost::test;

namespace {

/// Posts `main` (named `name`) with `files` written beside it (or into `sub_dir` of the same
/// temporary directory, then given as --subprogram-dir).
PostRun post_with_files(const std::string& main, const std::string& name,
                        const std::map<std::string, std::string>& files, const std::string& dialect,
                        const std::string& sub_dir = "", const std::string& extra = "") {
  const std::string dir = make_temp_dir("subprogram_files");
  std::string where = dir;
  if (!sub_dir.empty()) {
    where = dir + "/" + sub_dir;
    std::filesystem::create_directories(where);
  }
  for (const auto& [file, text] : files) write_text_file(where + "/" + file, text);
  const std::string in = write_text_file(dir + "/" + name, main);
  std::string args = "--machine " + source("machines/vmcl600.toml") + " --tolerance none --dialect " + dialect;
  if (!sub_dir.empty()) args += " --subprogram-dir " + where;
  return run_post(args + " " + extra, in, dir + "/out.nc", dir + "/log");
}

ControlSpec spec_with(const std::map<std::string, std::string>& files, bool linuxcnc) {
  ControlSpec spec;
  spec.linuxcnc = linuxcnc;
  spec.offsets["G54"] = {{'X', 0.0}, {'Y', 0.0}, {'Z', 0.0}};
  spec.files = files;
  return spec;
}

const std::string kFanucMain =
    "%\nO0001\nG21 G90 G17 G94\nG0 X0 Y0 Z10\nG1 Z0 F200\nM98 P1234 L2\nG90 G0 Z10\nM30\n%\n";
const std::string kO1234 = "%\nO1234 (STEP)\nG91 G1 X10\nY5\nG90\nM99\n%\n";

}  // namespace

TEST_CASE("subprogram files: M98 P1234 runs O1234 from O1234.nc beside the program, or from --subprogram-dir") {
  const std::map<std::string, std::string> files{{"O1234.nc", kO1234}};
  const PostRun beside = post_with_files(kFanucMain, "main.nc", files, "fanuc");
  INFO(beside.log);
  REQUIRE(beside.exit_code == 0);
  // ends: 2 + 2 x 2 + 1
  CHECK(compare_tips(kFanucMain, spec_with(files, false), "G54", "vmcl600.toml", beside.program) == 7);
  // 1234.tap in the directory given: the same program
  const std::map<std::string, std::string> numbered{{"1234.tap", kO1234}};
  const PostRun given = post_with_files(kFanucMain, "main.nc", numbered, "fanuc", "subs");
  INFO(given.log);
  REQUIRE(given.exit_code == 0);
  CHECK(compare_tips(kFanucMain, spec_with(numbered, false), "G54", "vmcl600.toml", given.program) == 7);
}

TEST_CASE("subprogram files: LinuxCNC o<drill> call finds drill.ngc, whose own sub calls work too") {
  const std::string main =
      "G21 G90 G17\nG0 X0 Y0 Z10\no<drill> call [10] [5] [-3]\no<drill> call [20] [5] [-4]\nG0 Z10\nM2\n";
  const std::map<std::string, std::string> files{
      {"drill.ngc", "o<drill> sub\n  G0 X#1 Y#2\n  G0 Z2\n  G1 Z#3 F100\n  o<lift> call [3]\no<drill> endsub\nM2\n"},
      {"lift.ngc", "o<lift> sub\n  G0 Z#1\no<lift> endsub\nM2\n"}};
  const PostRun p = post_with_files(main, "part.ngc", files, "linuxcnc");
  INFO(p.log);
  REQUIRE(p.exit_code == 0);
  // ends: 1 + 2 x 4 + 1
  CHECK(compare_tips(main, spec_with(files, true), "G54", "vmcl600.toml", p.program) == 10);
}

TEST_CASE("subprogram files: missing, ambiguous and failing subprogram files are refused naming each file") {
  const PostRun missing = post_with_files(kFanucMain, "main.nc", {}, "fanuc");
  CHECK(missing.exit_code == 2);
  CHECK_THAT(missing.log, Catch::Contains("main.nc:6") && Catch::Contains("M98 P1234") &&
                              Catch::Contains("no file O1234.* or 1234.*") && Catch::Contains("--subprogram-dir"));
  const PostRun two = post_with_files(kFanucMain, "main.nc", {{"O1234.nc", kO1234}, {"1234.tap", kO1234}}, "fanuc");
  CHECK(two.exit_code == 2);
  CHECK_THAT(two.log, Catch::Contains("could both hold O1234"));
  const PostRun wrong = post_with_files(kFanucMain, "main.nc", {{"O1234.nc", "%\nO1235\nM99\n%\n"}}, "fanuc");
  CHECK(wrong.exit_code == 2);
  CHECK_THAT(wrong.log, Catch::Contains("O1234.nc' holds no O1234"));
  // an error on line 3 of drill.ngc names that file and the call in part.ngc
  const PostRun inside =
      post_with_files("G21 G90\nG0 X0 Y0 Z10\no<drill> call [1]\nM2\n", "part.ngc",
                      {{"drill.ngc", "o<drill> sub\n  G0 X#1\n  G1 E5\no<drill> endsub\n"}}, "linuxcnc");
  CHECK(inside.exit_code == 2);
  CHECK_THAT(inside.log, Catch::Contains("drill.ngc:3") && Catch::Contains("via o<drill> call at ") &&
                             Catch::Contains("part.ngc:3"));
}

TEST_CASE("subprogram files: Fanuc M99 P<n> returns to block N<n> of the caller; duplicates are refused") {
  const std::string input =
      "%\nO0001\nG21 G90 G17\nG0 X0 Y0 Z10\nM98 P2000\nN20 G0 X50\nN30 G0 Y40\nM30\nO2000\nG1 Z0 F100\nM99 P30\n%\n";
  const PostRun p = post_with_files(input, "main.nc", {}, "fanuc");
  INFO(p.log);
  REQUIRE(p.exit_code == 0);
  // ends: X0 Y0 Z10, Z0, then N30's Y40 (N20 skipped)
  CHECK(compare_tips(input, spec_with({}, false), "G54", "vmcl600.toml", p.program) == 3);
  CHECK(p.program.find("X50.") == std::string::npos);
  const std::string twice =
      "%\nO0001\nG21 G90\nN30 G0 X0 Y0 Z10\nM98 P2000\nN30 G0 Y40\nM30\nO2000\nG1 Z0 F100\nM99 P30\n%\n";
  const PostRun dup = post_with_files(twice, "main.nc", {}, "fanuc");
  CHECK(dup.exit_code == 2);
  CHECK_THAT(dup.log, Catch::Contains("main.nc:10") && Catch::Contains("N30 at lines 4 and 6"));
  const PostRun none = post_with_files("G21 G90\nG0 X0 Y0 Z10\nM98 P2000\nM30\nO2000\nM99 P77\n", "m.nc", {}, "fanuc");
  CHECK(none.exit_code == 2);
  CHECK_THAT(none.log, Catch::Contains("has no block N77"));
}

TEST_CASE("subprogram files: Haas G154 P5 is G54.1 P5 (values from --work-offsets)") {
  const std::string input = "G21 G90 G17\nG54 G0 X0 Y0 Z10\nG1 Z0 F100\nG154 P5 G1 X5\nY5\nG0 Z10\nM30\n";
  const std::string dir = make_temp_dir("g154");
  const std::string offsets = write_text_file(
      dir + "/o.toml", "[G54]\nX = -200\nY = -100\nZ = -300\n[\"G54.1 P5\"]\nX = -150\nY = -90\nZ = -302\n");
  const PostRun p = post_with_files(input, "g.nc", {}, "haas", "", "--work-offsets " + offsets);
  INFO(p.log);
  REQUIRE(p.exit_code == 0);
  ControlSpec spec = spec_with({}, false);
  spec.offsets["G54"] = {{'X', -200.0}, {'Y', -100.0}, {'Z', -300.0}};
  spec.offsets["G54.1 P5"] = {{'X', -150.0}, {'Y', -90.0}, {'Z', -302.0}};
  CHECK(compare_tips(input, spec, "G54", "vmcl600.toml", p.program) == 5);
  const PostRun beyond = post_with_files("G21 G90\nG154 P100 G0 X0 Y0 Z0\nM30\n", "b.nc", {}, "haas");
  CHECK(beyond.exit_code == 2);
  CHECK_THAT(beyond.log, Catch::Contains("G154 needs P1 .. P99"));
}
