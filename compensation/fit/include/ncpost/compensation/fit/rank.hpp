// SPDX-License-Identifier: Apache-2.0
#pragma once
// The fitting core (compensation/fit/, docs/architecture.md), rank part: which parameters to fit.
// Identifiability of parameters from a Jacobian (Ceres covariance.h discusses the same problem):
// columns are scaled to unit norm (so that mm and rad parameters compare), the singular values
// of the scaled Jacobian give the rank, and a maximal independent set of parameters is chosen in
// priority order (the order given). Every other parameter is *pinned* (held at its prior value);
// its null-space direction expresses it as the combination of kept parameters that has the
// same effect on the data, so that the kept values carry the observable combination.
//
// A column counts as dependent when its distance from the span of the kept columns (both
// scaled: the sine of the angle between the column and that span) is below `tolerance`. The
// default 1e-3 treats as unobservable the exact couplings and the first-order ones whose only
// difference is second order in the errors (seed 000 at one height: ~1e-6; seed 002 at one
// tool length: ~2e-5): a parameter whose effect differs from a combination of the others by
// less than 0.1 % of itself cannot be separated from them at any realistic noise (its
// uncertainty would be ~1000 times its effect-to-noise ratio). Genuinely observable parameters
// of the tests here stay above 0.05. A column shorter than 1e-9 of the longest counts as zero.
//
// This is the rule for callers with a priority order (ballbar/sphere and laser identification):
// it pins whole parameters before the fit. A caller without one (TRR-XY) lets the solver
// truncate the singular values of the same column-scaled Jacobian instead (scaled_svd.hpp).
#include <string>
#include <vector>

#include <Eigen/Core>

namespace ncpost::comp {

struct RankAnalysis {
  int rank = 0;
  Eigen::VectorXd singular_values;            ///< of the column-scaled Jacobian, descending
  Eigen::VectorXd column_norms;               ///< the scaling
  std::vector<int> kept;                      ///< column indices, in priority order
  std::vector<int> pinned;                    ///< column indices
  std::vector<Eigen::VectorXd> null_vectors;  ///< one per pinned column, unit, in scaled space
};

/// `typical` (optional, one per column): a plausible size of each parameter (e.g. 0.01 mm,
/// 5e-5 rad). A column whose effect at that size is below `tolerance` times the largest such
/// effect counts as without effect: scaling alone would hide a parameter seen only at second
/// order (e.g. a B-line tilt read along X and Z only).
RankAnalysis analyse_rank(const Eigen::MatrixXd& J, double tolerance = 1e-3,
                          const Eigen::VectorXd& typical = Eigen::VectorXd());

}  // namespace ncpost::comp
