// SPDX-License-Identifier: Apache-2.0
#pragma once
// A TRR-XY model folded into the machine file (`ncpost export --format machine` on a TRR-XY
// machine; docs/trr-xy.md "Calibrated machine file"): the 30 geometric parameters of the model are
// the deviations of the parallel head from its symmetric design, so the corrected machine is the
// original with [trr_xy.calibration] = its calibration + the model's errors (parameter by parameter;
// each enters the kinematics once, trr_xy_geometry.hpp). Read nominally, it moves the tool exactly
// as the original machine with the model does. The TRR-XY model has no per-axis tables (LinuxCNC,
// SINUMERIK formats): nothing of it is left out of a machine file, and nothing fits a table.
#include <string>
#include <vector>

#include "ncpost/kinematics/trr_xy_geometry.hpp"

namespace ncpost::comp {

struct TrrMachineExport {
  trr::Machine corrected;            ///< named "<name>-calibrated"
  std::vector<std::string> applied;  ///< the names of the model's nonzero parameters
};

/// The corrected machine. std::invalid_argument when every parameter of the model is zero.
TrrMachineExport corrected_trr_machine(const trr::Machine& machine, const trr::Errors& model);

/// The machine file (docs/trr-xy.md "Machine file") with `notes` as `#` lines on top; numbers with
/// 17 significant digits, so that it reads back to the same machine.
std::string format_trr_machine_toml(const trr::Machine& machine, const std::vector<std::string>& notes);

}  // namespace ncpost::comp
