// SPDX-License-Identifier: Apache-2.0
// ncpost plan → simulate → identify end to end, exit codes and atomic outputs (docs/cli.md).
#include <catch2/catch.hpp>

#include "cli_run.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "ncpost/compensation/model_json.hpp"

namespace fs = std::filesystem;

namespace {

int run(const std::string& args, const std::string& log) { return ncpost::test::run_ncpost(args, log); }
std::string read(const std::string& path) { return ncpost::test::read_text_file(path); }

}  // namespace

TEST_CASE("plan, simulate and identify on the command line") {
  const fs::path dir = fs::temp_directory_path() / ("ncpost_cli_errmodel_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string d = dir.string() + "/";
  const std::string clean = std::string(NCPOST_SOURCE_DIR) + "/tests/data/scenarios/public-clean/";
  const std::string machine = "--machine " + clean + "machine.toml";
  REQUIRE(run("plan " + machine + " ballbar-4axis --height 250 300 -o " + d + "bb", d + "log") == 0);
  CHECK(fs::exists(d + "bb_h250.csv"));
  CHECK(fs::exists(d + "bb_h300.csv"));
  // the Fanuc dialect's 4 decimals, the plan rounded to them (was Y-1.57709 Z249.99503 A0.36145 C0.72289); X0 is modal
  CHECK(read(d + "bb.nc").find("G93 G1 Y-1.5771 Z249.9950 A0.3614 C0.7229 F120.0000") != std::string::npos);
  REQUIRE(run("plan " + machine + " sphere --t0 619 -o " + d + "sph.csv", d + "log") == 0);
  for (const char* f : {"bb_h250", "bb_h300", "sph"})
    REQUIRE(run("simulate " + machine + " --model " + clean + "truth.json --noise-um 0.5 --seed 4 -o " + d + f +
                    "_data.csv " + d + f + ".csv",
                d + "log") == 0);
  REQUIRE(run("identify " + machine + " --report " + d + "r.html -o " + d + "model.json " + d + "bb_h250_data.csv " +
                  d + "bb_h300_data.csv " + d + "sph_data.csv",
              d + "log") == 0);
  const std::string report = read(d + "log");
  CHECK(report.find("rank 8 of 10") != std::string::npos);
  const ncpost::comp::ModelFile m = ncpost::comp::read_model_json(d + "model.json", nullptr);
  CHECK(std::abs(*m.parameters.get("EY0C") - (-0.022)) < 3e-4);
  CHECK(m.identifiability->pinned == std::vector<std::string>{"EA0A", "EC0C"});
  CHECK(read(d + "r.html").find("<svg") != std::string::npos);

  SECTION("exit codes; failed runs leave the output alone") {
    std::ofstream(d + "keep.json") << "good";
    CHECK(run("identify " + machine + " -o " + d + "keep.json " + d + "missing.csv", d + "log") == 2);
    CHECK(read(d + "keep.json") == "good");
    std::ofstream(d + "bad.json") << "{\"parameters\": {\"EQ0C\": 1}}";
    CHECK(run("simulate " + machine + " --model " + d + "bad.json -o " + d + "keep.json " + d + "bb_h250.csv",
              d + "log") == 2);
    CHECK(read(d + "log").find("bad.json:1") != std::string::npos);
    CHECK(read(d + "keep.json") == "good");
    CHECK(run("identify " + machine + " --bogus -o x.json a.csv", d + "log") == 1);
    CHECK(run("plan " + machine + " bc-head -o " + d + "x", d + "log") == 3);  // not a BC head
  }
  fs::remove_all(dir);
}
