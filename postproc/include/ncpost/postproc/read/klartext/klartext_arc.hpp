// SPDX-License-Identifier: Apache-2.0
#pragma once
// The circular paths of Klartext (TNC 426 ... 640 user manual, "Path contours - Cartesian
// coordinates" and "Helical interpolation") as arcs in the working plane X Y (tool axis Z):
//   C  X Y DR±        about the centre CC to the end (DR+ counter-clockwise seen from +Z)
//   CR X Y R± DR±     radius R: R+ the arc up to 180 deg, R- the arc beyond 180 deg
//   CT X Y            tangential to the previous contour element
//   CP PA|IPA [Z|IZ] DR±  about CC to the polar angle (IPA: the total angle, several turns, a
//                     helix with IZ); the signs of IPA and DR must agree.
// Program coordinates (gcode::ProgramPoint: X Y Z mm, A B C rad); angles in rad; the result is a
// gcode::ArcMove, so that the G-code reader's arc expansion and chord bound apply unchanged.
#include <optional>
#include <string>

#include <Eigen/Core>

#include "ncpost/postproc/read/gcode/gcode_arc.hpp"

namespace ncpost::klartext {

using gcode::ArcMove;
using gcode::ProgramPoint;

/// An arc, or why there is none (a sentence for the message).
struct ArcResult {
  std::optional<ArcMove> arc;
  std::string error;
};

/// Start and end radius may differ by this much (mm) in C (the TNC's "circle end point" check).
inline constexpr double kCircleEndToleranceMm = 0.005;

/// C: from `start` to `end` about `centre_xy`; start = end in the plane is a full circle.
ArcResult arc_about_centre(const ProgramPoint& start, const ProgramPoint& end, const Eigen::Vector2d& centre_xy,
                           bool counter_clockwise);

/// CR: from `start` to `end` with the signed radius `radius_mm` (> 0: up to 180 deg).
ArcResult arc_by_radius(const ProgramPoint& start, const ProgramPoint& end, double radius_mm, bool counter_clockwise);

/// CT: from `start` to `end`, leaving `start` along `tangent_xy` (unit).
ArcResult arc_tangent(const ProgramPoint& start, const ProgramPoint& end, const Eigen::Vector2d& tangent_xy);

/// CP: about `centre_xy` from `start` through `sweep_rad` (signed, > 0 counter-clockwise, may exceed
/// a turn), Z going to `end_z_mm`.
ArcResult arc_polar(const ProgramPoint& start, const Eigen::Vector2d& centre_xy, double sweep_rad, double end_z_mm);

/// The signed sweep from polar angle `from_rad` to `to_rad` in the direction given, in (0, 2 pi]
/// counter-clockwise or [-2 pi, 0) clockwise (equal angles: a full turn).
double sweep_between(double from_rad, double to_rad, bool counter_clockwise);

/// The unit direction of travel in the plane at the end of `arc`.
Eigen::Vector2d end_tangent(const ArcMove& arc);

}  // namespace ncpost::klartext
