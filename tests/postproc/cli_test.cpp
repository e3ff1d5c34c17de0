// SPDX-License-Identifier: Apache-2.0
// The ncpost executable: exit codes of docs/cli.md, atomic output, help for every subcommand.
#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

#include "test_paths.hpp"

namespace {

int run(const std::string& args, std::string* err = nullptr) {
  const std::string cmd = std::string(NCPOST_BINARY) + " " + args + " >cli_test.out 2>cli_test.err";
  const int rc = std::system(cmd.c_str());
  if (err) {
    std::ifstream e("cli_test.err");
    std::stringstream s;
    s << e.rdbuf();
    *err = s.str();
  }
  return WEXITSTATUS(rc);
}

bool exists(const std::string& p) { return std::ifstream(p).good(); }

void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

}  // namespace

using ncpost::test::data;
using ncpost::test::source;

TEST_CASE("help for ncpost and every subcommand") {
  CHECK(run("--help") == 0);
  for (const char* sub : {"post", "preview", "identify", "simulate", "plan", "sensitivity"}) {
    INFO(sub);
    CHECK(run(std::string(sub) + " --help") == 0);
  }
}

TEST_CASE("exit codes: usage 1, bad input 2, infeasible 3; no partial output") {
  const std::string machine = source("machines/ac-trunnion.toml");
  std::string err;
  CHECK(run("post --bogus", &err) == 1);
  CHECK(run("post --machine " + machine, &err) == 1);  // missing INPUT

  write("cli_bad.cls", "GOTO/1,2,3\nGOTO/1,2.5.3,4\n");
  write("cli_out.nc", "GOOD OLD PROGRAM\n");
  CHECK(run("post --machine " + machine + " -o cli_out.nc cli_bad.cls", &err) == 2);
  CHECK_THAT(err, Catch::Contains("cli_bad.cls:2:") && Catch::Contains("^"));
  std::ifstream old("cli_out.nc");
  std::string first;
  std::getline(old, first);
  CHECK(first == "GOOD OLD PROGRAM");  // not clobbered

  write("cli_bad_machine.toml", "[machine]\nname = \"x\"\n");
  CHECK(run("post --machine cli_bad_machine.toml cli_bad.cls", &err) == 2);
  CHECK_THAT(err, Catch::Contains("cli_bad_machine.toml"));

  // a tool axis tilted 150 deg is beyond A's limits [-120, 120] in both solutions
  write("cli_far.cls", "GOTO/0,0,0,0,0.5,-0.8660254\n");
  CHECK(run("post --machine " + machine + " -o cli_new.nc cli_far.cls", &err) == 3);
  CHECK_THAT(err, Catch::Contains("cli_far.cls:1"));
  CHECK_FALSE(exists("cli_new.nc"));
}

TEST_CASE("post writes a program in each dialect") {
  for (const char* d : {"fanuc", "haas", "linuxcnc", "sinumerik", "heidenhain"}) {
    INFO(d);
    CHECK(run(std::string("post --machine ") + data("scenarios/public-clean/machine.toml") +
              " --workpiece-origin 0,0,80 --dialect " + d +
              // Klartext has no inverse-time feed: simultaneous five-axis moves need M128 (--rtcp)
              (std::string(d) == "heidenhain" ? " --rtcp" : "") + " -o cli_dialect.nc " +
              data("scenarios/public-clean/path.cls")) == 0);
    std::ifstream in("cli_dialect.nc");
    std::stringstream s;
    s << in.rdbuf();
    const std::string text = s.str();
    CHECK(text.size() > 10000);
    if (std::string(d) == "heidenhain")
      CHECK_THAT(text, Catch::Contains("BEGIN PGM") && Catch::Contains("L X"));
    else
      CHECK_THAT(text, Catch::Contains("G1") && Catch::Contains("G93"));
  }
}

TEST_CASE("post --model --tolerance --verify-on --report: before/after printed, program and report written") {
  const std::string d = data("scenarios/public-clean/");
  std::string err;
  REQUIRE(run("identify --machine " + d + "machine.toml --no-diagnose -o cli_model.json " + d + "ballbar_h250.csv " +
              d + "ballbar_h300.csv " + d + "sphere.csv") == 0);
  std::remove("cli_post_model.nc");
  std::remove("cli_post_report.html");
  CHECK(run("post --machine " + d +
                "machine.toml --workpiece-origin 0,0,80 --model cli_model.json --tolerance 0.005 "
                "--verify-on " +
                d + "truth.json --report cli_post_report.html -o cli_post_model.nc " + d + "path.cls",
            &err) == 0);
  CHECK_THAT(err, Catch::Contains("before") && Catch::Contains("after") && Catch::Contains("truth.json"));
  CHECK(exists("cli_post_model.nc"));
  std::ifstream report("cli_post_report.html");
  std::stringstream html;
  html << report.rdbuf();
  CHECK_THAT(html.str(), Catch::Contains("<svg") && Catch::Contains("largest contour error"));
  // the after figure printed is under the tolerance, the before one far above it
  const auto after = err.find("after");
  REQUIRE(after != std::string::npos);
  const auto mm = err.find("largest contour error ", after);
  REQUIRE(mm != std::string::npos);
  CHECK(std::stod(err.substr(mm + 22)) < 0.005);

  // a model naming a parameter the machine lacks: bad input, nothing written, old files kept
  write("cli_bad_model.json", "{\"machine\":\"x\",\"parameters\":{\"EX0B\":0.01}}");
  write("cli_keep.nc", "GOOD OLD PROGRAM\n");
  CHECK(run("post --machine " + d + "machine.toml --model cli_bad_model.json --tolerance 0.005 -o cli_keep.nc " + d +
                "path.cls",
            &err) == 2);
  CHECK_THAT(err, Catch::Contains("cli_bad_model.json"));
  std::ifstream kept("cli_keep.nc");
  std::string first;
  std::getline(kept, first);
  CHECK(first == "GOOD OLD PROGRAM");
}

namespace {

/// The CL lines of the retract notices in `err`, in order.
std::vector<int> retract_lines(const std::string& err) {
  std::vector<int> lines;
  const std::string tail = ": the axis limits force a change of solution";
  for (auto at = err.find(tail); at != std::string::npos; at = err.find(tail, at + 1)) {
    const auto colon = err.rfind(':', at - 1);
    lines.push_back(std::stoi(err.substr(colon + 1, at - colon - 1)));
  }
  return lines;
}

double after_contour_mm(const std::string& err) {
  const auto after = err.find("after");
  REQUIRE(after != std::string::npos);
  const auto mm = err.find("largest contour error ", after);
  REQUIRE(mm != std::string::npos);
  return std::stod(err.substr(mm + 22));
}

}  // namespace

TEST_CASE("post: a limit-forced change of solution retracts, or fails with --retract 0") {
  // the BC head's C is limited to +-360 deg: the spiral of the hemisphere sample (~6 turns of C)
  // runs into it. Greedy (each motion nearest the previous): at +360 deg B flips its sign and C
  // turns back 180 deg, 10 times (first at line 83). Planned ahead (the default), from the rapid
  // at line 8 (C -360 there instead of 0): C turns back a whole turn, B keeps its sign: 2 changes,
  // at lines 155 and 299.
  const std::string args = "post --machine " + source("machines/gantry-bc-head.toml") +
                           " --workpiece-origin 0,0,-300 --tool-length 120 --verify ";
  std::string err;
  std::remove("cli_bc.nc");
  // no retract allowed: no plan avoids every change, the post fails at the greedy path's first
  for (const char* plan : {"lookahead", "greedy"}) {
    INFO(plan);
    CHECK(run(args + "--branch-plan " + plan + " --retract 0 -o cli_bc.nc " + source("samples/hemisphere_5axis.cls"),
              &err) == 3);
    CHECK_THAT(err, Catch::Contains("hemisphere_5axis.cls:83") && Catch::Contains("no retract"));
    CHECK_FALSE(exists("cli_bc.nc"));
  }

  CHECK(run(args + "--branch-plan greedy --retract 40 -o cli_bc.nc " + source("samples/hemisphere_5axis.cls"), &err) ==
        0);
  CHECK(retract_lines(err) == std::vector<int>{83, 119, 155, 191, 227, 263, 299, 335, 371, 407});
  CHECK(after_contour_mm(err) < 1.0);
  CHECK(run(args + "--branch-plan lookahead --retract 40 -o cli_bc.nc " + source("samples/hemisphere_5axis.cls"),
            &err) == 0);
  CHECK_THAT(err, Catch::Contains("hemisphere_5axis.cls:155: the axis limits force a change of solution"));
  CHECK_THAT(err, Catch::Contains("lines 8 to 442 are planned ahead") &&
                      Catch::Contains("2 changes of solution there instead of 10"));
  CHECK(retract_lines(err) == std::vector<int>{155, 299});
  std::ifstream in("cli_bc.nc");
  std::stringstream s;
  s << in.rdbuf();
  CHECK_THAT(s.str(), Catch::Contains("retract, reorient, re-engage"));
  // re-executed: no block swings through the part (the retract is a feed move along the tool axis)
  CHECK(after_contour_mm(err) < 1.0);
}

TEST_CASE("post --model re-posts a machine-axis G-code program the same way") {
  const std::string d = data("scenarios/public-clean/");
  std::string err;
  REQUIRE(run("identify --machine " + d + "machine.toml --no-diagnose -o cli_model2.json " + d + "ballbar_h250.csv " +
              d + "ballbar_h300.csv " + d + "sphere.csv") == 0);
  // the nominal program of the dome (machine axes), then that program re-posted for the actual machine
  REQUIRE(run("post --machine " + d +
              "machine.toml --workpiece-origin 0,0,80 --tolerance 0.002 -o cli_dome_nominal.nc " + d + "path.cls") ==
          0);
  REQUIRE(run("post --machine " + d +
                  "machine.toml --workpiece-origin 0,0,80 --model cli_model2.json --tolerance 0.002 "
                  "--verify-on " +
                  d + "truth.json -o cli_dome_repost.nc cli_dome_nominal.nc",
              &err) == 0);
  // the "after" line (the notice on the program end's G28 also says "after")
  const auto after = err.find("\nafter ");
  REQUIRE(after != std::string::npos);
  const auto before = err.find("largest contour error ");
  const auto mm = err.find("largest contour error ", after);
  INFO(err);
  CHECK(std::stod(err.substr(before + 22)) > 0.05);  // the nominal program on the truth: ~80 um
  CHECK(std::stod(err.substr(mm + 22)) < 0.005);
}
