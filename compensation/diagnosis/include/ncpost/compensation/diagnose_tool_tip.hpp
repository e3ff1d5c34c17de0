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
//
// A claim names where it holds (issue 25 item 4): `measured_region` is the box of the commands the
// data cover, per axis; sampled within it (`region`), the figures are those the measurements
// support; over the working space beyond it they rest on the model's form (location errors
// constant along the axes), which no measurement there confirms — e.g. with one ballbar height,
// Z is measured at one position only.
#include <Eigen/Core>

#include <string>
#include <vector>

#include "ncpost/compensation/error_parameters.hpp"
#include "ncpost/compensation/measurement.hpp"
#include "ncpost/kinematics/machine.hpp"

namespace ncpost::comp {

/// Per axis of the machine, the range the poses are drawn from (mm, rad).
struct PoseRegion {
  std::vector<double> lo, hi;
  /// "X −100 … 100 mm, Y …, Z 250 mm only, A −90 … 90°, C 0 … 360°"
  std::string description(const Machine& machine) const;
  /// The axes held at one position ("Z"), empty if every axis moved.
  std::string single_position_axes(const Machine& machine) const;
};

/// The box of the commands of every row of the sets.
PoseRegion measured_region(const Machine& machine, const std::vector<MeasurementSet>& sets);

struct ToolTipComparison {
  int poses = 0;
  double uncompensated_max_um = 0.0, uncompensated_rms_um = 0.0;
  double basic_left_max_um = 0.0, basic_left_rms_um = 0.0;
  double basic_left_axis_max_urad = 0.0;
  double final_sigma_max_um = 0.0, final_sigma_rms_um = 0.0;
  /// Set by `within_measured_region`: the same figures sampled within the measured region, its
  /// description and the axes it holds at one position (empty: not computed).
  std::string measured_region, single_position_axes;
  double measured_uncompensated_max_um = 0.0, measured_sigma_max_um = 0.0, measured_sigma_rms_um = 0.0;
};

/// `final_sigma` / `final_covariance`: the fitted parameters' standard deviations (their names
/// and order) and covariance; empty: no uncertainty figures.
ToolTipComparison compare_tool_tip(const Machine& machine, const ErrorParameters& final_model,
                                   const ErrorParameters& basic_model, const ErrorParameters& final_sigma = {},
                                   const Eigen::MatrixXd& final_covariance = {}, int poses = 2000,
                                   const PoseRegion* region = nullptr);

/// `comparison` (over the working space) with the figures within the measured region of `sets` added.
ToolTipComparison within_measured_region(ToolTipComparison comparison, const Machine& machine,
                                         const std::vector<MeasurementSet>& sets, const ErrorParameters& final_model,
                                         const ErrorParameters& basic_model, const ErrorParameters& final_sigma,
                                         const Eigen::MatrixXd& final_covariance, int poses = 2000);

}  // namespace ncpost::comp
