// SPDX-License-Identifier: Apache-2.0
#pragma once
// Predictions of measurements by the error model (docs/conventions.md "Measurements"), templated on
// the parameter scalar P so that identification differentiates them exactly.
//
//   ballbar  L = | bed_T_tool(q)·tool_ball − bed_T_table(q)·table_ball | + ballbar:length      (mm)
//   sphere   d = [bed_T_table(q)·(s + sphere:position) − bed_T_tool(q)·0] − [same, nominal]   (mm, M)
//   laser    e = 1000 · component of [table_T_tool(q)·tool_point − nominal], minus its value at
//            the first row of the run (µm)
// bed_T_table / bed_T_tool are the actual chain with the set-up at home (forward.hpp
// chain_pose); the home pose is evaluated once per set. Rows are evaluated in order, so reversal
// offsets follow the measuring order (reversal.hpp).
#include <cmath>
#include <map>
#include <vector>

#include "ncpost/compensation/error_model.hpp"
#include "ncpost/compensation/measurement.hpp"
#include "ncpost/compensation/reversal.hpp"

namespace ncpost::comp {

/// The rows of a set evaluated in order: `visit.begin_row(k)` before row k's own work (the home
/// pose and the row states come before row 0), then `visit.row(k, values, n)` with its n values in
/// the file's units; a laser row's value is before its run's zero is taken off (run_zero_rows).
template <class P, class Visitor>
void predict_rows(const Machine& m, const MeasurementSet& set, const ModelLayout& layout, const P* values,
                  Visitor& visit) {
  using std::sqrt;
  std::vector<AxisPosition> commands;
  std::vector<double> times;
  for (const auto& r : set.rows) {
    commands.push_back(r.command);
    times.push_back(r.time_s);
  }
  const std::vector<RowState<P>> states = row_states<P>(layout, values, commands, times);
  ErrorFunctor<P> f(layout, values);
  const double tl = set.tool_length_mm;
  const ChainPose<P> home = raw_chain_pose<P>(m, AxisPositionT<P>{}, tl, f, true);
  const Rigid<P> table_home_inv = home.bed_T_table.inverse();
  const Rigid<P> tool_home_inv = home.bed_T_tool.inverse();

  for (std::size_t k = 0; k < set.rows.size(); ++k) {
    visit.begin_row(k);
    f.set_state(states[k]);
    const AxisPositionT<P> q = set.rows[k].command.template cast<P>();
    const ChainPose<P> raw = raw_chain_pose<P>(m, q, tl, f, false);
    const Rigid<P> bed_T_table = raw.bed_T_table * table_home_inv;
    const Rigid<P> bed_T_tool = raw.bed_T_tool * tool_home_inv;
    switch (set.type) {
      case MeasurementType::ballbar: {
        const Vec3<P> d = bed_T_tool.apply(set.tool_ball_mm.template cast<P>()) -
                          bed_T_table.apply(set.table_ball_mm.template cast<P>());
        const P length = sqrt(d.squaredNorm()) + f.value(layout.ballbar_length());
        visit.row(k, &length, 1);
        break;
      }
      case MeasurementType::sphere: {
        Vec3<P> s = set.sphere_mm.template cast<P>();
        for (int c = 0; c < 3; ++c) s[c] += f.value(layout.sphere_position()[static_cast<std::size_t>(c)]);
        const Vec3<P> actual = bed_T_table.apply(s) - bed_T_tool.t;
        const ChainPose<double> nom = chain_pose<double>(m, set.rows[k].command, tl, NominalErrors{});
        const Vec3d nominal = nom.bed_T_table.apply(set.sphere_mm) - nom.bed_T_tool.t;
        P deviation[3];
        for (int c = 0; c < 3; ++c) deviation[c] = actual[c] - P(nominal[c]);
        visit.row(k, deviation, 3);
        break;
      }
      case MeasurementType::laser: {
        const Vec3<P> actual = (bed_T_table.inverse() * bed_T_tool).apply(set.tool_point_mm.template cast<P>());
        const ChainPose<double> nom = chain_pose<double>(m, set.rows[k].command, tl, NominalErrors{});
        const Vec3d nominal = nom.table_T_tool().apply(set.tool_point_mm);
        const int c = set.component - 'X';
        const P e = P(1000.0) * (actual[c] - P(nominal[c]));
        visit.row(k, &e, 1);
        break;
      }
    }
  }
}

/// Per row of a laser set, the first row of its run: a laser value is the reading minus the
/// reading at that row (the run's zero). Empty for the other kinds.
inline std::vector<std::size_t> run_zero_rows(const MeasurementSet& set) {
  std::vector<std::size_t> first;
  if (set.type != MeasurementType::laser) return first;
  std::map<int, std::size_t> first_of_run;
  for (std::size_t k = 0; k < set.rows.size(); ++k)
    first.push_back(first_of_run.emplace(set.rows[k].run, k).first->second);
  return first;
}

/// Predicted values of every row, flattened row by row (values_per_row each), in the file's
/// units (mm; µm for laser).
template <class P>
std::vector<P> predict_set(const Machine& m, const MeasurementSet& set, const ModelLayout& layout, const P* values) {
  struct Collect {
    std::vector<P> out;
    void begin_row(std::size_t) {}
    void row(std::size_t, const P* v, int n) { out.insert(out.end(), v, v + n); }
  } collect;
  collect.out.reserve(set.rows.size() * static_cast<std::size_t>(set.values_per_row()));
  predict_rows<P>(m, set, layout, values, collect);
  const std::vector<std::size_t> zero_row = run_zero_rows(set);
  if (zero_row.empty()) return collect.out;
  const std::vector<P> reading = collect.out;
  for (std::size_t k = 0; k < reading.size(); ++k) collect.out[k] = reading[k] - reading[zero_row[k]];
  return collect.out;
}

/// Scale from the file's value unit to mm (1 for ballbar and sphere, 1e-3 for laser µm).
inline double value_unit_mm(const MeasurementSet& set) { return set.type == MeasurementType::laser ? 1e-3 : 1.0; }

}  // namespace ncpost::comp
