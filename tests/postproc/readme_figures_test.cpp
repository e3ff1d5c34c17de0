// SPDX-License-Identifier: Apache-2.0
// The figures the README quotes from runs of the executable, asserted on what the run prints: the
// main job (tools/demo.sh: identify the AC trunnion, post the hemisphere with the model), the
// worked example without RTCP (hemisphere, --tolerance none) and the public-clean worked example
// (identify, post compensated, executed on the truth). A README figure that changes fails here
// first; update the README with it.
#include <catch2/catch.hpp>

#include <string>

#include "cli_run.hpp"
#include "temp_dir.hpp"
#include "test_paths.hpp"

using ncpost::test::data;
using ncpost::test::read_text_file;
using ncpost::test::run_ncpost;
using ncpost::test::source;

namespace {

/// `ncpost identify` on the public-clean measurements into `model` (the worked example's first step);
/// what it printed.
std::string identify_public_clean(const std::string& model, const std::string& log) {
  const std::string S = data("scenarios/public-clean/");
  REQUIRE(run_ncpost("identify --machine " + S + "machine.toml -o " + model + " " + S + "ballbar_h250.csv " + S +
                         "ballbar_h300.csv " + S + "sphere.csv",
                     log) == 0);
  return read_text_file(log);
}

}  // namespace

TEST_CASE("README, Conventions / worked example: the hemisphere with one block per CL motion", "[readme][cli]") {
  const std::string dir = ncpost::test::make_temp_dir("readme_hemisphere");
  const std::string log = dir + "/post.log";
  REQUIRE(run_ncpost("post --machine " + source("machines/ac-trunnion.toml") +
                         " --workpiece-origin 0,0,80 --tolerance none --verify -o " + dir + "/h.nc " +
                         source("samples/hemisphere_5axis.cls"),
                     log) == 0);
  const std::string out = read_text_file(log);
  INFO(out);
  // 435 CL motions, 436 blocks: the last rapid rises in a block of its own before it travels
  CHECK_THAT(out, Catch::Contains("435 CL motions -> 436 blocks"));
  CHECK_THAT(out, Catch::Contains("after  (the written program re-executed, 433 blocks): largest contour error "
                                  "0.0245 mm"));
  CHECK_THAT(out, Catch::Contains("block ends 0.0002 mm"));

  // the public dome path: the nonlinear error that --tolerance is about
  const std::string S = data("scenarios/public-clean/");
  REQUIRE(run_ncpost("post --machine " + S + "machine.toml --workpiece-origin 0,0,80 --tolerance none --verify -o " +
                         dir + "/d.nc " + S + "path.cls",
                     log) == 0);
  const std::string dome = read_text_file(log);
  INFO(dome);
  CHECK_THAT(dome, Catch::Contains("1201 CL motions -> 1201 blocks"));
  CHECK_THAT(dome, Catch::Contains("largest contour error 1.0367 mm"));
}

TEST_CASE("README, main job (tools/demo.sh): identify the AC trunnion, post the hemisphere on the truth",
          "[readme][cli][model]") {
  const std::string dir = ncpost::test::make_temp_dir("readme_demo");
  const std::string S = source("samples/measurements/ac-trunnion/");
  const std::string model = dir + "/model.json", log = dir + "/run.log";
  REQUIRE(run_ncpost("identify --machine " + source("machines/ac-trunnion.toml") + " -o " + model + " " + S +
                         "ballbar_h250_data.csv " + S + "ballbar_h300_data.csv " + S + "sphere_data.csv",
                     log) == 0);
  REQUIRE(run_ncpost("post --machine " + source("machines/ac-trunnion.toml") + " --workpiece-origin 0,0,80 --model " +
                         model + " --tolerance 0.002 --verify-on " + S + "truth.json -o " + dir +
                         "/hemisphere_5axis.nc " + source("samples/hemisphere_5axis.cls"),
                     log) == 0);
  const std::string out = read_text_file(log);
  INFO(out);
  CHECK_THAT(out, Catch::Contains("largest contour error 0.0464 mm (CL line 64), mean 0.0312 mm over 433 blocks"));
  CHECK_THAT(out, Catch::Contains("after  (the written program re-executed, 1434 blocks): largest contour error "
                                  "0.0018 mm (CL line 239)"));
}

TEST_CASE("README, worked example: measure, identify, post compensated, cut on the true machine",
          "[readme][cli][model]") {
  const std::string dir = ncpost::test::make_temp_dir("readme_public_clean");
  const std::string S = data("scenarios/public-clean/");
  const std::string model = dir + "/model.json", log = dir + "/run.log";
  const std::string identified = identify_public_clean(model, log);
  INFO(identified);
  // residual 43.5 -> 0.62 µm rms over all sets
  CHECK_THAT(identified, Catch::Matches("[\\s\\S]*\\n  all +43\\.5\\d / [0-9.]+ +0\\.6[12]\\d / [\\s\\S]*"));

  const std::string post = "post --machine " + S +
                           "machine.toml --workpiece-origin 0,0,80 --tolerance 0.002 "
                           "--verify-on " +
                           S + "truth.json ";
  REQUIRE(run_ncpost(post + "--model " + model + " -o " + dir + "/dome.nc " + S + "path.cls", log) == 0);
  const std::string compensated = read_text_file(log);
  INFO(compensated);
  CHECK_THAT(compensated, Catch::Contains("1201 CL motions -> 4017 blocks"));
  CHECK_THAT(compensated, Catch::Contains("re-executed, 4016 blocks): largest contour error 0.0018 mm"));

  REQUIRE(run_ncpost(post + "-o " + dir + "/plain.nc " + S + "path.cls", log) == 0);
  const std::string plain = read_text_file(log);
  INFO(plain);
  // 78.2 µm, 77.6 µm of it at the CL points themselves
  CHECK_THAT(plain, Catch::Contains("largest contour error 0.0782 mm"));
  CHECK_THAT(plain, Catch::Contains("block ends 0.0776 mm"));
}

TEST_CASE("README, branch planning: retracts on the BC head, greedy and planned", "[readme][cli]") {
  const std::string dir = ncpost::test::make_temp_dir("readme_branch_plan");
  struct Case {
    std::string cl;
    std::size_t greedy, planned;
  };
  const Case cases[] = {{source("samples/hemisphere_5axis.cls"), 10, 2},
                        {data("scenarios/public-clean/path.cls"), 19, 5}};
  auto count = [](const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
  };
  for (const Case& c : cases) {
    INFO(c.cl);
    std::string log[2];
    for (int k = 0; k < 2; ++k) {
      const std::string path = dir + "/post" + std::to_string(k) + ".log";
      REQUIRE(run_ncpost("post --machine " + source("machines/gantry-bc-head.toml") +
                             " --workpiece-origin 0,0,-300 --tool-length 120 --retract 40 --verify --branch-plan " +
                             (k == 0 ? "greedy" : "lookahead") + " -o " + dir + "/p.nc " + c.cl,
                         path) == 0);
      log[k] = read_text_file(path);
    }
    const std::string retract = "the axis limits force a change of solution (rotary";
    CHECK(count(log[0], retract) == c.greedy);
    CHECK(count(log[1], retract) == c.planned);
    // the re-executed contour error is the same
    const auto after = [](const std::string& text) {
      const auto at = text.find("largest contour error ", text.find("after"));
      return at == std::string::npos ? std::string() : text.substr(at, 31);
    };
    CHECK_FALSE(after(log[1]).empty());
    CHECK(after(log[0]) == after(log[1]));
  }
}

TEST_CASE("README, worked example: a Heidenhain and a Sinumerik program re-posted with the identified model",
          "[readme][cli][model]") {
  const std::string dir = ncpost::test::make_temp_dir("readme_programs_in");
  const std::string S = data("scenarios/public-clean/");
  const std::string model = dir + "/model.json", log = dir + "/run.log";
  identify_public_clean(model, log);
  const std::string machine = "--machine " + S + "machine.toml --workpiece-origin 0,0,80 ";
  // the dome as the controls' programs: Klartext with M128 (tool tip and A C), Sinumerik in machine axes
  REQUIRE(run_ncpost("post " + machine + "--dialect heidenhain --rtcp -o " + dir + "/dome.h " + S + "path.cls", log) ==
          0);
  REQUIRE(run_ncpost("post " + machine + "--dialect sinumerik -o " + dir + "/dome.mpf " + S + "path.cls", log) == 0);
  CHECK_THAT(read_text_file(log), Catch::Contains("1201 CL motions -> 2114 blocks"));
  const std::string repost = "post " + machine + "--tolerance 0.002 --verify-on " + S + "truth.json ";
  struct Case {
    const char* input;
    const char* motions;
    const char* compensated;
    const char* plain;
  };
  for (const Case& c : {Case{"dome.h", "1201 CL motions -> 4017 blocks", "largest contour error 0.0018 mm",
                             "largest contour error 0.0782 mm"},
                        Case{"dome.mpf", "2114 CL motions -> 4434 blocks", "largest contour error 0.0014 mm",
                             "largest contour error 0.0781 mm"}}) {
    INFO(c.input);
    REQUIRE(run_ncpost(repost + "--model " + model + " -o " + dir + "/re.nc " + dir + "/" + c.input, log) == 0);
    const std::string compensated = read_text_file(log);
    INFO(compensated);
    CHECK_THAT(compensated, Catch::Contains(c.motions));
    CHECK_THAT(compensated, Catch::Contains(c.compensated));
    REQUIRE(run_ncpost(repost + "-o " + dir + "/plain.nc " + dir + "/" + c.input, log) == 0);
    const std::string plain = read_text_file(log);
    INFO(plain);
    CHECK_THAT(plain, Catch::Contains(c.plain));
  }
}
