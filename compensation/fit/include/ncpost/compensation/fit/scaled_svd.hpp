// SPDX-License-Identifier: Apache-2.0
#pragma once
// The fitting core (compensation/fit/, docs/architecture.md), linear algebra part: the singular
// value decomposition of a column-scaled Jacobian, and what the three identifications take from
// it — the damped step, the rank and null space, the covariance.
//
// Column scaling: column j of J is divided by its norm d_j, so that parameters in mm and in rad
// (and rates, time constants) compare; K = J·D⁻¹ = U·Σ·Vᵀ. A column of norm at most
// `unseen_share` × the largest is not seen at all: it is set to zero with d_j = 1 (scaling it up
// would only magnify rounding or differencing noise).
//
// Directions: a right singular vector v_i is *seen* when σ_i > cut (cut = `relative_cut` × σ_max;
// 0: every σ_i > 0); the others, and the n − min(m, n) directions a short matrix has no singular
// value for, form the null space (in the scaled parameters, per unit of effect on the data).
//
// Step (Levenberg–Marquardt with Marquardt's scaling, Nocedal & Wright §10.3): the δ minimising
// |J·δ − b|² + λ·|D·δ|² over the seen directions, δ = D⁻¹ Σ_seen v_i σ_i/(σ_i² + λ) u_iᵀ b;
// λ = 0 gives the minimum-norm (truncated-SVD) Gauss–Newton step.
//
// Covariance: s²·(JᵀJ)⁺ over the seen directions, D⁻¹ (Σ_seen v_i v_iᵀ / σ_i²) D⁻¹ · s²; for a
// full-rank J this is s²·(JᵀJ)⁻¹ (Ceres covariance.h; the Gauss–Markov estimate).
#include <vector>

#include <Eigen/Core>
#include <Eigen/SVD>

namespace ncpost::comp {

struct ScaledSvd {
  Eigen::MatrixXd columns;  ///< K = J·D⁻¹
  Eigen::VectorXd scale;    ///< d_j (1 for an unseen column)
  Eigen::JacobiSVD<Eigen::MatrixXd> svd;
  double cut = 0.0;  ///< σ ≤ cut: not seen
  int rank = 0;      ///< seen directions

  /// The damped step for the right-hand side `b` (rows of J), in the unscaled parameters.
  Eigen::VectorXd step(const Eigen::VectorXd& b, double damping) const;
  /// |D·step| of that step: its size in units of effect.
  Eigen::VectorXd scaled_step(const Eigen::VectorXd& b, double damping) const;
  /// The unit directions the data cannot see (scaled parameters).
  std::vector<Eigen::VectorXd> null_space() const;
  /// Per parameter, the share of its unit vector (scaled) that lies in the null space.
  Eigen::VectorXd null_share() const;
  /// s²·(JᵀJ)⁺ over the seen directions (see the header comment), unscaled parameters.
  Eigen::MatrixXd covariance(double residual_variance) const;
};

/// The decomposition of J with its columns scaled (header comment).
ScaledSvd scaled_svd(const Eigen::MatrixXd& J, double unseen_share = 0.0, double relative_cut = 0.0);

}  // namespace ncpost::comp
