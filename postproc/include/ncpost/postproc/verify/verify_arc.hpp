// SPDX-License-Identifier: Apache-2.0
#pragma once
// Built-in verification of a native arc block (G2/G3, `post --verify`): the control interpolates
// the circle in the program's frame (the machine's linear axes with the rotary axes standing, or a
// tilted work plane) from the written words; each point goes through the machine's forward
// kinematics and its distance from the CL circle is the contour error (mm, in W). Frames: the
// program's frame for FrameArc, W for ClArc.
#include <functional>

#include "ncpost/postproc/verify/verify.hpp"

namespace ncpost {

/// A G2/G3 block as the control runs it (program frame, mm): from `start` about `centre` to `end`,
/// `sweep_rad` counter-clockwise about the unit `normal`; the radius goes linearly from the start's
/// to the end's (controls accept a few µm between them) and a helix rises linearly along `normal`.
struct FrameArc {
  Vec3d start_mm, centre_mm, end_mm, normal;
  double sweep_rad = 0.0;
  Vec3d at(double t) const;  ///< t in [0, 1]
};

/// The CL circle (W): from `start_mm` to `end_mm`, `sweep_rad` counter-clockwise about the unit
/// `axis` through `centre_mm`, with the same radius and rise rules; the tool axis `tool_axis`.
struct ClArc {
  Vec3d start_mm, centre_mm, end_mm, axis, tool_axis;
  double sweep_rad = 0.0;
  /// Distance of `p` from the arc: the nearest of the points at the angle of `p` about the axis
  /// (on every turn of the sweep) and the two ends (an upper bound of the true distance on a helix).
  double distance(const Vec3d& p) const;
};

/// Adds one arc block to the report and returns its contour error (mm). `commands_at` gives the
/// machine commands the control reaches at a point of the program frame.
double verify_arc(const KinematicModel& solver, const SolverData& data, const FrameArc& executed,
                  const std::function<AxisPosition(const Vec3d&)>& commands_at, const ClArc& cl, int line,
                  VerifyReport& report, int samples = 48);

}  // namespace ncpost
