// SPDX-License-Identifier: Apache-2.0
// Issue 17: effects the old catalogue did not hold. Data from the project's simulator (plan +
// simulate, the sphere swept every 10° of C, 0.5 µm noise), public-clean's location errors plus
// one effect the analysis is not told about.
#include <catch2/catch.hpp>

#include "diagnose_open_support.hpp"

using namespace ncpost;
using namespace ncpost::test;

namespace {

double rms_of(const Eigen::VectorXd& r_mm) { return 1e3 * std::sqrt(r_mm.squaredNorm() / double(r_mm.size())); }

void no_false_attribution(const comp::DiagnoseResult& d) {
  const std::vector<std::string> wrong = false_terms(d);
  INFO("false terms added: " << wrong.size() << (wrong.empty() ? "" : " first " + wrong.front()));
  CHECK(wrong.empty());
  CHECK_FALSE(has_effect(d, "sphere:position"));
}

}  // namespace

TEST_CASE("ECC six per revolution is found by name, at the noise, nothing else added", "[diagnose][open]") {
  const Machine m = public_machine();
  comp::ErrorParameters extra;
  extra.set("ECC:h6:cos", 30e-6);
  extra.set("ECC:h6:sin", -20e-6);
  const auto sets = simulate_plan(m, open_plan(m), truth_with(m, extra), 0.5, 11);
  const comp::DiagnoseResult d = run_diagnose("ECC:h6", m, sets);
  REQUIRE(d.added.size() == 1);
  CHECK(d.added.front().candidate.effect == "ECC:h6");
  const auto& v = d.added.front().values;
  const auto& u = d.added.front().uncertainty;
  CHECK(std::abs(*v.get("ECC:h6:cos") - 30e-6) < 3.0 * *u.get("ECC:h6:cos"));
  CHECK(std::abs(*v.get("ECC:h6:sin") + 20e-6) < 3.0 * *u.get("ECC:h6:sin"));
  CHECK(d.final_fit.rms_after_um < 1.2 * 0.5);
  CHECK(d.basic.rms_after_um > 3.0 * 0.5);
  CHECK(d.unexplained.empty());
  no_false_attribution(d);
}

TEST_CASE("A local bump of ECC is modelled as C's table, at the noise, no harmonics or cross terms",
          "[diagnose][open]") {
  const Machine m = public_machine();
  const comp::ErrorParameters truth = truth_with(m, ecc_bump(40e-6, 120.0, 12.0));
  const auto sets = simulate_plan(m, open_plan(m), truth, 0.5, 11);
  const comp::DiagnoseResult d = run_diagnose("ECC bump", m, sets);
  REQUIRE(d.added.size() == 1);
  CHECK(d.added.front().candidate.effect == "ECC:t");
  for (const auto& a : d.added) CHECK(a.candidate.effect.rfind("ECC:h", 0) == std::string::npos);
  CHECK(d.final_fit.rms_after_um < 1.2 * 0.5);
  CHECK(d.unexplained.empty());
  no_false_attribution(d);
  // the table at the bump's top (node 120°) and far from it (node 300°): the truth within 3σ
  const auto& v = d.added.front().values;
  const auto& u = d.added.front().uncertainty;
  CHECK(std::abs(*v.get("ECC:t:120") - 40e-6) < 3.0 * *u.get("ECC:t:120") + 1e-6);
  CHECK(std::abs(*v.get("ECC:t:300")) < 3.0 * *u.get("ECC:t:300") + 1e-6);
  // the post uses the table like a linear axis's: the machine with the identified table predicts
  // the truth's tool tip at the dome path's poses
  comp::ErrorParameters model = d.final_fit.parameters;
  double truth_error = 0.0;
  const double off_um = worst_prediction_um(m, truth, model, &truth_error);
  std::printf("  identified table vs the truth over the working space: %.3f um (truth off nominal %.1f um)\n", off_um,
              truth_error);
  CHECK(off_um < 0.1 * truth_error);
}
