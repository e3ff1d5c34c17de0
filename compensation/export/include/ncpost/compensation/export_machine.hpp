// SPDX-License-Identifier: Apache-2.0
#pragma once
// The location errors of an error model applied to the machine file, as a control's kinematic
// calibration does (Heidenhain KinematicsOpt, Siemens CYCLE996, Fanuc 5-axis kinematic
// compensation: measured pivot points and axis directions written into the kinematics): the
// corrected machine, read *nominally*, moves the tool as the original machine with the model does
// (issue 17, `ncpost export --format machine`).
//
// With only location errors the model's rotary axis j turns the body it carries about its actual
// line c_j = P_j + δ_j⊥, d̂_j = Rot(ε_j⊥)·d_j (forward.hpp). The set-up at home absorbs the zero
// errors ε_j∥ of each axis itself, but the zero error of an axis nearer the bed turns the lines
// of the axes it carries: the corrected line of axis k is T_1(0)···T_{k-1}(0) applied to its
// actual line (T_i(0) the transforms at home of the axes between the bed and k, same side). Tool-
// side pivots stay relative to the spindle gauge point. Squareness and every component error
// function, table or reversal cannot be written into a machine file: they are listed as left out.
#include <string>
#include <vector>

#include "ncpost/compensation/machine_model.hpp"

namespace ncpost::comp {

struct MachineExport {
  Machine corrected;                  ///< named "<name>-calibrated"
  std::vector<std::string> applied;   ///< parameter names written into the axis lines
  std::vector<std::string> left_out;  ///< "NAME (why)" for every machine term it cannot hold
};

/// The corrected machine. std::invalid_argument when the model has no location error to apply.
MachineExport corrected_machine(const MachineModel& model);

/// The section of one axis in the machine file ([axes.A], type, direction and pivot, limits).
std::vector<std::string> machine_axis_lines(const Axis& axis);

/// The machine file (docs/formats.md "Machine definition (TOML)") with `notes` as `#` lines on
/// top; numbers with 17 significant digits, so that it reads back to the same machine.
std::string format_machine_toml(const Machine& machine, const std::vector<std::string>& notes);

}  // namespace ncpost::comp
