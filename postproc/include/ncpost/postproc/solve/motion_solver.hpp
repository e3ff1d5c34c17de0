// SPDX-License-Identifier: Apache-2.0
#pragma once
// How the post turns a CL point into axis commands, and how it re-executes commands: through the
// kinematic model interface (kinematics/kinematic_model.hpp) with its per-thread data
// (kinematics/solver_data.hpp): the nominal serial chain, the actual machine of `post --model`
// (actual_solver.hpp) or the TRR-XY machine (trr_solver.hpp).
#include "ncpost/kinematics/kinematic_model.hpp"
#include "ncpost/kinematics/serial_chain_model.hpp"

namespace ncpost {

/// The post's names for the kinematic model and the nominal serial chain (kept for code written
/// against them).
using MotionSolver = KinematicModel;
using NominalSolver = SerialChainModel;

}  // namespace ncpost
