// SPDX-License-Identifier: Apache-2.0
// Issue 13 item 9: "no solution within the axis limits" names, for each solution, the axis that
// leaves its travel, the value it would need and its limits — so that a user whose Z travel is
// short does not blame B/C — in `post` and in `preview`, both with the tip and axis of the point.
#include <catch2/catch.hpp>

#include <string>

#include "cli_run.hpp"
#include "temp_dir.hpp"
#include "test_paths.hpp"

namespace {

struct Run {
  int rc = -1;
  std::string messages;
};

Run run(const std::string& command, const std::string& machine, const std::string& cl) {
  static const std::string dir = ncpost::test::make_temp_dir("ncpost_unreachable");
  const std::string input = ncpost::test::write_text_file(dir + "/p.apt", cl);
  Run r;
  r.rc = ncpost::test::run_ncpost(command + " --machine " + ncpost::test::source("machines/" + machine + ".toml") +
                                      " --workpiece-origin 0,0,80 " + input +
                                      (command == "post" ? " -o " + dir + "/out.nc" : std::string()),
                                  dir + "/log");
  r.messages = ncpost::test::read_text_file(dir + "/log");
  return r;
}

const char* const kTooHigh = "UNITS/MM\nMULTAX/ON\nFEDRAT/500\nGOTO/0,0,10,0,0,1\nGOTO/0,0,700,0,0,1\nFINI\n";
// tilted 130° from vertical toward +X: B would have to be ±130°, the UMC-750's B travel is -35…120°
const char* const kTooTilted =
    "UNITS/MM\nMULTAX/ON\nFEDRAT/500\nGOTO/0,0,10,0,0,1\nGOTO/0,0,10,0.7660444,0,-0.6427876\nFINI\n";

}  // namespace

TEST_CASE("no solution within the limits: the linear axis, its value and its limits", "[post][limits]") {
  for (const char* command : {"post", "preview"}) {
    INFO(command);
    const Run r = run(command, "ac-trunnion", kTooHigh);
    CHECK(r.rc == 3);
    // Z of M = 700 mm in W + 80 mm origin; ac-trunnion Z travel is ±600 mm
    CHECK_THAT(r.messages,
               Catch::Contains("p.apt:5: no solution within the axis limits: with A 0.000° C 0.000°: Z would "
                               "be 780.000 mm (limits -600.000 to 600.000 mm) (tip 0.0000, 0.0000, "
                               "700.0000 mm, axis 0.000000, 0.000000, 1.000000)"));
    CHECK_THAT(r.messages, Catch::Contains("check --workpiece-origin and the tool length"));
  }
}

TEST_CASE("no solution within the limits: the rotary axis of each solution", "[post][limits]") {
  const Run r = run("post", "haas-umc750", kTooTilted);
  CHECK(r.rc == 3);
  CHECK_THAT(r.messages,
             Catch::Contains("p.apt:5: no solution within the axis limits: "
                             "with B -130.000° C -180.000°: B would be -130.000° (limits -35.000 to 120.000°); "
                             "with B 130.000° C 0.000°: B would be 130.000° (limits -35.000 to 120.000°)"));
  CHECK_THAT(r.messages, !Catch::Contains("check --workpiece-origin"));
}
