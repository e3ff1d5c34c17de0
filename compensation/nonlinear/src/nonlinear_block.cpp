// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/nonlinear_block.hpp"

#include <algorithm>

namespace ncpost::nonlinear {

AxisPosition lerp(const AxisPosition& q0, const AxisPosition& q1, double t) {
  AxisPosition q;
  q.linear_mm = q0.linear_mm + t * (q1.linear_mm - q0.linear_mm);
  q.rotary_rad = q0.rotary_rad + t * (q1.rotary_rad - q0.rotary_rad);
  return q;
}

double angle_between(const Vec3d& a, const Vec3d& b) { return std::atan2(a.cross(b).norm(), a.dot(b)); }

Vec3d slerp(const Vec3d& u0, const Vec3d& u1, double t) {
  const Vec3d a = u0.normalized();
  const Vec3d b = u1.normalized();
  const double omega = angle_between(a, b);
  if (omega < 1e-9) return ((1.0 - t) * a + t * b).normalized();
  Vec3d normal = a.cross(b);
  if (normal.norm() < 1e-12) {  // antiparallel: any great circle through both
    normal = a.unitOrthogonal();
  }
  normal.normalize();
  // rotate a about the normal of the great circle by t·omega
  return rotation_about<double>(normal, t * omega) * a;
}

ClPoint cl_at(const ClPoint& start, const ClPoint& end, double t) {
  ClPoint p;
  p.tip_mm = start.tip_mm + t * (end.tip_mm - start.tip_mm);
  p.axis = slerp(start.axis, end.axis, t);
  return p;
}

Vec3d lerp_axis(const Vec3d& u0, const Vec3d& u1, double t) {
  const Vec3d v = (1.0 - t) * u0.normalized() + t * u1.normalized();
  const double n = v.norm();
  if (n < 1e-12) return slerp(u0, u1, t);
  return v / n;
}

Vec3d offset_from_segment(const Vec3d& x, const Vec3d& p0, const Vec3d& p1) {
  const Vec3d d = p1 - p0;
  const double len2 = d.squaredNorm();
  if (len2 < 1e-24) return x - p0;
  const double s = std::clamp((x - p0).dot(d) / len2, 0.0, 1.0);
  return x - (p0 + s * d);
}

}  // namespace ncpost::nonlinear
