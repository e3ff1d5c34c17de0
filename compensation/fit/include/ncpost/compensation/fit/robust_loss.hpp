// SPDX-License-Identifier: Apache-2.0
#pragma once
// The fitting core (compensation/fit/), robust loss: ρ(r) per residual and the weight ρ'(r)/r of
// iteratively reweighted least squares (Ceres loss_function.h; Huber 1964). `scale` is where the
// loss leaves the quadratic, in the residuals' unit.
//   squared: ρ = r²/2                                   w = 1
//   huber:   ρ = r²/2 (|r| ≤ k), k|r| − k²/2 beyond     w = 1, k/|r|
//   cauchy:  ρ = k²/2 · ln(1 + (r/k)²)                  w = 1/(1 + (r/k)²)
#include <Eigen/Core>

namespace ncpost::comp {

enum class Loss { squared, huber, cauchy };

struct RobustLoss {
  Loss loss = Loss::squared;
  double scale = 1.0;

  double rho(double r) const;
  double weight(double r) const;
  /// Σ ρ(r_i).
  double cost(const Eigen::VectorXd& r) const;
  /// w(r_i) for every residual.
  Eigen::VectorXd weights(const Eigen::VectorXd& r) const;
};

}  // namespace ncpost::comp
