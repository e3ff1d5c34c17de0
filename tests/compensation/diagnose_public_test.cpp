// Residual analysis on the public scenarios: public-ezc holds an axial error motion of C
// (truth.json: EZC:h1) that the basic model lacks — it is found by name and the final model
// predicts the truth's tool-tip deviations within 1 um over the working space (measured as in
// identify_clean_test.cpp); public-clean holds nothing beyond the basic model — nothing is added.
#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "ncpost/compensation/diagnose.hpp"
#include "ncpost/compensation/machine_model.hpp"
#include "ncpost/compensation/measurement_csv.hpp"
#include "ncpost/compensation/model_json.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "diagnose_support.hpp"

using namespace ncpost;
using namespace ncpost::comp;

namespace {

std::vector<MeasurementSet> read_sets(const std::string& dir, const Machine& m) {
  std::vector<MeasurementSet> sets;
  for (const char* f : {"ballbar_h250.csv", "ballbar_h300.csv", "sphere.csv"}) sets.push_back(read_measurement_csv(dir + f, m));
  return sets;
}

}  // namespace

TEST_CASE("diagnose public-ezc: EZC:h1 found, predictions within 1 um of the truth", "[diagnose]") {
  const std::string dir = test::public_scenario("public-ezc");
  const Machine m = load_machine(dir + "machine.toml");
  const ModelFile truth = read_model_json(dir + "truth.json", &m);
  const DiagnoseResult d = test::run_diagnose("public-ezc", m, read_sets(dir, m));
  REQUIRE(d.final_fit.converged);
  CHECK(d.effects_added() == std::vector<std::string>{"EZC:h1"});
  CHECK(d.final_fit.rms_after_um < 0.8);
  CHECK(d.basic.rms_after_um > 2.0 * d.final_fit.rms_after_um);
  for (const char* p : {"EZC:h1:cos", "EZC:h1:sin"}) {
    const double t = *truth.parameters.get(p), v = d.final_fit.parameters.value_or(p, 0.0),
                 u = d.final_fit.uncertainty.value_or(p, 1.0);
    INFO(p << ": identified " << v << " +- " << u << ", truth " << t);
    CHECK(std::abs(v - t) < 4.0 * u + 1e-9);
  }
  double truth_error_um = 0.0;
  const double off_final = test::worst_prediction_um(m, truth.parameters, d.final_fit.parameters, &truth_error_um);
  const double off_basic = test::worst_prediction_um(m, truth.parameters, d.basic.parameters, nullptr);
  printf("public-ezc: truth's tool-tip error up to %.1f um; basic model off by %.3f um, final model by %.3f um\n",
         truth_error_um, off_basic, off_final);
  CHECK(off_final < 1.0);
  CHECK(off_basic > off_final);
  const ModelFile file = to_model_file(m, d);
  CHECK(file.effects_added == std::vector<std::string>{"EZC:h1"});
  REQUIRE(file.fit);
  CHECK(file.fit->rms_before_um == Approx(d.basic.rms_after_um));
  CHECK(file.fit->rms_after_um == Approx(d.final_fit.rms_after_um));
}

TEST_CASE("diagnose public-clean: nothing added", "[diagnose]") {
  const std::string dir = test::public_scenario("public-clean");
  const Machine m = load_machine(dir + "machine.toml");
  const DiagnoseResult d = test::run_diagnose("public-clean", m, read_sets(dir, m));
  CHECK(d.effects_added().empty());
  CHECK(d.final_fit.rms_after_um == Approx(d.basic.rms_after_um));
}

TEST_CASE("diagnose public-ezc: which parameter limits the prediction", "[.debug]") {
  const std::string dir = test::public_scenario("public-ezc");
  const Machine m = load_machine(dir + "machine.toml");
  const ModelFile truth = read_model_json(dir + "truth.json", &m);
  const DiagnoseResult d = test::run_diagnose("public-ezc", m, read_sets(dir, m));
  for (std::size_t i = 0; i < truth.parameters.size(); ++i) {
    const std::string& n = truth.parameters.names()[i];
    ErrorParameters fixed = d.final_fit.parameters;
    fixed.set(n, truth.parameters.values()[i]);
    printf("%-12s truth %.6g fit %.6g +- %.2g (%.1f sigma); prediction with it at truth %.3f um\n", n.c_str(),
           truth.parameters.values()[i], d.final_fit.parameters.value_or(n, 0), d.final_fit.uncertainty.value_or(n, 0),
           (d.final_fit.parameters.value_or(n, 0) - truth.parameters.values()[i]) / d.final_fit.uncertainty.value_or(n, 1),
           test::worst_prediction_um(m, truth.parameters, fixed, nullptr));
  }
  IdentifyResult plain = identify(m, read_sets(dir, m), [&] { auto b = basic_parameters(m); b.push_back("EZC:h1:cos"); b.push_back("EZC:h1:sin"); return b; }());
  printf("unweighted fit: %.3f um\n", test::worst_prediction_um(m, truth.parameters, plain.parameters, nullptr));
}

TEST_CASE("diagnose public-ezc: sphere residual by component", "[.debug2]") {
  const std::string dir = test::public_scenario("public-ezc");
  const Machine m = load_machine(dir + "machine.toml");
  const auto sets = read_sets(dir, m);
  const DiagnoseResult d = test::run_diagnose("public-ezc", m, sets);
  const Eigen::Index at = static_cast<Eigen::Index>(sets[0].rows.size() + sets[1].rows.size());
  for (int c = 0; c < 3; ++c) {
    double s = 0;
    for (std::size_t k = 0; k < sets[2].rows.size(); ++k) s += std::pow(d.residual_after_mm[at + 3 * Eigen::Index(k) + c], 2);
    printf("component %d rms %.3f um\n", c, 1e3 * std::sqrt(s / double(sets[2].rows.size())));
  }
}
