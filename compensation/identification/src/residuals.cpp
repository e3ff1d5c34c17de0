// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/residuals.hpp"

#include <unsupported/Eigen/AutoDiff>

#include "ncpost/compensation/prediction.hpp"

namespace ncpost::comp {
namespace {

// Fixed-size derivatives: every operation of the forward pass works on kJetSize numbers without
// size bookkeeping (a dynamic vector, even with inline storage, made the pass about twice as slow);
// a chunk of fewer columns leaves its last entries at zero.
using Derivatives = Eigen::Matrix<double, kJetSize, 1>;
using Jet = Eigen::AutoDiffScalar<Derivatives>;

}  // namespace

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
  Eigen::MatrixXd J(residual_count(), static_cast<Eigen::Index>(columns.size()));
  for (std::size_t first = 0; first < columns.size(); first += kJetSize) {
    const int chunk = static_cast<int>(std::min<std::size_t>(kJetSize, columns.size() - first));
    std::vector<Jet> jets(values.size());
    for (std::size_t p = 0; p < values.size(); ++p) jets[p] = Jet(values[p], Derivatives::Zero());
    for (int c = 0; c < chunk; ++c)
      jets[static_cast<std::size_t>(columns[first + static_cast<std::size_t>(c)])].derivatives()[c] = 1.0;
    Eigen::Index i = 0;
    for (const auto& s : *sets) {
      const std::vector<Jet> p = predict_set<Jet>(*machine, s, layout, jets.data());
      const double unit = value_unit_mm(s);
      for (const Jet& v : p) {
        for (int c = 0; c < chunk; ++c) J(i, static_cast<Eigen::Index>(first) + c) = unit * v.derivatives()[c];
        ++i;
      }
    }
  }
  return J;
}

}  // namespace ncpost::comp
