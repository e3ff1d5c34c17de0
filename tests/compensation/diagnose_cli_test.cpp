// SPDX-License-Identifier: Apache-2.0
// The worked example of compensation/DIAGNOSE.md on the command line: `ncpost plan` and
// `ncpost simulate` make the public scenarios' measurements on a machine with a cyclic angular
// error of C (ECC:h2) and a warm-up drift along Z that the analysis is not told about;
// `ncpost identify` finds both, writes effects_added and fit (docs/formats.md), and the report shows
// the residual before and after. `--no-diagnose` keeps the basic model.
#include <catch2/catch.hpp>

#include "cli_run.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "diagnose_support.hpp"
#include "ncpost/compensation/model_json.hpp"

namespace fs = std::filesystem;

namespace {

int run(const std::string& args, const std::string& log) { return ncpost::test::run_ncpost(args, log); }
std::string read(const std::string& path) { return ncpost::test::read_text_file(path); }

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST_CASE("identify on the command line: effects found, before / after, measuring-only effects marked",
          "[diagnose][cli]") {
  const fs::path dir = fs::temp_directory_path() / ("ncpost_diagnose_cli_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string d = dir.string() + "/";
  const std::string machine =
      "--machine " + std::string(NCPOST_SOURCE_DIR) + "/tests/data/scenarios/public-clean/machine.toml";
  std::ofstream(d + "truth.json") << R"({"machine": "public-clean", "parameters": {
    "EY0A": 0.018, "EZ0A": -0.012, "EB0A": 4e-05, "EC0A": -2.5e-05,
    "EX0C": 0.015, "EY0C": -0.022, "EA0C": 3e-05, "EB0C": -3.5e-05,
    "ECC:h2:cos": 4e-05, "ECC:h2:sin": 3e-05, "drift:Z:t:exp": 0.012, "drift:Z:t:tau": 900}})";
  REQUIRE(run("plan " + machine + " ballbar-4axis --height 250 --height 300 -o " + d + "ballbar", d + "log") == 0);
  REQUIRE(run("plan " + machine + " sphere --t0 619 -o " + d + "sphere", d + "log") == 0);
  for (const char* f : {"ballbar_h250", "ballbar_h300", "sphere"})
    REQUIRE(run("simulate " + machine + " --model " + d + "truth.json --noise-um 0.5 --seed 11 -o " + d + f +
                    "_data.csv " + d + f + ".csv",
                d + "log") == 0);
  const std::string data = d + "ballbar_h250_data.csv " + d + "ballbar_h300_data.csv " + d + "sphere_data.csv";

  REQUIRE(run("identify " + machine + " --report " + d + "report.html -o " + d + "model.json " + data, d + "log") == 0);
  const std::string text = read(d + "log");
  INFO(text);
  const ncpost::comp::ModelFile model = ncpost::comp::read_model_json(d + "model.json", nullptr);
  CHECK(model.effects_added == std::vector<std::string>{"drift:Z:t", "ECC:h2"});
  REQUIRE(model.fit);
  CHECK(model.fit->rms_before_um > 2.0);
  CHECK(model.fit->rms_after_um < 0.55);
  CHECK(model.fit->max_after_um < model.fit->max_before_um);
  CHECK(std::abs(*model.parameters.get("ECC:h2:cos") - 4e-5) < 4.0 * *model.uncertainty.get("ECC:h2:cos"));
  CHECK(std::abs(*model.parameters.get("ECC:h2:sin") - 3e-5) < 4.0 * *model.uncertainty.get("ECC:h2:sin"));
  CHECK(model.parameters.contains("drift:Z:t:tau"));
  CHECK(text.find("added ECC:h2") != std::string::npos);
  CHECK(text.find("measuring only, not posted") != std::string::npos);
  CHECK(text.find("predicted tool-tip error") != std::string::npos);
  const std::string html = read(d + "report.html");
  CHECK(html.find("<h1>Residual analysis</h1>") != std::string::npos);
  CHECK(count(html, "<svg") >= 8);  // 2 polar plots, residual against A, C and t

  REQUIRE(run("identify " + machine + " --no-diagnose -o " + d + "basic.json " + data, d + "log") == 0);
  const ncpost::comp::ModelFile basic = ncpost::comp::read_model_json(d + "basic.json", nullptr);
  CHECK(basic.effects_added.empty());
  REQUIRE(basic.fit);
  CHECK(basic.fit->rms_after_um == Approx(model.fit->rms_before_um).epsilon(1e-3));
  CHECK(read(d + "log").find("residual analysis") == std::string::npos);

  // the dome path posted with each model (compensated IK, 5 um adaptive subdivision, 4 decimals),
  // executed on the truth machine (the drift is not part of it: measuring only)
  const ncpost::Machine m = ncpost::test::public_machine();
  const ncpost::comp::ErrorParameters truth = ncpost::comp::read_model_json(d + "truth.json", &m).parameters;
  double ends_final = 0.0, ends_basic = 0.0;
  const double cut_final = ncpost::test::compensated_cut_mm(m, model.parameters, truth, d + "final.nc", &ends_final);
  const double cut_basic = ncpost::test::compensated_cut_mm(m, basic.parameters, truth, d + "basic.nc", &ends_basic);
  std::printf("dome on the truth: basic model %.4f mm (block ends %.4f), final model %.4f mm (block ends %.4f)\n",
              cut_basic, ends_basic, cut_final, ends_final);
  CHECK(cut_final <= 0.006);
  CHECK(ends_final < 0.5e-3);
  CHECK(cut_basic > cut_final);
  fs::remove_all(dir);
}
