// SPDX-License-Identifier: Apache-2.0
// Issue 7 on the command line: plan laser → simulate → identify (laser dispatch), exit codes.
#include <catch2/catch.hpp>

#include "cli_run.hpp"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "ncpost/compensation/model_json.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "test_paths.hpp"

namespace fs = std::filesystem;

namespace {

int run(const std::string& args, const std::string& log) { return ncpost::test::run_ncpost(args, log); }
std::string read(const std::string& path) { return ncpost::test::read_text_file(path); }

}  // namespace

TEST_CASE("laser: plan, simulate and identify on the command line", "[laser][cli]") {
  const fs::path dir = fs::temp_directory_path() / ("ncpost_laser_cli_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string d = dir.string() + "/";
  const std::string machine = "--machine " + ncpost::test::source("machines/vmcl600.toml");
  const std::string truth = ncpost::test::source("samples/measurements/vmcl600/truth.json");
  REQUIRE(run("plan " + machine + " laser --axes X --runs 2 -o " + d + "l", d + "log") == 0);
  const std::string nc = read(d + "l.nc");
  // overshoot before −295: the set-up rapid goes there for the first pass, a feed move for the second
  // (axis words are modal in the NC writer's output: Y and Z stay on the line)
  CHECK(nc.find("G0 X-300.0000 Y-105.0000 Z-90.0000\n") != std::string::npos);
  CHECK(nc.find("(run 2 forward pass)\nX-300.0000\nX-295.0000\n") != std::string::npos);
  CHECK(nc.find("X-305") == std::string::npos);  // never beyond the travel
  std::string data;
  int seed = 1;
  for (const char* s :
       {"X1_pos", "X1_strY", "X1_strZ", "X2_pos", "X2_strY", "X2_strZ", "X3_pos", "X3_strY", "X3_strZ"}) {
    REQUIRE(fs::exists(d + "l_" + s + ".csv"));
    REQUIRE(run("simulate " + machine + " --model " + truth + " --noise-um 0.2 --seed " + std::to_string(seed++) +
                    " -o " + d + s + ".csv " + d + "l_" + s + ".csv",
                d + "log") == 0);
    data += " " + d + s + ".csv";
  }
  REQUIRE(run("identify " + machine + " -o " + d + "model.json --report " + d + "r.html" + data, d + "out") == 0);
  const std::string out = read(d + "out");
  CHECK(out.find("ISO 230-2") != std::string::npos);
  // the six functions of X are seen; squareness needs the straightness of Y and Z too
  for (const char* f : {"EXX (", "EYX (", "EZX (", "EAX (", "EBX (", "ECX ("})
    CHECK(out.find(std::string("  ") + f) == std::string::npos);
  CHECK(out.find("EC0Y: needs the straightness EYX and EXY") != std::string::npos);
  const ncpost::Machine m = ncpost::load_machine(ncpost::test::source("machines/vmcl600.toml"));
  const ncpost::comp::ModelFile model = ncpost::comp::read_model_json(d + "model.json", &m);
  CHECK(model.parameters.contains("EXX:t:-295"));
  CHECK(model.parameters.contains("reversal:X"));
  CHECK(std::abs(*model.parameters.get("reversal:X") - 0.004) < 0.0005);
  CHECK(model.extra.contains("laser"));
  // positioning lines only on X: straightness (and roll) reported as not seen, exit 0
  REQUIRE(
      run("identify " + machine + " -o " + d + "pos.json " + d + "X1_pos.csv " + d + "X2_pos.csv " + d + "X3_pos.csv",
          d + "out2") == 0);
  CHECK(read(d + "out2").find("EYX (straightness in Y of X)") != std::string::npos);
  // bad input: a laser row off its line is refused with exit 2
  std::string bad = read(d + "X1_pos.csv");
  bad.replace(bad.find(",-105.00000,"), 12, ",-104.00000,");
  std::ofstream(d + "bad.csv") << bad;
  CHECK(run("identify " + machine + " -o " + d + "bad.json " + d + "bad.csv", d + "out3") == 2);
  CHECK_FALSE(fs::exists(d + "bad.json"));
  fs::remove_all(dir);
}
