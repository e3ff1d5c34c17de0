// SPDX-License-Identifier: Apache-2.0
#pragma once
// Test support for the open-ended diagnosis (issue 17): the public scenarios' plan with the
// sphere swept every 10° of C, and truths outside the fixed catalogue.
#include <cmath>

#include "diagnose_support.hpp"

namespace ncpost::test {

/// Ballbar-4axis at 250 and 300 mm, then the sphere every `sphere_step_deg` of C (t0 619 s).
inline std::vector<comp::MeasurementSet> open_plan(const Machine& m, double sphere_step_deg = 10.0,
                                                   int ballbar_points = 500, bool two_ballbars = true) {
  comp::BallbarPlanOptions b;
  b.heights_mm = two_ballbars ? std::vector<double>{250.0, 300.0} : std::vector<double>{250.0};
  b.points = ballbar_points;
  comp::SpherePlanOptions s;
  s.t0_s = 619.0;
  s.step_deg = sphere_step_deg;
  std::vector<comp::MeasurementSet> plans;
  for (auto& p : comp::plan_ballbar_4axis(m, b)) plans.push_back(p.set), plans.back().file = p.name;
  for (auto& p : comp::plan_sphere(m, s)) plans.push_back(p.set), plans.back().file = p.name;
  return plans;
}

/// The plan simulated on `truth` (the simulator of `ncpost simulate`).
inline std::vector<comp::MeasurementSet> simulate_plan(const Machine& m, const std::vector<comp::MeasurementSet>& plans,
                                                       const comp::ErrorParameters& truth, double noise_um,
                                                       std::uint64_t seed) {
  std::vector<comp::MeasurementSet> sets;
  for (std::size_t i = 0; i < plans.size(); ++i) {
    comp::SimulationOptions o;
    o.noise_um = noise_um;
    o.seed = seed + 7919 * i;
    sets.push_back(comp::simulate(m, plans[i], truth, o));
    sets.back().file = plans[i].file;
  }
  return sets;
}

/// A local bump of C's angular error: amplitude_rad · exp(−½ (d / width)²), d the angle from
/// `at_deg` round the turn, as the truth's table of ECC with a node every 2°.
inline comp::ErrorParameters ecc_bump(double amplitude_rad, double at_deg, double width_deg) {
  comp::ErrorParameters p;
  for (int deg = 0; deg < 360; deg += 2) {
    double d = std::abs(deg - at_deg);
    d = std::min(d, 360.0 - d);
    p.set(comp::table_parameter_name('C', 'C', deg),
          amplitude_rad * std::exp(-0.5 * (d / width_deg) * (d / width_deg)));
  }
  return p;
}

/// The plan simulated row by row, each row with its own truth: `vary(truth, row)` changes a copy
/// of `truth` for that row (effects that depend on more than one axis, outside the model's
/// families: an independent simulation of them).
template <class Vary>
inline std::vector<comp::MeasurementSet> simulate_row_by_row(const Machine& m,
                                                             const std::vector<comp::MeasurementSet>& plans,
                                                             const comp::ErrorParameters& truth, const Vary& vary,
                                                             double noise_um, std::uint64_t seed) {
  (void)m;
  std::vector<comp::MeasurementSet> sets;
  for (std::size_t i = 0; i < plans.size(); ++i) {
    comp::MeasurementSet out = plans[i];
    for (std::size_t r = 0; r < plans[i].rows.size(); ++r) {
      comp::MeasurementSet one = plans[i];
      one.rows = {plans[i].rows[r]};
      comp::ErrorParameters t = truth;
      vary(t, plans[i].rows[r]);
      comp::SimulationOptions o;
      o.noise_um = noise_um;
      o.seed = seed + 7919 * i + 104729 * r;
      out.rows[r] = comp::simulate(m, one, t, o).rows.front();
    }
    out.has_values = true;
    sets.push_back(std::move(out));
  }
  return sets;
}

/// The plan simulated on a truth whose tilt of C about X grows with A (EA0C = base + per_rad · A,
/// an effect coupling two axes): row by row, each with its own truth.
inline std::vector<comp::MeasurementSet> simulate_coupled_tilt(const Machine& m,
                                                               const std::vector<comp::MeasurementSet>& plans,
                                                               const comp::ErrorParameters& truth, double per_rad,
                                                               double noise_um, std::uint64_t seed) {
  const int a = m.index_of('A');
  return simulate_row_by_row(
      m, plans, truth,
      [&](comp::ErrorParameters& t, const comp::MeasurementRow& row) {
        t.set("EA0C", truth.value_or("EA0C", 0.0) + per_rad * row.command[a]);
      },
      noise_um, seed);
}

/// The plan simulated on a truth with an effect outside every family of the model: a
/// three-per-revolution angular error of C whose amplitude grows with A (ECC:h3:sin = per_rad ·
/// A, rad per rad of A): wrong-model data for the false-attribution rate.
inline std::vector<comp::MeasurementSet> simulate_h3_growing_with_a(const Machine& m,
                                                                    const std::vector<comp::MeasurementSet>& plans,
                                                                    const comp::ErrorParameters& truth, double per_rad,
                                                                    double noise_um, std::uint64_t seed) {
  const int a = m.index_of('A');
  return simulate_row_by_row(
      m, plans, truth,
      [&](comp::ErrorParameters& t, const comp::MeasurementRow& row) { t.set("ECC:h3:sin", per_rad * row.command[a]); },
      noise_um, seed);
}

inline bool has_effect(const comp::DiagnoseResult& d, const std::string& e) {
  for (const auto& a : d.added)
    if (a.candidate.effect == e) return true;
  return false;
}

/// Added effects that are cross terms of C (a component of C other than its angular positioning:
/// EXC, EYC, EZC, EAC, EBC) or instrument terms.
inline std::vector<std::string> false_terms(const comp::DiagnoseResult& d) {
  std::vector<std::string> out;
  for (const auto& a : d.added) {
    const std::string& e = a.candidate.effect;
    const bool cross_c = e.size() >= 3 && e[0] == 'E' && e[2] == 'C' && e[1] != 'C';
    if (cross_c || a.candidate.kind == comp::CandidateKind::instrument) out.push_back(e);
  }
  return out;
}

}  // namespace ncpost::test
