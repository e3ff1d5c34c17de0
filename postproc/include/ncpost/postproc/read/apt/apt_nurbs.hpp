// SPDX-License-Identifier: Apache-2.0
#pragma once
// Rational B-spline curves as NX writes them in a CLSF (`NURBS/`, then `KNOT/` and `CNTRL/`
// records) and their linearization into chords within a tolerance.
//
// Units and frames: control points in mm in W, tool axes (when the file gives one per control
// point) unit vectors in W. The curve is C(u) = sum N_i,p(u) w_i P_i / sum N_i,p(u) w_i on
// [knots[p], knots[n]] (n control points, degree p, n + p + 1 knots).
#include <optional>
#include <string>
#include <vector>

#include "ncpost/kinematics/pose.hpp"

namespace ncpost::cl {

struct NurbsCurve {
  int degree = 0;
  std::vector<double> knots;
  std::vector<Vec3d> points_mm;
  std::vector<double> weights;  ///< one per control point, all > 0
  std::vector<Vec3d> axes;      ///< empty, or one tool axis per control point

  /// "" when the curve is well formed, else what is wrong (for an error message).
  std::string defect() const;
  double u_begin() const { return knots[static_cast<std::size_t>(degree)]; }
  double u_end() const { return knots[points_mm.size()]; }
  Vec3d point_at(double u) const;
  /// The tool axis at u (the axes blended with the curve's own rational basis, normalised).
  std::optional<Vec3d> axis_at(double u) const;
};

/// Parameters u_begin = u_0 < u_1 < ... < u_k = u_end such that each chord C(u_i) C(u_i+1)
/// stays within `tolerance_mm` of the curve between them (checked at interior samples of every
/// chord; chords are halved until they pass). Empty when that takes more than `max_chords`.
std::vector<double> linearize(const NurbsCurve& curve, double tolerance_mm, std::size_t max_chords = 1000000);

}  // namespace ncpost::cl
