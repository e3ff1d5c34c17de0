// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/fit/damped_least_squares.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "ncpost/compensation/fit/scaled_svd.hpp"

namespace ncpost::comp {
namespace {

/// The damping after a rejected step starts here when it was 0; it moves by this factor; at the
/// largest no step decreases the cost, and it never falls below the smallest once positive.
constexpr double kFirstDamping = 1e-3;
constexpr double kDampingFactor = 10.0;
constexpr double kMaxDamping = 1e16;
constexpr double kMinDamping = 1e-12;
/// The default stop rules (header): cost decrease, scaled step, scaled gradient.
constexpr double kCostTolerance = 1e-12;
constexpr double kStepTolerance = 1e-10;
constexpr double kGradientTolerance = 1e-6;

bool within(const Eigen::VectorXd& step, const Eigen::VectorXd& tolerance) {
  return (step.cwiseAbs().array() <= tolerance.array()).all();
}

/// One iteration: the first accepted damped step from `s` (s updated, true), or false.
bool accepted_step(const LeastSquaresProblem& p, const DampedOptions& o, const ScaledSvd& svd, const Eigen::VectorXd& b,
                   double& damping, DampedSummary& s, bool& converged) {
  while (damping < kMaxDamping) {
    const Eigen::VectorXd step = -svd.step(b, damping);
    const Eigen::VectorXd trial = s.x + step;
    const std::optional<Eigen::VectorXd> rt = p.residuals(trial);
    const double ct = rt ? o.loss.cost(*rt) : HUGE_VAL;
    if (std::isfinite(ct) && ct <= s.cost) {
      const double decrease = s.cost - ct;
      const double scaled_step = svd.scaled_step(b, damping).norm();
      s.x = trial;
      s.r = *rt;
      s.cost = ct;
      damping = damping > 0.0 ? std::max(damping / kDampingFactor, kMinDamping) : 0.0;
      converged = o.step_tolerance.size() ? within(step, o.step_tolerance)
                                          : decrease <= kCostTolerance * s.cost + 1e-30 ||
                                                scaled_step <= kStepTolerance * std::sqrt(2.0 * s.cost + 1e-30);
      return true;
    }
    damping = damping > 0.0 ? damping * kDampingFactor : kFirstDamping;
  }
  return false;
}

}  // namespace

std::string DampedOptions::validate() const {
  if (max_iterations < 1) return "max_iterations must be at least 1";
  if (!(initial_damping >= 0.0 && initial_damping < kMaxDamping)) return "the initial damping must be in [0, 1e16)";
  if (!(unseen_share >= 0.0 && unseen_share < 1.0)) return "unseen_share must be in [0, 1)";
  if (!(relative_cut >= 0.0 && relative_cut < 1.0)) return "relative_cut must be in [0, 1)";
  if (!(loss.scale > 0.0)) return "the loss scale must be positive";
  return {};
}

DampedSummary levenberg_marquardt(const LeastSquaresProblem& p, const Eigen::VectorXd& x0, const Eigen::VectorXd& r0,
                                  const DampedOptions& o) {
  DampedSummary s{x0, r0, o.loss.cost(r0), 0, x0.size() == 0};
  double damping = o.initial_damping;
  while (!s.converged && s.iterations < o.max_iterations) {
    const Eigen::VectorXd root_w = o.loss.weights(s.r).cwiseSqrt();
    const ScaledSvd svd = scaled_svd(root_w.asDiagonal() * p.jacobian(s.x), o.unseen_share, o.relative_cut);
    const Eigen::VectorXd b = root_w.cwiseProduct(s.r);
    if (!accepted_step(p, o, svd, b, damping, s, s.converged)) {
      // no decrease possible: at a minimum if the gradient is negligible
      const double gradient = (svd.columns.transpose() * b).norm();
      s.converged = gradient <= kGradientTolerance * std::sqrt(2.0 * s.cost + 1e-30) + 1e-15;
      break;
    }
    ++s.iterations;
  }
  return s;
}

}  // namespace ncpost::comp
