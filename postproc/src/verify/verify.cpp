// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/verify/verify.hpp"

#include <algorithm>
#include <cmath>

namespace ncpost {

double distance_to_segment(const Vec3d& p, const Vec3d& a, const Vec3d& b) {
  const Vec3d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

AxisPosition executed_in_plane(const KinematicModel& solver, SolverData& data, const TiltedPlane& plane,
                               const Vec3d& home_offset_mm, const RotaryAngles& rotary_rad, const Vec3d& xyz_F) {
  const Vec3d tip_W = plane.to_program(xyz_F) - home_offset_mm;
  return solver.with_rotary(ClPoint{tip_W, plane.P_R_F.col(2)}, rotary_rad, data);
}

double verify_block(const KinematicModel& solver, const SolverData& data, const ClPoint& cl0, const AxisPosition& q0,
                    const ClPoint& cl1, const AxisPosition& q1, int line, VerifyReport& report, int samples) {
  auto at = [&](double t) {
    AxisPosition q;
    q.linear_mm = q0.linear_mm + t * (q1.linear_mm - q0.linear_mm);
    q.rotary_rad = q0.rotary_rad + t * (q1.rotary_rad - q0.rotary_rad);
    return solver.execute(q, data);
  };
  auto contour = [&](double t) { return distance_to_segment(at(t).tip_mm, cl0.tip_mm, cl1.tip_mm); };
  auto orientation = [&](double t) {
    const Vec3d u = ((1.0 - t) * cl0.axis + t * cl1.axis).normalized();
    const Vec3d e = at(t).axis;
    return std::atan2(u.cross(e).norm(), u.dot(e));
  };
  double best = 0.0, best_t = 0.0;
  for (int i = 0; i <= samples; ++i) {
    const double t = static_cast<double>(i) / samples;
    const double c = contour(t);
    if (c > best) {
      best = c;
      best_t = t;
    }
    report.max_orientation_rad = std::max(report.max_orientation_rad, orientation(t));
  }
  // golden-section refinement around the best sample
  double lo = std::max(0.0, best_t - 1.0 / samples), hi = std::min(1.0, best_t + 1.0 / samples);
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  double f1 = contour(x1), f2 = contour(x2);
  for (int it = 0; it < 40 && hi - lo > 1e-9; ++it) {
    if (f1 > f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - g * (hi - lo);
      f1 = contour(x1);
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + g * (hi - lo);
      f2 = contour(x2);
    }
  }
  best = std::max({best, f1, f2});
  report.max_endpoint_mm =
      std::max({report.max_endpoint_mm, (at(0.0).tip_mm - cl0.tip_mm).norm(), (at(1.0).tip_mm - cl1.tip_mm).norm()});
  record_verified_block(report, best, line);
  return best;
}

void record_verified_block(VerifyReport& report, double contour_mm, int line) {
  if (contour_mm > report.max_contour_mm) {
    report.max_contour_mm = contour_mm;
    report.worst_line = line;
  }
  ++report.blocks;
}

}  // namespace ncpost
