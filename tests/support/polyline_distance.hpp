// SPDX-License-Identifier: Apache-2.0
#pragma once
// Distance from a point to a polyline (a CL path), for tests that ask it for many points along an
// executed program (trr_program.hpp). Every segment is measured, except those that cannot be nearer
// than the best so far: for any point q of a segment with middle c and half length r,
// |p - q| >= |p - c| - r, so a segment with |p - c| >= best + r is skipped. The answer is the
// smallest distance over all segments, as by measuring each (segment_distance_mm).
#include <algorithm>
#include <cstddef>
#include <vector>

#include "ncpost/kinematics/pose.hpp"

namespace ncpost::test {

/// Distance (mm) from `p` to the segment from `a` to `b`.
inline double segment_distance_mm(const Vec3d& p, const Vec3d& a, const Vec3d& b) {
  const Vec3d d = b - a;
  const double len2 = d.squaredNorm();
  const double u = len2 > 0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + u * d)).norm();
}

/// A polyline with each segment's middle and half length, for many distance queries.
class PolylineDistance {
 public:
  explicit PolylineDistance(std::vector<Vec3d> points) : points_(std::move(points)) {
    for (std::size_t i = 0; i + 1 < points_.size(); ++i) {
      middles_.push_back(0.5 * (points_[i] + points_[i + 1]));
      half_lengths_.push_back(0.5 * (points_[i + 1] - points_[i]).norm());
    }
  }

  /// Distance (mm) from `p` to the polyline (1e300 if it has no segment). Starts from the segment
  /// nearest to the previous point asked (successive points along a path are near each other).
  double operator()(const Vec3d& p) const {
    if (middles_.empty()) return 1e300;
    double best = segment_distance_mm(p, points_[last_], points_[last_ + 1]);
    for (std::size_t i = 0; i < middles_.size(); ++i) {
      const double reach = best + half_lengths_[i] + kMarginMm;
      if ((p - middles_[i]).squaredNorm() >= reach * reach) continue;
      const double d = segment_distance_mm(p, points_[i], points_[i + 1]);
      if (d < best) {
        best = d;
        last_ = i;
      }
    }
    return best;
  }

 private:
  static constexpr double kMarginMm = 1e-9;  // rounding of the bound: a segment this close is measured
  std::vector<Vec3d> points_;
  std::vector<Vec3d> middles_;
  std::vector<double> half_lengths_;
  mutable std::size_t last_ = 0;
};

}  // namespace ncpost::test
