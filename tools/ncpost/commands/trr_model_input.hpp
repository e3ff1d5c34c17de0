// SPDX-License-Identifier: Apache-2.0
#pragma once
// A TRR-XY model JSON for a command (post, preview, simulate): read and checked like a serial
// machine's (model_input.hpp), the TRR-XY parameters (trr_model.hpp).
#include <string>

#include "ncpost/kinematics/trr_xy_geometry.hpp"

namespace ncpost::cli {

/// The errors of the model at `path` for the machine `machine_name`, checked (trr::ModelChecks);
/// with `force_model` the failed checks are printed as warnings and the model is applied.
trr::Errors read_trr_model(const std::string& path, const std::string& machine_name, bool force_model);

}  // namespace ncpost::cli
