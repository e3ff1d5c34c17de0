// SPDX-License-Identifier: Apache-2.0
// Issue 25 item 4: the ISO 14253-1 decision rule, tolerances per figure kind, and the uncertainty
// budgets (k = 2) of the reported figures, each against a hand calculation written here.
#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

#include "ncpost/compensation/decision_rule.hpp"
#include "ncpost/compensation/measurement_csv.hpp"
#include "ncpost/compensation/uncertainty_budget.hpp"
#include "ncpost/machines/machine_file.hpp"

using namespace ncpost;
using namespace ncpost::comp;

namespace {

Machine ac() { return load_machine(std::string(NCPOST_SOURCE_DIR) + "/machines/ac-trunnion.toml"); }
Machine vmc() { return load_machine(std::string(NCPOST_SOURCE_DIR) + "/machines/vmcl600.toml"); }

MeasurementSet ballbar(const std::string& extra) {
  return parse_measurement_csv(
      "# type: ballbar\n# table_ball: 0, -100, 250\n# tool_ball: 0, 0, 0\n# bar_length: 100.0\n" + extra +
          "t,X,Y,Z,A,C,L\n0.00,0,0,250,0,0,100.001\n",
      "b.csv", ac());
}

const BudgetLine& line(const UncertaintyBudget& b, const std::string& source) {
  for (const auto& l : b.lines)
    if (l.source == source) return l;
  throw std::logic_error("no line " + source);
}

}  // namespace

TEST_CASE("ISO 14253-1: pass only when value + U is within the tolerance", "[decision]") {
  CHECK(decide(8.0, 1.0, 10.0) == Verdict::pass);         // 9 ≤ 10
  CHECK(decide(9.0, 1.0, 10.0) == Verdict::pass);         // 10 ≤ 10: on the limit, still proven
  CHECK(decide(9.5, 1.0, 10.0) == Verdict::not_proven);   // 10.5 > 10 but 8.5 ≤ 10
  CHECK(decide(11.0, 1.0, 10.0) == Verdict::not_proven);  // 10 is not beyond 10
  CHECK(decide(11.5, 1.0, 10.0) == Verdict::fail);        // 10.5 > 10
  CHECK(decide(10.0, 0.0, 10.0) == Verdict::pass);        // no uncertainty: the plain comparison
  CHECK(std::string(to_string(Verdict::not_proven)) == "NOT PROVEN");
}

TEST_CASE("tolerances per figure kind from text", "[decision]") {
  const Tolerances t = parse_tolerances("G=10, A=8.5,R=3");
  CHECK(*t.of("G") == 10.0);
  CHECK(*t.of("A") == 8.5);
  CHECK(*t.of("R") == 3.0);
  CHECK_FALSE(t.of("E"));
  CHECK(parse_tolerances("").empty());
  CHECK_THROWS_WITH(parse_tolerances("Q=3"), Catch::Contains("unknown figure kind 'Q'"));
  CHECK_THROWS_WITH(parse_tolerances("G=-1"), Catch::Contains("positive number"));
  CHECK_THROWS_WITH(parse_tolerances("G=1mm"), Catch::Contains("positive number"));
  CHECK_THROWS_WITH(parse_tolerances("G10"), Catch::Contains("expected KIND=µm"));
  CHECK_THROWS_WITH(parse_tolerances("G=1,G=2"), Catch::Contains("G given twice"));
}

TEST_CASE("budget of one reading: instrument and the 20 °C correction's uncertainty", "[budget]") {
  const MeasurementSet s = ballbar(
      "# temperature: 23.5\n# material_expansion: 11.5e-6\n# instrument_uncertainty: 1.0\n"
      "# temperature_uncertainty: 0.2\n# expansion_uncertainty: 1e-6\n");
  const UncertaintyBudget b = reading_budget(s);
  CHECK(b.complete());
  // instrument: U 1.0 µm (k = 2) → u = 0.5 µm
  CHECK(line(b, "instrument").u_um == Approx(0.5));
  // temperature over the bar (100 mm): 1000 × 100 × √((3.5 × 1e-6)² + (11.5e-6 × 0.2)²)
  //   = 1e5 × √(12.25e-12 + 5.29e-12) = 1e5 × √(17.54e-12) = 1e5 × 4.188078e-6 = 0.4188078 µm
  CHECK(line(b, "temperature").u_um == Approx(0.4188078).epsilon(1e-6));
  // u_c = √(0.25 + 0.1754) = √0.4254 = 0.6522270; U = 1.3044540
  CHECK(b.combined_um() == Approx(0.6522270).epsilon(1e-6));
  CHECK(b.expanded_um() == Approx(1.3044540).epsilon(1e-6));
}

TEST_CASE("a budget that lacks a contribution says so", "[budget]") {
  const UncertaintyBudget none = reading_budget(ballbar(""));
  CHECK_FALSE(none.complete());
  CHECK(none.missing() == "instrument, temperature");
  CHECK(none.expanded_um() == 0.0);
  const UncertaintyBudget no_alpha = reading_budget(ballbar("# temperature: 23\n# instrument_uncertainty: 2\n"));
  CHECK(no_alpha.missing() == "temperature");
  CHECK(line(no_alpha, "temperature").note.find("not corrected to 20 °C") != std::string::npos);
}

TEST_CASE("budget of the ballbar G: √2 × instrument, repeatability from repeated files", "[budget]") {
  const MeasurementSet s = ballbar("# instrument_uncertainty: 1.0\n");
  const UncertaintyBudget one = circularity_budget(s, {});
  // G is the difference of two readings: √2 × 0.5 = 0.7071068 µm; temperature none; not repeated
  CHECK(line(one, "instrument").u_um == Approx(0.7071068).epsilon(1e-6));
  CHECK(line(one, "temperature").u_um == 0.0);
  CHECK(one.missing() == "repeatability");
  CHECK(one.expanded_um() == Approx(1.4142136).epsilon(1e-6));
  // three runs of the test: G 10, 12, 11 µm → mean 11, s = √((1 + 1 + 0) / 2) = 1 µm
  const UncertaintyBudget three = circularity_budget(s, {10.0, 12.0, 11.0});
  CHECK(three.complete());
  CHECK(line(three, "repeatability").u_um == Approx(1.0));
  // u_c = √(0.5 + 1) = 1.2247449; U = 2.4494897
  CHECK(three.expanded_um() == Approx(2.4494897).epsilon(1e-6));
}

TEST_CASE("budget of the ISO 230-2 figures of a positioning line", "[budget]") {
  const MeasurementSet s = parse_measurement_csv(
      "# type: laser\n# axis: X\n# component: X\n# tool_point: 0, 0, 0\n# temperature: 22\n# material_expansion: "
      "10e-6\n"
      "# temperature_uncertainty: 0.1\n# expansion_uncertainty: 2e-6\n# instrument_uncertainty: 0.6\n"
      "t,run,X,Y,Z,e_um\n0,1,0,0,0,0\n1,1,100,0,0,1\n2,1,200,0,0,2\n",
      "x.csv", vmc());
  Iso230Figures g;
  g.repeatability_R_um = 4.0;
  Iso230Target t;
  t.s_up_um = 0.5;
  t.s_down_um = 0.8;
  t.runs_up = t.runs_down = 5;
  g.targets = {t, t};
  CHECK(budget_length_mm(s) == 200.0);
  const UncertaintyBudget e = iso230_2_budget(s, g, 'E');
  // instrument √2 × 0.6 / 2 = 0.4242641; repeatability √2 × 0.8 / √5 = 0.5059644
  CHECK(line(e, "instrument").u_um == Approx(0.4242641).epsilon(1e-6));
  CHECK(line(e, "repeatability").u_um == Approx(0.5059644).epsilon(1e-6));
  // temperature over 200 mm: 1000 × 200 × √((2 × 2e-6)² + (10e-6 × 0.1)²) = 2e5 × √(16e-12 + 1e-12)
  //   = 2e5 × 4.1231056e-6 = 0.8246211 µm
  CHECK(line(e, "temperature").u_um == Approx(0.8246211).epsilon(1e-6));
  // U = 2 √(0.18 + 0.256 + 0.68) = 2 √1.116 = 2.1128180
  CHECK(e.expanded_um() == Approx(2.1128180).epsilon(1e-6));
  const UncertaintyBudget b = iso230_2_budget(s, g, 'B');
  CHECK(line(b, "temperature").u_um == 0.0);  // a difference at one position
  const UncertaintyBudget r = iso230_2_budget(s, g, 'R');
  // R from s of 5 runs: R / √(2 × 4) = 4 / 2.8284271 = 1.4142136; no instrument or temperature part
  CHECK(r.expanded_um() == Approx(2.8284271).epsilon(1e-6));
  CHECK(r.complete());
}
