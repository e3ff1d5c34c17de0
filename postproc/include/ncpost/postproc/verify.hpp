// SPDX-License-Identifier: Apache-2.0
#pragma once
// Built-in verification (`post --verify`): re-executes each emitted block as the control does
// (linear interpolation in axis space of the rounded commands, docs/conventions.md "Execution model")
// through the forward kinematics, and measures the contour error (distance of the executed tool
// tip from the straight CL segment, mm, in W) and the orientation error (angle between the executed
// tool axis and the normalised linearly interpolated CL axis, rad).
#include <cstddef>

#include "ncpost/postproc/motion_solver.hpp"

namespace ncpost {

struct VerifyReport {
  std::size_t blocks = 0;
  double max_contour_mm = 0.0;
  double max_orientation_rad = 0.0;
  double max_endpoint_mm = 0.0;  ///< error at block ends (rounding, model)
  int worst_line = 0;            ///< CL line of the block with the largest contour error
};

/// Adds one block from (cl0, q0) to (cl1, q1), executed on `solver`'s machine, to the report and
/// returns its contour error (mm). `samples` points per block, refined around the largest by
/// golden-section search.
double verify_block(const MotionSolver& solver, const ClPoint& cl0, const AxisPosition& q0, const ClPoint& cl1,
                  const AxisPosition& q1, int line, VerifyReport& report, int samples = 24);

/// Distance of `p` from the segment a-b.
double distance_to_segment(const Vec3d& p, const Vec3d& a, const Vec3d& b);

}  // namespace ncpost
