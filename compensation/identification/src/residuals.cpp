// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/residuals.hpp"

#include "ncpost/compensation/prediction.hpp"
#include "ncpost/compensation/prediction_jacobian.hpp"

namespace ncpost::comp {

Eigen::Index ResidualProblem::residual_count() const {
  Eigen::Index n = 0;
  for (const auto& s : *sets) n += static_cast<Eigen::Index>(s.rows.size()) * s.values_per_row();
  return n;
}

std::vector<std::vector<double>> ResidualProblem::predictions(const std::vector<double>& values) const {
  std::vector<std::vector<double>> out;
  for (const auto& s : *sets) out.push_back(predict_set<double>(*machine, s, layout, values.data()));
  return out;
}

Eigen::VectorXd ResidualProblem::residuals(const std::vector<double>& values) const {
  Eigen::VectorXd r(residual_count());
  Eigen::Index i = 0;
  for (const auto& s : *sets) {
    const std::vector<double> p = predict_set<double>(*machine, s, layout, values.data());
    const double unit = value_unit_mm(s);
    const int n = s.values_per_row();
    for (std::size_t k = 0; k < s.rows.size(); ++k)
      for (int v = 0; v < n; ++v)
        r[i++] = unit * (p[k * static_cast<std::size_t>(n) + static_cast<std::size_t>(v)] - s.rows[k].value[v]);
  }
  return r;
}

Eigen::MatrixXd ResidualProblem::jacobian(const std::vector<double>& values, const std::vector<int>& columns) const {
  return prediction_jacobian_mm(*machine, *sets, layout, values, columns);
}

}  // namespace ncpost::comp
