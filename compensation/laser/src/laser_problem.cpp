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

std::vector<int> Problem::support(int set_index, const MeasurementRow& row) const {
  std::vector<int> out;
  for (int a = 0; a < 3; ++a) {
    const auto& x = nodes[static_cast<std::size_t>(a)];
    if (x.empty()) continue;
    const double q = row.command[a];
    std::vector<std::size_t> idx;
    if (q <= x.front())
      idx = {0};
    else if (q >= x.back())
      idx = {x.size() - 1};
    else {
      std::size_t i = 1;
      while (x[i] < q) ++i;
      idx = {i - 1, i};
    }
    for (int c = 0; c < 6; ++c)
      for (std::size_t i : idx) {
        const int p = node_param[static_cast<std::size_t>(a)][static_cast<std::size_t>(c)][i];
        if (column_of[static_cast<std::size_t>(p)] >= 0) out.push_back(p);
      }
  }
  const int rev = reversal_param[static_cast<std::size_t>(moving[static_cast<std::size_t>(set_index)])];
  if (rev >= 0) out.push_back(rev);
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

Eigen::MatrixXd Problem::jacobian(const std::vector<double>& values) const {
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(rows, static_cast<Eigen::Index>(param_of.size()));
  std::vector<double> v = values;
  Eigen::Index k = 0;
  for (std::size_t s = 0; s < sets.size(); ++s) {
    const MeasurementSet& set = sets[s];
    std::map<int, Eigen::Index> first_of_run;
    for (const auto& row : set.rows) {
      for (int p : support(static_cast<int>(s), row)) {
        const double h = layout.spec(p).is_angle() ? 1e-5 : 1e-3;
        const double keep = v[static_cast<std::size_t>(p)];
        v[static_cast<std::size_t>(p)] = keep + h;
        const double up = raw(static_cast<int>(s), row, v);
        v[static_cast<std::size_t>(p)] = keep - h;
        const double down = raw(static_cast<int>(s), row, v);
        v[static_cast<std::size_t>(p)] = keep;
        J(k, column_of[static_cast<std::size_t>(p)]) = (up - down) / (2.0 * h);
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
