// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/verify/verify_arc.hpp"
#include "ncpost/kinematics/units.hpp"

#include <algorithm>
#include <cmath>

#include "ncpost/kinematics/pose.hpp"

namespace ncpost {
namespace {

/// The part of `v` in the plane normal to the unit `n`.
Vec3d in_plane(const Vec3d& v, const Vec3d& n) { return v - v.dot(n) * n; }

/// A point of the arc about `centre` (normal `n`) from `start` to `end`, `sweep` rad, at angle `phi`.
Vec3d arc_point(const Vec3d& start, const Vec3d& centre, const Vec3d& end, const Vec3d& n, double sweep, double phi) {
  const Vec3d r0 = start - centre, r1 = end - centre;
  const Vec3d p0 = in_plane(r0, n), p1 = in_plane(r1, n);
  const double s = sweep > 0.0 ? phi / sweep : 0.0;
  const double radius = p0.norm() + s * (p1.norm() - p0.norm());
  const double rise = r0.dot(n) + s * (r1.dot(n) - r0.dot(n));
  const Vec3d dir = rotation_about<double>(n, phi) * p0.normalized();
  return centre + radius * dir + rise * n;
}

}  // namespace

Vec3d FrameArc::at(double t) const { return arc_point(start_mm, centre_mm, end_mm, normal, sweep_rad, t * sweep_rad); }

double ClArc::distance(const Vec3d& p) const {
  const Vec3d p0 = in_plane(start_mm - centre_mm, axis), v = in_plane(p - centre_mm, axis);
  const auto at = [&](double phi) { return (p - arc_point(start_mm, centre_mm, end_mm, axis, sweep_rad, phi)).norm(); };
  double best = std::min(at(0.0), at(sweep_rad));  // the ends
  if (v.norm() > 1e-12 && p0.norm() > 1e-12) {
    // the angle of p about the axis, on every turn the sweep covers (a full circle's helix ends
    // where it started, one pitch lower)
    double phi = std::atan2(p0.cross(v).dot(axis), p0.dot(v));
    if (phi < 0.0) phi += kTwoPi;
    for (; phi <= sweep_rad; phi += kTwoPi) best = std::min(best, at(phi));
  }
  return best;
}

double verify_arc(const KinematicModel& solver, const SolverData& data, const FrameArc& executed,
                  const std::function<AxisPosition(const Vec3d&)>& commands_at, const ClArc& cl, int line,
                  VerifyReport& report, int samples) {
  double best = 0.0;
  for (int i = 0; i <= samples; ++i) {
    const double t = static_cast<double>(i) / samples;
    const ToolPoseT<double> pose = solver.execute(commands_at(executed.at(t)), data);
    best = std::max(best, cl.distance(pose.tip_mm));
    report.max_orientation_rad = std::max(
        report.max_orientation_rad, std::atan2(cl.tool_axis.cross(pose.axis).norm(), cl.tool_axis.dot(pose.axis)));
    if (i == 0) report.max_endpoint_mm = std::max(report.max_endpoint_mm, (pose.tip_mm - cl.start_mm).norm());
    if (i == samples) report.max_endpoint_mm = std::max(report.max_endpoint_mm, (pose.tip_mm - cl.end_mm).norm());
  }
  record_verified_block(report, best, line);
  return best;
}

}  // namespace ncpost
