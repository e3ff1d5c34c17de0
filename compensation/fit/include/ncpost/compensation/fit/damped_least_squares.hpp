// SPDX-License-Identifier: Apache-2.0
#pragma once
// The fitting core (compensation/fit/, docs/architecture.md): nonlinear least squares by
// Levenberg–Marquardt with Marquardt's column scaling (Moré 1978; Ceres' "LEVENBERG_MARQUARDT"),
// optionally with a robust loss (robust_loss.hpp, iteratively reweighted) and a truncated
// singular value decomposition for rank-deficient problems (scaled_svd.hpp).
//
// Minimises Σ ρ(r_i(x)). At each iteration the Jacobian J = ∂r/∂x is evaluated once; with the
// robust weights w_i = ρ'(r_i)/r_i the step is δ = −step of scaled_svd(√w·J) for the right-hand
// side √w·r and damping λ. A step is accepted when the cost does not grow (λ ← max(λ/10, 1e-12),
// or stays 0), otherwise λ ← 10 λ (from 1e-3 if it was 0) until λ reaches 1e16.
//
// Callers: identification (identify.cpp), laser identification (laser_identify.cpp) and TRR-XY
// identification (trr_identify.cpp).
#include <functional>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "ncpost/compensation/fit/robust_loss.hpp"

namespace ncpost::comp {

struct LeastSquaresProblem {
  /// r(x); nullopt where the model cannot be evaluated (a step there is rejected).
  std::function<std::optional<Eigen::VectorXd>(const Eigen::VectorXd& x)> residuals;
  /// ∂r/∂x at x (rows of r, one column per variable).
  std::function<Eigen::MatrixXd(const Eigen::VectorXd& x)> jacobian;
};

struct DampedOptions {
  RobustLoss loss;
  int max_iterations = 100;
  double initial_damping = 1e-3;  ///< λ of the first step; 0: Gauss–Newton until a step fails
  double unseen_share = 0.0;      ///< scaled_svd.hpp
  double relative_cut = 0.0;      ///< scaled_svd.hpp (0: no truncation)
  /// Per variable: converged when no accepted step moves it by more. Empty: converged when the
  /// cost decreases by at most 1e-12 of itself or the scaled step |D·δ| is at most 1e-10 of the
  /// residual norm √(2·cost); with no step accepted, when the scaled gradient is at most 1e-6 of it.
  Eigen::VectorXd step_tolerance;

  /// Empty if valid, else what is wrong.
  std::string validate() const;
};

struct DampedSummary {
  Eigen::VectorXd x;   ///< the solution
  Eigen::VectorXd r;   ///< residuals at x
  double cost = 0.0;   ///< Σ ρ(r_i)
  int iterations = 0;  ///< accepted steps
  bool converged = false;
};

/// From x0 with residuals r0 = r(x0). Zero variables: converged at once.
DampedSummary levenberg_marquardt(const LeastSquaresProblem& problem, const Eigen::VectorXd& x0,
                                  const Eigen::VectorXd& r0, const DampedOptions& options);

}  // namespace ncpost::comp
