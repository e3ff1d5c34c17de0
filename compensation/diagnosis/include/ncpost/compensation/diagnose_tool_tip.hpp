// SPDX-License-Identifier: Apache-2.0
#pragma once
// Predicted tool-tip error of the machine before and after compensation (issue 6, step 4), over
// a sample of the working space: commands uniform within the axis limits (linear axes capped to
// ±250 mm, rotary axes without limits over a full turn), workpiece origin and tool length 0
// (the tool tip at the table point under it). Measurement-only effects (drift, instruments) are
// not part of either machine (machine_model.hpp).
//
//   uncompensated        |tip(final model) − tip(nominal)|   the machine's error as identified
//   basic compensation   |tip(final model) − tip(basic)|     left after compensating with the
//                                                            basic model only
//   final model          its 1σ tool-tip uncertainty √trace(J C Jᵀ), J = d tip / d parameters
//                        (finite differences), C the covariance of the fitted parameters: what
//                        compensating with it leaves, as far as the data can tell
// Tip deviations in W, µm; axis deviations in µrad. Deterministic sample (fixed seed).
#include <Eigen/Core>

#include "ncpost/compensation/error_parameters.hpp"
#include "ncpost/kinematics/machine.hpp"

namespace ncpost::comp {

struct ToolTipComparison {
  int poses = 0;
  double uncompensated_max_um = 0.0, uncompensated_rms_um = 0.0;
  double basic_left_max_um = 0.0, basic_left_rms_um = 0.0;
  double basic_left_axis_max_urad = 0.0;
  double final_sigma_max_um = 0.0, final_sigma_rms_um = 0.0;
};

/// `final_sigma` / `final_covariance`: the fitted parameters' standard deviations (their names
/// and order) and covariance; empty: no uncertainty figures.
ToolTipComparison compare_tool_tip(const Machine& machine, const ErrorParameters& final_model,
                                   const ErrorParameters& basic_model, const ErrorParameters& final_sigma = {},
                                   const Eigen::MatrixXd& final_covariance = {}, int poses = 2000);

}  // namespace ncpost::comp
