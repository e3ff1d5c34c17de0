// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/fit/scaled_svd.hpp"

#include <algorithm>

namespace ncpost::comp {

ScaledSvd scaled_svd(const Eigen::MatrixXd& J, double unseen_share, double relative_cut) {
  ScaledSvd s;
  const Eigen::Index n = J.cols();
  s.columns = J;
  s.scale = J.colwise().norm().transpose();
  const double largest = n > 0 ? s.scale.maxCoeff() : 0.0;
  for (Eigen::Index j = 0; j < n; ++j) {
    if (s.scale[j] > unseen_share * largest && s.scale[j] > 0.0) {
      s.columns.col(j) /= s.scale[j];
    } else {
      s.columns.col(j).setZero();
      s.scale[j] = 1.0;
    }
  }
  if (n == 0) return s;
  s.svd.compute(s.columns, Eigen::ComputeThinU | Eigen::ComputeFullV);
  const Eigen::VectorXd& sv = s.svd.singularValues();
  s.cut = sv.size() ? relative_cut * sv[0] : 0.0;
  for (Eigen::Index i = 0; i < sv.size(); ++i)
    if (sv[i] > s.cut) ++s.rank;
  return s;
}

Eigen::VectorXd ScaledSvd::scaled_step(const Eigen::VectorXd& b, double damping) const {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(scale.size());
  if (scale.size() == 0) return out;
  const Eigen::VectorXd& sv = svd.singularValues();
  const Eigen::VectorXd ub = svd.matrixU().transpose() * b;
  for (Eigen::Index i = 0; i < sv.size(); ++i)
    if (sv[i] > cut) out += svd.matrixV().col(i) * (sv[i] / (sv[i] * sv[i] + damping) * ub[i]);
  return out;
}

Eigen::VectorXd ScaledSvd::step(const Eigen::VectorXd& b, double damping) const {
  return scaled_step(b, damping).cwiseQuotient(scale);
}

std::vector<Eigen::VectorXd> ScaledSvd::null_space() const {
  std::vector<Eigen::VectorXd> out;
  const Eigen::VectorXd& sv = svd.singularValues();
  for (Eigen::Index i = 0; i < scale.size(); ++i)
    if (i >= sv.size() || !(sv[i] > cut)) out.push_back(svd.matrixV().col(i));
  return out;
}

Eigen::VectorXd ScaledSvd::null_share() const {
  Eigen::VectorXd share = Eigen::VectorXd::Zero(scale.size());
  for (const Eigen::VectorXd& v : null_space()) share += v.cwiseAbs2();
  return share;
}

Eigen::MatrixXd ScaledSvd::covariance(double residual_variance) const {
  const Eigen::Index n = scale.size();
  Eigen::MatrixXd c = Eigen::MatrixXd::Zero(n, n);
  const Eigen::VectorXd& sv = svd.singularValues();
  for (Eigen::Index i = 0; i < sv.size(); ++i)
    if (sv[i] > cut) c += svd.matrixV().col(i) * svd.matrixV().col(i).transpose() / (sv[i] * sv[i]);
  const Eigen::VectorXd inv = scale.cwiseInverse();
  return residual_variance * (inv.asDiagonal() * c * inv.asDiagonal());
}

}  // namespace ncpost::comp
