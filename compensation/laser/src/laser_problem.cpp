// SPDX-License-Identifier: Apache-2.0
#include "laser_problem.hpp"

#include <algorithm>
#include <map>

#include "ncpost/compensation/laser_reading.hpp"

namespace ncpost::comp::laser {

int priority_of(int axis, int component) {
  if (component == axis) return 0;      // positioning
  if (component < 3) return 2;          // straightness
  if (component - 3 == axis) return 4;  // roll
  return 3;                             // pitch, yaw
}

void fill_approach(MeasurementSet& set) {
  if (has_approach(set)) return;
  const int j = laser_moving_axis(set);
  for (std::size_t k = 0; k < set.rows.size(); ++k) {
    MeasurementRow& r = set.rows[k];
    const bool first = k == 0 || set.rows[k - 1].run != r.run;
    if (first)
      r.approach = 1;
    else if (r.command[j] > set.rows[k - 1].command[j] + 1e-9)
      r.approach = 1;
    else if (r.command[j] < set.rows[k - 1].command[j] - 1e-9)
      r.approach = -1;
    else
      r.approach = -set.rows[k - 1].approach;
  }
}

std::vector<Problem::Support> Problem::support(int set_index, const MeasurementRow& row) const {
  std::vector<Support> out;
  auto fitted = [&](int p) { return column_of[static_cast<std::size_t>(p)] >= 0 ? p : -1; };
  for (int a = 0; a < 3; ++a) {
    const auto& x = nodes[static_cast<std::size_t>(a)];
    if (x.empty()) continue;
    const double q = row.command[a];
    std::size_t i = 1;
    double w = 1.0;  // weight of node i (node i − 1 has 1 − w)
    if (q <= x.front()) {
      i = 0;
    } else if (q >= x.back()) {
      i = x.size() - 1;
    } else {
      while (x[i] < q) ++i;
      w = (q - x[i - 1]) / (x[i] - x[i - 1]);
    }
    for (int c = 0; c < 6; ++c) {
      const auto& to = node_param[static_cast<std::size_t>(a)][static_cast<std::size_t>(c)];
      Support g{{fitted(to[i]), -1}, {w, 0.0}};
      if (w < 1.0) g = {{fitted(to[i]), fitted(to[i - 1])}, {w, 1.0 - w}};
      if (g.index[0] >= 0 || g.index[1] >= 0) out.push_back(g);
    }
  }
  const int rev = reversal_param[static_cast<std::size_t>(moving[static_cast<std::size_t>(set_index)])];
  if (rev >= 0 && column_of[static_cast<std::size_t>(rev)] >= 0) out.push_back({{rev, -1}, {1.0, 0.0}});
  return out;
}

double Problem::raw(int set_index, const MeasurementRow& row, const std::vector<double>& values) const {
  const ErrorFunctor<double> f(
      layout, values.data(), laser_row_state(layout, values.data(), moving[static_cast<std::size_t>(set_index)], row));
  return laser_raw_reading_um(*machine, sets[static_cast<std::size_t>(set_index)], row, f);
}

Eigen::VectorXd Problem::residual(const std::vector<double>& values) const {
  Eigen::VectorXd r(rows);
  Eigen::Index k = 0;
  for (const auto& s : sets) {
    const std::vector<double> p = predict_laser_set(*machine, s, layout, values.data());
    for (std::size_t i = 0; i < s.rows.size(); ++i) r[k++] = s.rows[i].value[0] - p[i];
  }
  return r;
}

double Problem::value_derivative(int set_index, const MeasurementRow& row, const Support& g,
                                 std::vector<double>& values) const {
  // the reading depends on a table through its value at the row's position only: the fitted nodes
  // around it moved by h move that value by h·(their weights), one pair of readings for both nodes
  double moved = 0.0, h = 0.0;
  std::array<double, 2> keep{};
  for (int n = 0; n < 2; ++n) {
    if (g.index[n] < 0) continue;
    keep[n] = values[static_cast<std::size_t>(g.index[n])];
    moved += g.weight[n];
    h = layout.spec(g.index[n]).is_angle() ? 1e-5 : 1e-3;
  }
  if (moved <= 0.0) return 0.0;
  double reading[2] = {0.0, 0.0};
  for (int side = 0; side < 2; ++side) {
    for (int n = 0; n < 2; ++n)
      if (g.index[n] >= 0) values[static_cast<std::size_t>(g.index[n])] = keep[n] + (side == 0 ? h : -h);
    reading[side] = raw(set_index, row, values);
  }
  for (int n = 0; n < 2; ++n)
    if (g.index[n] >= 0) values[static_cast<std::size_t>(g.index[n])] = keep[n];
  return (reading[0] - reading[1]) / (2.0 * h * moved);
}

Eigen::MatrixXd Problem::jacobian(const std::vector<double>& values) const {
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(rows, static_cast<Eigen::Index>(param_of.size()));
  std::vector<double> v = values;
  Eigen::Index k = 0;
  for (std::size_t s = 0; s < sets.size(); ++s) {
    const MeasurementSet& set = sets[s];
    std::map<int, Eigen::Index> first_of_run;
    for (const auto& row : set.rows) {
      for (const Support& g : support(static_cast<int>(s), row)) {
        const double d_value = value_derivative(static_cast<int>(s), row, g, v);
        for (int n = 0; n < 2; ++n)
          if (g.index[n] >= 0) J(k, column_of[static_cast<std::size_t>(g.index[n])]) = g.weight[n] * d_value;
      }
      auto it = first_of_run.find(row.run);
      if (it == first_of_run.end()) first_of_run.emplace(row.run, k);
      ++k;
    }
    // zeroed at the first row of each run
    Eigen::Index base = k - static_cast<Eigen::Index>(set.rows.size());
    std::map<int, Eigen::RowVectorXd> zero;
    for (const auto& [run, at] : first_of_run) zero.emplace(run, J.row(at));
    for (std::size_t i = 0; i < set.rows.size(); ++i)
      J.row(base + static_cast<Eigen::Index>(i)) -= zero.at(set.rows[i].run);
  }
  return J;
}

}  // namespace ncpost::comp::laser
