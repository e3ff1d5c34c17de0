// SPDX-License-Identifier: Apache-2.0
#pragma once
// Compensated inverse kinematics: the commands that make the *actual* machine (MachineModel)
// put the tool tip on the CL point with the CL tool axis (docs/conventions.md "Nominal closure", with
// the error model in the chain). For `post --model` (issue 5).
//
// Method: Newton–Gauss from the nominal solution. Unknowns: the five commands (mm, rad).
// Equations: the tip in W (3, mm) and the actual tool axis projected on two unit vectors
// perpendicular to the CL axis (2, rad) — the axis has two degrees of freedom, so 5 equations for
// 5 unknowns. Jacobian by automatic differentiation of the templated chain with respect to the
// commands; steps by a truncated-SVD pseudo-inverse, so that near the singular orientation
// (free outer angle) the free angle stays at its nominal value. Converged when the tip is within
// `tip_tolerance_mm` and the axis within `axis_tolerance_rad`. A three-axis machine (no rotary
// axes) cannot turn the tool: it solves the tip only, and `axis_error_rad` reports the tilt its
// angular errors leave (issue 7).
//
// Reversal: with `previous_actual` (where each axis actually stands, after the previous block)
// the dead band makes the actual position a non-smooth function of the command (a play: it stands
// still while the command crosses the band). The solver first finds where the axes must actually
// go (no offsets), which gives each axis with reversal the side of its band the motion implies
// (rising, falling, or standing where the needed move is within the tolerances), solves the
// commands with the axes held on those sides, and checks the result on the exact dead band; where
// that choice fails, every other choice of sides is tried before giving up. Without history the
// offsets are 0 (approach from below).
#include <optional>
#include <string>

#include "ncpost/compensation/machine_model.hpp"

namespace ncpost::comp {

struct ActualIkOptions {
  double tip_tolerance_mm = 1e-6;
  double axis_tolerance_rad = 1e-8;
  int max_iterations = 30;
  std::optional<AxisPosition> previous_actual;  ///< for reversal: where the axes actually are
  /// for reversal: the commands that put them there (an axis that need not move keeps its command)
  std::optional<AxisPosition> previous_command;
  const HomeInverse* home = nullptr;  ///< the model's home inverse (home_inverse), if computed
  /// The CL point whose nominal IK solution the guess is (the CL point itself, or the CL point less
  /// a predicted error of the machine), if it is one (not programmed angles): its nominal pose is
  /// then known, so the first step needs no nominal evaluation.
  std::optional<ClPoint> guess_solves;
};

struct ActualIkOutcome {
  std::optional<AxisPosition> position;  ///< the commands
  AxisPosition actual;                   ///< where the axes actually go (command + reversal offset)
  int iterations = 0;
  double tip_error_mm = 0.0;    ///< remaining |tip − CL tip|
  double axis_error_rad = 0.0;  ///< remaining angle between the actual and the CL axis
  /// The actual tool pose at `position` (W), when the fixed-point iteration evaluated it there
  std::optional<ToolPoseT<double>> actual_pose;
  std::string message;  ///< why it failed, when !position
  bool ok() const { return position.has_value(); }
};

ActualIkOutcome solve_actual(const MachineModel& model, const ClPoint& cl, const Setup& setup,
                             const AxisPosition& nominal_guess, const ActualIkOptions& options = {});

/// Reversal offsets (actual − command per axis) of moving to `command` from `previous_actual`.
RowState<double> reversal_state(const MachineModel& model, const AxisPosition& command,
                                const std::optional<AxisPosition>& previous_actual);

/// Where the axes actually stand after moving to `command` from `previous_actual` (command plus
/// its reversal offsets; the command itself without history).
AxisPosition actual_after(const MachineModel& model, const AxisPosition& command,
                          const std::optional<AxisPosition>& previous_actual);

}  // namespace ncpost::comp
