// SPDX-License-Identifier: Apache-2.0
// The G-code input paths of issues 13.12 and 14.11 through the ncpost executable: exit codes and
// the messages a user reads (file:line, the axis and its limit; G10 with what to do).
#include <catch2/catch.hpp>

#include <stdlib.h>

#include <fstream>
#include <string>

#include "cli_run.hpp"
#include "temp_dir.hpp"
#include "test_paths.hpp"

namespace {

std::string temp_dir() {
  const std::string dir = ncpost::test::make_temp_dir("ncpost_gcode_cli");
  REQUIRE(dir != ".");
  return dir;
}

}  // namespace

TEST_CASE("gcode cli: a program beyond the axis limits exits 3 naming the line, the axis and the limit") {
  const std::string dir = temp_dir();
  const std::string program = dir + "/limits.ngc";
  std::ofstream(program) << "G21 G90\nG0 X0 Y0 Z10 A0 C0\nG1 X10 Z5000 A150 F100\nM30\n";
  for (const char* kind : {"machine", "rtcp", "auto"}) {
    INFO(kind);
    const std::string log = dir + "/" + kind + ".log";
    const int rc = ncpost::test::run_ncpost(std::string("post --input-kind ") + kind + " --machine " +
                                                ncpost::test::source("machines/ac-trunnion.toml") +
                                                " --workpiece-origin 0,0,80 -o " + dir + "/out.nc " + program,
                                            log);
    const std::string text = ncpost::test::read_text_file(log);
    INFO(text);
    CHECK(rc == 3);
    CHECK_THAT(text, Catch::Contains("limits.ngc:3:1: A 150.000 deg, beyond the A axis limit 120.000 deg (travel "
                                     "-120.000 .. 120.000 deg) of machine ac-trunnion"));
  }
}

TEST_CASE("gcode cli: the CAMotics botomata program posts in G55, whose values its own G10 L2 sets (notice)") {
  const std::string dir = temp_dir();
  const std::string log = dir + "/botomata.log";
  const int rc = ncpost::test::run_ncpost(
      "post --input-kind rtcp --machine " + ncpost::test::source("machines/vmcl600.toml") +
          " --workpiece-origin -100,-40,-100 --tolerance 0.01 --verify --dialect fanuc --integer-words units -o " +
          dir + "/out.nc " + ncpost::test::data("real/camotics_botomata_bottom.nc"),
      log);
  const std::string text = ncpost::test::read_text_file(log);
  INFO(text);
  CHECK(rc == 0);
  CHECK_THAT(text, Catch::Contains("camotics_botomata_bottom.nc:18:1: the posted program moves in the frame of G55, "
                                   "whose values the input's G10 at line 10 sets"));
}
