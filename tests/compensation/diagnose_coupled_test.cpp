// SPDX-License-Identifier: Apache-2.0
// Issue 17: an effect coupled between two axes, a tilt of C that grows with A (a C table on a
// cradle that sags with A). The family EA0C:A:p1 (parameter_name.hpp) holds it: parsed, in the
// chain like the row-by-row truth of the independent simulator, found by name by the diagnosis,
// the residual at the noise, and the compensated dome path cut on the truth.
#include <catch2/catch.hpp>

#include "diagnose_open_support.hpp"

using namespace ncpost;
using namespace ncpost::test;

TEST_CASE("Names: a location error of C that grows with A", "[diagnose][coupled][names]") {
  const Machine m = public_machine();
  const auto p = comp::parse_parameter_name("EA0C:A:p1", m);
  REQUIRE(p.spec);
  CHECK(p.spec->kind == comp::ParameterKind::coupled);
  CHECK(p.spec->axis_index == m.index_of('C'));
  CHECK(p.spec->coupled_axis_index == m.index_of('A'));
  CHECK(p.spec->component == 3);
  CHECK(p.spec->order == 1);
  CHECK(p.spec->is_angle());
  CHECK(comp::parse_parameter_name("EX0C:A:p2", m).spec->order == 2);
  CHECK_FALSE(comp::parse_parameter_name("EX0C:A:p2", m).spec->is_angle());
  // A is not carried by C (C rides on A): refused, with the reason
  const auto reverse = comp::parse_parameter_name("EB0A:C:p1", m);
  CHECK_FALSE(reverse.spec);
  CHECK(reverse.error.find("only where C carries A") != std::string::npos);
  CHECK_FALSE(comp::parse_parameter_name("EZ0C:A:p1", m).spec);  // an offset along C's own line
  CHECK_FALSE(comp::parse_parameter_name("EA0C:X:p1", m).spec);  // not a rotary carrier
  CHECK_FALSE(comp::parse_parameter_name("EA0C:A:p3", m).spec);
  CHECK(comp::effect_of("EA0C:A:p1") == "EA0C:A:p1");
}

TEST_CASE("EA0C:A:p1 in the chain equals the tilt set row by row from A", "[diagnose][coupled]") {
  const Machine m = public_machine();
  const auto plans = open_plan(m, 30.0, 200, false);
  const comp::ErrorParameters base = truth_with(m, {});
  comp::ErrorParameters with_family = base;
  with_family.set("EA0C:A:p1", 40e-6);
  with_family.set("EX0C:A:p2", 5e-3);
  const auto modelled = simulate_plan(m, plans, with_family, 0.0, 1);
  // the independent simulation: each row with its own location errors EA0C, EX0C from its A
  std::vector<comp::MeasurementSet> rowwise;
  const int a = m.index_of('A');
  for (const auto& plan : plans) {
    comp::MeasurementSet out = plan;
    for (std::size_t r = 0; r < plan.rows.size(); ++r) {
      comp::MeasurementSet one = plan;
      one.rows = {plan.rows[r]};
      comp::ErrorParameters t = base;
      const double q = plan.rows[r].command[a];
      t.set("EA0C", base.value_or("EA0C", 0.0) + 40e-6 * q);
      t.set("EX0C", base.value_or("EX0C", 0.0) + 5e-3 * q * q);
      out.rows[r] = comp::simulate(m, one, t, {}).rows.front();
    }
    rowwise.push_back(out);
  }
  double worst = 0.0, largest = 0.0;
  const auto plain = simulate_plan(m, plans, base, 0.0, 1);
  for (std::size_t s = 0; s < plans.size(); ++s)
    for (std::size_t r = 0; r < plans[s].rows.size(); ++r)
      for (int v = 0; v < plans[s].values_per_row(); ++v) {
        worst = std::max(worst, std::abs(modelled[s].rows[r].value[v] - rowwise[s].rows[r].value[v]));
        largest = std::max(largest, std::abs(modelled[s].rows[r].value[v] - plain[s].rows[r].value[v]));
      }
  std::printf("coupled family vs row-by-row truth: %.3g (effect up to %.3g, units of the sets)\n", worst, largest);
  CHECK(largest > 1e-3);  // the effect shows (over 1 µm)
  CHECK(worst < 1e-9);
}

TEST_CASE("EA0C:A:p1: the posting path (home cache, compensated IK) sees the tilt at every A", "[diagnose][coupled]") {
  const Machine m = public_machine();
  comp::ErrorParameters coupled = truth_with(m, {}), rowwise = coupled;
  coupled.set("EA0C:A:p1", 40e-6);
  AxisPosition q = home_of(m);
  q.linear_mm = Vec3d(50, 30, 20);
  q.rotary_rad = Eigen::Vector2d(1.0, 0.7);
  rowwise.set("EA0C", rowwise.value_or("EA0C", 0.0) + 40e-6 * 1.0);
  const comp::MachineModel a(m, coupled), b(m, rowwise), base(m, truth_with(m, {}));
  const Setup s = dome_setup();
  const HomeInverse home = a.home_inverse(s.tool_length_mm);
  const Vec3d expected = b.tool_pose(q, s).tip_mm;
  CHECK((base.tool_pose(q, s).tip_mm - expected).norm() > 1e-3);  // the effect: over 1 µm here
  CHECK((a.tool_pose(q, s).tip_mm - expected).norm() < 1e-12);
  CHECK((a.tool_pose(q, s, {}, &home).tip_mm - expected).norm() < 1e-12);
  ClPoint cl;
  cl.tip_mm = expected;
  cl.axis = b.tool_pose(q, s).axis;
  AxisPosition guess = q;
  guess.rotary_rad += Eigen::Vector2d(1e-4, -1e-4);
  const comp::ActualIkOutcome ik = comp::solve_actual(a, cl, s, guess, {});
  REQUIRE(ik.ok());
  CHECK((ik.position->linear_mm - q.linear_mm).norm() < 1e-6);
  CHECK((ik.position->rotary_rad - q.rotary_rad).norm() < 1e-8);
}

TEST_CASE("C's tilt growing with A is found by name, at the noise, and the compensated cut is within 2.5 um",
          "[diagnose][coupled]") {
  const Machine m = public_machine();
  const auto plans = open_plan(m, 30.0, 200, false);
  const comp::ErrorParameters base = truth_with(m, {});
  // 40 µrad of tilt about X per rad of A: 63 µrad at A = 90°, the simulator's row-by-row truth
  const auto sets = simulate_coupled_tilt(m, plans, base, 40e-6, 0.5, 500);
  const comp::DiagnoseResult d = run_diagnose("C tilt growing with A", m, sets);
  REQUIRE(d.added.size() == 1);
  CHECK(d.added.front().candidate.effect == "EA0C:A:p1");
  CHECK(d.unexplained.empty());
  CHECK(d.not_attributed.empty());
  CHECK(false_terms(d).empty());
  const double v = *d.final_fit.parameters.get("EA0C:A:p1"), u = *d.final_fit.uncertainty.get("EA0C:A:p1");
  std::printf("  EA0C:A:p1 = %.4g +- %.2g rad/rad (truth 4e-05)\n", v, u);
  CHECK(std::abs(v - 40e-6) < 4.0 * u);
  CHECK(d.basic.rms_after_um > 1.5 * 0.5);
  CHECK(d.final_fit.rms_after_um < 1.2 * 0.5);
  // the dome path posted with the identified model (subdivided to 2 µm), executed on the truth
  comp::ErrorParameters truth = base;
  truth.set("EA0C:A:p1", 40e-6);
  const double ends_mm = compensated_ends_mm(m, d.final_fit.parameters, truth);
  const double basic_ends_mm = compensated_ends_mm(m, d.basic.parameters, truth);
  double cut_ends_mm = 0.0;
  const double cut_mm =
      compensated_cut_mm(m, d.final_fit.parameters, truth, "diagnose_coupled.nc", &cut_ends_mm, 0.002);
  std::printf(
      "  tool tip at the CL points on the truth: basic model %.2f um, final model %.2f um; written program: "
      "contour %.2f um, block ends %.2f um\n",
      1e3 * basic_ends_mm, 1e3 * ends_mm, 1e3 * cut_mm, 1e3 * cut_ends_mm);
  CHECK(ends_mm < 2.5e-3);
  CHECK(cut_ends_mm < 2.5e-3);
  CHECK(cut_mm < 2.5e-3);  // the written program subdivided to 2 µm, executed on the truth
  CHECK(basic_ends_mm > 2.0 * ends_mm);
}
