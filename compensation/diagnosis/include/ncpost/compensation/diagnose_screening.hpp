// SPDX-License-Identifier: Apache-2.0
#pragma once
// Linearised screening of candidate effects (diagnose.hpp, step 1). Everything acts on Jacobian
// columns of the residual (residuals.hpp: mm per parameter unit) at the current solution and on
// an orthonormal basis Q of the span of the model's fitted columns.
//
//   added_basis      the orthonormal directions a candidate's columns add to span(Q); a column
//                    keeping no more than `tol` of its norm (the sine of its angle to the span, as
//                    fit/rank.hpp) is aliased. The residual's projection on the added
//                    directions is the drop in Σr² the candidate buys (exact for a linear model).
//   same_directions  two candidates adding the same directions: the data cannot tell them apart.
//   screen_drift     drift along one axis: lin·t, exp·(1 − e^(−t/tau)) or both. Both columns are
//                    law(t) · d r / d drift, so every exp column follows from the lin one; tau from
//                    a log grid of 61 values (30 s … 4 × t_span) refined by a parabola in log tau;
//                    the simpler single term is kept, both only if the second is significant alone
//                    (F test at 1 % of `significance`).
//   f_upper_tail     P(F > f) of the F distribution with (k, dof) degrees of freedom.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "ncpost/compensation/error_parameters.hpp"

namespace ncpost::comp {

double f_upper_tail(double f, double k, double dof);

/// `aliased_column`: -1 if every column of C adds a direction, else the first that does not.
Eigen::MatrixXd added_basis(const Eigen::MatrixXd& Q, const Eigen::MatrixXd& C, double tol, int& aliased_column);

bool same_directions(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, double tol);

struct DriftScreen {
  bool aliased = true;                  ///< no variant adds a direction
  std::vector<std::string> parameters;  ///< `effect`:lin and / or `effect`:exp
  ErrorParameters held;                 ///< `effect`:tau (s), when exp is in
  double drop = 0.0;                    ///< Σr² it buys (mm²)
  Eigen::MatrixXd basis;                ///< its added directions
};

/// `lin_column`: d r / d (effect:lin); `time_s`: the time stamp of every residual.
DriftScreen screen_drift(const std::string& effect, const Eigen::MatrixXd& Q, const Eigen::VectorXd& lin_column,
                         const Eigen::VectorXd& r, const Eigen::VectorXd& time_s, double t_span_s, double tol,
                         double significance);

}  // namespace ncpost::comp
