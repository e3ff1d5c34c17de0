// SPDX-License-Identifier: Apache-2.0
#pragma once
// The message for a CL point the machine cannot reach (exit 3): the solver's reason, and for
// "no solution within the axis limits" which axis of each solution leaves its travel, the value
// it would need and its limits, so that the user knows whether to move the workpiece origin
// (linear travel) or whether the orientation itself is out of the rotary travel.
// Units in the text: mm and degrees.
#include <string>

#include "ncpost/postproc/solve/motion_solver.hpp"

namespace ncpost {

/// For each rotary solution of `cl` (unwound nearest `previous`, the free angle kept at a singular
/// pose), the axes out of their limits: "with A 30.000° C 90.000°: Z would be 612.345 mm (limits
/// -600 to 600 mm)", solutions joined by "; ". Empty when no axis is out of its limits.
/// `linear_out` (if given) is set when a linear axis is among them.
std::string axes_out_of_limits(const KinematicModel& solver, SolverData& data, const ClPoint& cl,
                               const AxisPosition& previous, bool* linear_out = nullptr);

/// "INPUT:LINE: why[: axes_out_of_limits] (tip x, y, z mm, axis i, j, k)[; what to do]".
std::string unreachable_message(const std::string& input, int line, const KinematicModel& solver, SolverData& data,
                                const ClPoint& cl, const AxisPosition& previous, const std::string& why);

}  // namespace ncpost
