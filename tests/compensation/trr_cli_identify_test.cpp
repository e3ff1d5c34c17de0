// SPDX-License-Identifier: Apache-2.0
// The TRR-XY measurement loop through the CLI: plan sphere → simulate → identify → the model
// predicts the true machine; bad probing data fail with file and line.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "ncpost/compensation/trr_identify.hpp"
#include "ncpost/compensation/trr_model.hpp"
#include "ncpost/machines/trr_xy_file.hpp"
#include "cli_run.hpp"
#include "test_paths.hpp"

using namespace ncpost;
using namespace ncpost::trr;

namespace {

/// `ncpost ARGS`: the exit code; `err` (if given) gets what it printed.
int run(const std::string& args, std::string* err = nullptr) {
  const int rc = test::run_ncpost(args, "trr_cli.log");
  if (err) *err = test::read_text_file("trr_cli.log");
  return rc;
}

}  // namespace

TEST_CASE("plan sphere, simulate, identify on the TRR-XY machine") {
  const std::string machine = test::source("machines/trr-xy.toml");
  const trr::Machine m = load_trr_xy_machine(machine);
  Errors truth;
  for (int k = 0; k < kParameterCount; ++k)  // a deterministic spread of signs and sizes
    truth[k] = std::sin(1.7 * k + 0.3) * (Errors::is_angle(k) ? 8e-5 : 0.025);
  std::ofstream("trr_truth.json") << comp::format_model_json(model_from_errors(truth, "trr-xy"));

  REQUIRE(run("plan --machine " + machine + " sphere -o trr_plan") == 0);
  REQUIRE(run("simulate --machine " + machine +
              " --model trr_truth.json --noise-um 0.2 --seed 3 -o trr_data.csv trr_plan.csv") == 0);
  REQUIRE(run("identify --machine " + machine + " --report trr_id.html -o trr_identified.json trr_data.csv") == 0);

  std::ifstream in("trr_identified.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  CHECK(j["identifiability"]["rank"] == 24);
  CHECK(j["identifiability"]["null_space"].size() == 6);
  CHECK(j["fit"]["rms_after_um"].get<double>() < 0.3);
  CHECK(j["fit"]["rms_before_um"].get<double>() > 10.0);
  CHECK_FALSE(j["uncertainty"].contains("dzs_a"));
  CHECK(j["uncertainty"].contains("gp_a"));
  // the report and its one-page summary (issue 25 item 5): the residual and the parameters ± U = 2u
  // as the model file holds them, the undetermined ones and the null space named as limits
  const std::string html = test::read_text_file("trr_id.html"), page = test::read_text_file("trr_id-summary.html");
  CHECK(html.find(fmt::format("{:.3f} / {:.3f} µm", j["fit"]["rms_after_um"].get<double>(),
                              j["fit"]["max_after_um"].get<double>())) != std::string::npos);
  CHECK(html.find("</td><td colspan=\"2\">not determined") != std::string::npos);
  CHECK(html.find("<td class=n>gp_a</td><td colspan") == std::string::npos);
  const std::string row = "<td class=n>gp_a</td><td>";  // gp is an angle: µrad
  const std::size_t at = html.find(row);
  REQUIRE(at != std::string::npos);
  double value = 0, u = 0, U = 0;
  REQUIRE(std::sscanf(html.c_str() + at + row.size(), "%lf</td><td>%lf</td><td>%lf", &value, &u, &U) == 3);
  CHECK(value == Approx(1e6 * j["parameters"]["gp_a"].get<double>()).margin(1e-3));
  CHECK(u == Approx(1e6 * j["uncertainty"]["gp_a"].get<double>()).margin(1e-3));
  CHECK(U == Approx(2.0 * u).margin(2e-3));
  // the parameters without an uncertainty in the model file are the ones the summary calls undetermined
  const std::size_t undetermined = kParameterCount - j["uncertainty"].size();
  CHECK(undetermined >= 6);  // at least one per direction not seen
  CHECK(page.find(fmt::format("{} parameters not determined", undetermined)) != std::string::npos);
  CHECK(page.find("trr_data.csv: measured (date not given)") != std::string::npos);
  CHECK(page.find("approved by") != std::string::npos);
  CHECK(page.find("href=\"trr_id.html\"") != std::string::npos);

  const Kinematics actual(m, truth), model(m, read_errors_json("trr_identified.json")), nominal(m);
  double worst_um = 0.0;
  for (const Vec3d& s : probing_poses(m))
    for (double L : {0.0, 50.0, 100.0}) {
      const auto a = predicted_deviation(actual, nominal, s, L), b = predicted_deviation(model, nominal, s, L);
      REQUIRE(a);
      REQUIRE(b);
      worst_um = std::max(worst_um, 1000.0 * (*a - *b).norm());
    }
  CHECK(worst_um < 1.0);
}

TEST_CASE("bad probing data: file and line") {
  const std::string machine = test::source("machines/trr-xy.toml");
  std::ofstream("trr_bad.csv")
      << "# type: sphere\nt,X,Y,U,V,W,stylus,dx,dy,dz\n0,0,0,170,170,170,0,0,0,0\n1,0,0,abc,170,170,0,0,0,0\n";
  std::string err;
  CHECK(run("identify --machine " + machine + " -o trr_never.json trr_bad.csv", &err) == 2);
  CHECK(err.find("trr_bad.csv:4:") != std::string::npos);
  CHECK_FALSE(std::ifstream("trr_never.json").good());
  CHECK(run("plan --machine " + machine + " ballbar-4axis -o trr_never", &err) == 1);
  CHECK(run("identify --machine " + machine + " --params EX0C -o trr_never.json trr_bad.csv", &err) == 1);
}
