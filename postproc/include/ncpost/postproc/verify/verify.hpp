// SPDX-License-Identifier: Apache-2.0
#pragma once
// Built-in verification (`post --verify`): re-executes each emitted block as the control does
// (linear interpolation in axis space of the rounded commands, docs/conventions.md "Execution model")
// through the forward kinematics, and measures the contour error (distance of the executed tool
// tip from the straight CL segment, mm, in W) and the orientation error (angle between the executed
// tool axis and the normalised linearly interpolated CL axis, rad).
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "ncpost/postproc/solve/motion_solver.hpp"
#include "ncpost/postproc/write/tilted_plane.hpp"

namespace ncpost {

struct VerifyReport {
  /// What the written program does other than the input meant, each "program line N (CL line L):
  /// what": a rapid that leaves its retract line, an arc the wrong way round, a feed word off its
  /// rule, a motion word of the wrong kind. `post --verify` with any of these writes no program.
  std::vector<std::string> defects;
  std::size_t blocks = 0;
  double max_contour_mm = 0.0;
  double max_orientation_rad = 0.0;
  double max_endpoint_mm = 0.0;  ///< error at block ends (rounding, model)
  int worst_line = 0;            ///< CL line of the block with the largest contour error
};

/// The written program does not do what the input meant (VerifyReport::defects): exit 5, no output.
class VerifyFailed : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Counts one verified block of contour error `contour_mm` (CL line `line`) in the report.
void record_verified_block(VerifyReport& report, double contour_mm, int line);

/// Adds one block from (cl0, q0) to (cl1, q1), executed on `solver`'s machine, to the report and
/// returns its contour error (mm). `samples` points per block, refined around the largest by
/// golden-section search.
double verify_block(const KinematicModel& solver, const SolverData& data, const ClPoint& cl0, const AxisPosition& q0,
                    const ClPoint& cl1, const AxisPosition& q1, int line, VerifyReport& report, int samples = 24);

/// The commands the control executes for the words X Y Z `xyz_F` (as written) of a block in the
/// tilted plane `plane` (its words as written): the plane's transform into the program frame at
/// home P, into W (W = P - `home_offset_mm`), then the machine with the rotary axes at
/// `rotary_rad` (where the control turned them: the tool along the plane's Z). verify_block of two
/// such commands measures the block as the control runs it.
AxisPosition executed_in_plane(const KinematicModel& solver, SolverData& data, const TiltedPlane& plane,
                               const Vec3d& home_offset_mm, const RotaryAngles& rotary_rad, const Vec3d& xyz_F);

/// Distance of `p` from the segment a-b.
double distance_to_segment(const Vec3d& p, const Vec3d& a, const Vec3d& b);

}  // namespace ncpost
