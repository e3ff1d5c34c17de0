// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/fit/rank.hpp"

#include <Eigen/QR>
#include <Eigen/SVD>

namespace ncpost::comp {

RankAnalysis analyse_rank(const Eigen::MatrixXd& J, double tolerance, const Eigen::VectorXd& typical) {
  RankAnalysis a;
  const Eigen::Index n = J.cols();
  a.column_norms = J.colwise().norm().transpose();
  // a column this small next to the largest has no effect (rounding of an exact invariance)
  const double largest = n > 0 ? a.column_norms.maxCoeff() : 0.0;
  for (Eigen::Index c = 0; c < n; ++c)
    if (a.column_norms[c] <= 1e-9 * largest) a.column_norms[c] = 0.0;
  if (typical.size() == n && n > 0) {
    const Eigen::VectorXd effect = a.column_norms.cwiseProduct(typical.cwiseAbs());
    const double strongest = effect.maxCoeff();
    for (Eigen::Index c = 0; c < n; ++c)
      if (effect[c] < tolerance * strongest) a.column_norms[c] = 0.0;
  }
  Eigen::MatrixXd Js = J;
  for (Eigen::Index c = 0; c < n; ++c) {
    if (a.column_norms[c] > 0.0)
      Js.col(c) /= a.column_norms[c];
    else
      Js.col(c).setZero();
  }
  if (n > 0) {
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(Js);
    a.singular_values = svd.singularValues();
  }
  // Greedy selection in priority order with an orthonormal basis of the kept columns.
  Eigen::MatrixXd Q(J.rows(), 0);
  for (Eigen::Index c = 0; c < n; ++c) {
    Eigen::VectorXd v = Js.col(c);
    if (a.column_norms[c] > 0.0) {
      Eigen::VectorXd rest = v - Q * (Q.transpose() * v);
      rest -= Q * (Q.transpose() * rest);  // re-orthogonalise
      if (rest.norm() > tolerance) {
        Q.conservativeResize(Eigen::NoChange, Q.cols() + 1);
        Q.col(Q.cols() - 1) = rest.normalized();
        a.kept.push_back(static_cast<int>(c));
        continue;
      }
    }
    a.pinned.push_back(static_cast<int>(c));
  }
  a.rank = static_cast<int>(a.kept.size());
  // Null vector of a pinned column: e_p − Σ x_k e_k with Js_kept x = Js_p.
  Eigen::MatrixXd K(J.rows(), static_cast<Eigen::Index>(a.kept.size()));
  for (std::size_t k = 0; k < a.kept.size(); ++k) K.col(static_cast<Eigen::Index>(k)) = Js.col(a.kept[k]);
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(K);
  for (int p : a.pinned) {
    Eigen::VectorXd v = Eigen::VectorXd::Zero(n);
    v[p] = 1.0;
    if (a.column_norms[p] > 0.0 && !a.kept.empty()) {
      const Eigen::VectorXd x = qr.solve(Js.col(p));
      for (std::size_t k = 0; k < a.kept.size(); ++k) v[a.kept[k]] = -x[static_cast<Eigen::Index>(k)];
    }
    a.null_vectors.push_back(v.normalized());
  }
  return a;
}

}  // namespace ncpost::comp
