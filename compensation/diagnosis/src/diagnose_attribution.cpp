// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/diagnose_attribution.hpp"

#include <Eigen/QR>
#include <algorithm>

#include "ncpost/compensation/diagnose_screening.hpp"

namespace ncpost::comp {

Eigen::MatrixXd structure_nuisance(const std::vector<MeasurementSet>& sets,
                                   const std::vector<ResidualStructure>& columns,
                                   const std::vector<ResidualStructure>& left, Eigen::Index count) {
  std::vector<Eigen::Index> offset(sets.size() + 1, 0);
  for (std::size_t i = 0; i < sets.size(); ++i)
    offset[i + 1] = offset[i] + static_cast<Eigen::Index>(sets[i].rows.size()) * sets[i].values_per_row();
  auto structured = [&](std::size_t set) {
    return std::any_of(left.begin(), left.end(), [&](const ResidualStructure& s) { return s.set_index == set; });
  };
  auto groups = [](const ResidualStructure& s) {
    return s.group_of_row.empty() ? 0 : *std::max_element(s.group_of_row.begin(), s.group_of_row.end()) + 1;
  };
  Eigen::Index total = 0;
  for (const auto& s : columns)
    if (s.set_index < sets.size() && structured(s.set_index)) total += groups(s);
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(count, total);
  Eigen::Index first = 0;
  for (const auto& s : columns) {
    if (s.set_index >= sets.size() || !structured(s.set_index)) continue;
    const int nv = sets[s.set_index].values_per_row();
    for (std::size_t i = 0; i < s.group_of_row.size(); ++i)
      G(offset[s.set_index] + static_cast<Eigen::Index>(i) * nv + s.value_index, first + s.group_of_row[i]) = 1.0;
    first += groups(s);
  }
  return G;
}

OwnEvidence own_evidence(const Eigen::MatrixXd& J, const Eigen::VectorXd& r, const std::vector<int>& effect,
                         const Eigen::VectorXd& beta, const Eigen::MatrixXd& nuisance) {
  const Eigen::Index m = J.rows();
  const Eigen::Index k = static_cast<Eigen::Index>(effect.size());
  Eigen::MatrixXd C(m, k);
  for (Eigen::Index j = 0; j < k; ++j) C.col(j) = J.col(effect[static_cast<std::size_t>(j)]);
  // the span of the other fitted parameters and of the structure (normalised columns, rank-revealing)
  Eigen::MatrixXd X(m, J.cols() - k + nuisance.cols());
  Eigen::Index x = 0;
  for (Eigen::Index j = 0; j < J.cols(); ++j)
    if (std::find(effect.begin(), effect.end(), static_cast<int>(j)) == effect.end()) X.col(x++) = J.col(j);
  X.rightCols(nuisance.cols()) = nuisance;
  for (Eigen::Index j = 0; j < X.cols(); ++j)
    if (X.col(j).norm() > 0) X.col(j).normalize();
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(X);
  qr.setThreshold(1e-10);
  const Eigen::Index rank = qr.rank();
  const Eigen::MatrixXd Q = Eigen::MatrixXd(qr.householderQ()).leftCols(rank);
  auto project = [&](const Eigen::MatrixXd& v) { return Eigen::MatrixXd(v - Q * (Q.transpose() * v)); };
  const Eigen::MatrixXd PC = project(C);
  const Eigen::VectorXd Pr_without = project(r - C * beta);
  const Eigen::VectorXd Pr = project(r);
  OwnEvidence e;
  e.separation = 1.0;
  for (Eigen::Index j = 0; j < k; ++j)
    e.separation = std::min(e.separation, C.col(j).norm() > 0 ? PC.col(j).norm() / C.col(j).norm() : 0.0);
  const Eigen::VectorXd fit = PC * PC.colPivHouseholderQr().solve(Pr_without);
  e.drop_mm2 = fit.squaredNorm();
  const double dof = double(m - rank - k);
  const double s = Pr.squaredNorm();
  if (dof < 1 || s <= 0) return e;
  e.f_statistic = (e.drop_mm2 / double(k)) / (s / dof);
  e.p_value = f_upper_tail(e.f_statistic, double(k), dof);
  return e;
}

}  // namespace ncpost::comp
