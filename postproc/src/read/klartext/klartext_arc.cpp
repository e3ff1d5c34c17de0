// SPDX-License-Identifier: Apache-2.0
// Klartext circular paths as arcs in the X Y plane (klartext_arc.hpp).
#include "ncpost/postproc/read/klartext/klartext_arc.hpp"

#include <fmt/format.h>

#include <cmath>

#include "ncpost/kinematics/pose.hpp"

namespace ncpost::klartext {
namespace {

constexpr double kTurn = 2.0 * kPi;
constexpr double kSamePointMm = 1e-9;

Eigen::Vector2d xy(const ProgramPoint& p) { return {p[0], p[1]}; }

/// The arc from `start` to `end` about `centre` through `sweep_rad`.
ArcMove make_arc(const ProgramPoint& start, const ProgramPoint& end, const Eigen::Vector2d& centre, double sweep_rad) {
  ArcMove a;
  a.start = start;
  a.end = end;
  a.axes = gcode::axes_of(gcode::Plane::xy);
  a.centre1_mm = centre.x();
  a.centre2_mm = centre.y();
  a.radius_start_mm = (xy(start) - centre).norm();
  a.radius_end_mm = (xy(end) - centre).norm();
  a.angle_start_rad = std::atan2(start[1] - centre.y(), start[0] - centre.x());
  a.sweep_rad = sweep_rad;
  return a;
}

double polar_angle(const ProgramPoint& p, const Eigen::Vector2d& centre) {
  return std::atan2(p[1] - centre.y(), p[0] - centre.x());
}

}  // namespace

double sweep_between(double from_rad, double to_rad, bool counter_clockwise) {
  double d = std::fmod(to_rad - from_rad, kTurn);
  if (counter_clockwise) {
    if (d < 0.0) d += kTurn;
    if (d <= 1e-12) d += kTurn;
  } else {
    if (d > 0.0) d -= kTurn;
    if (d >= -1e-12) d -= kTurn;
  }
  return d;
}

Eigen::Vector2d end_tangent(const ArcMove& arc) {
  const double a = arc.angle_start_rad + arc.sweep_rad;
  const double s = arc.sweep_rad > 0.0 ? 1.0 : -1.0;
  return {-s * std::sin(a), s * std::cos(a)};
}

ArcResult arc_about_centre(const ProgramPoint& start, const ProgramPoint& end, const Eigen::Vector2d& centre_xy,
                           bool counter_clockwise) {
  ArcResult out;
  const double r0 = (xy(start) - centre_xy).norm(), r1 = (xy(end) - centre_xy).norm();
  if (!(r0 > kSamePointMm)) {
    out.error = "the circle centre CC is the start point (radius 0)";
    return out;
  }
  if (std::abs(r1 - r0) > kCircleEndToleranceMm) {
    out.error = fmt::format(
        "the end point is {:.4f} mm from the centre CC X{:+.4f} Y{:+.4f}, the start {:.4f} mm: "
        "not on the circle (the TNC stops here too); check CC",
        r1, centre_xy.x(), centre_xy.y(), r0);
    return out;
  }
  const double sweep = sweep_between(polar_angle(start, centre_xy), polar_angle(end, centre_xy), counter_clockwise);
  out.arc = make_arc(start, end, centre_xy, sweep);
  return out;
}

ArcResult arc_by_radius(const ProgramPoint& start, const ProgramPoint& end, double radius_mm, bool counter_clockwise) {
  ArcResult out;
  const Eigen::Vector2d chord = xy(end) - xy(start);
  const double d = chord.norm();
  const double r = std::abs(radius_mm);
  if (d < kSamePointMm) {
    out.error = "CR with the end at the start: a full circle has no centre by radius (program it with CC and C)";
    return out;
  }
  if (!(r > 0.0) || d > 2.0 * r + kCircleEndToleranceMm) {
    out.error = fmt::format("the end is {:.4f} mm from the start, more than the diameter {:.4f} of R{:+.4f}", d,
                            2.0 * r, radius_mm);
    return out;
  }
  const Eigen::Vector2d u = chord / d;
  const Eigen::Vector2d left(-u.y(), u.x());
  const double h = std::sqrt(std::max(0.0, r * r - 0.25 * d * d));
  const double side = (counter_clockwise ? 1.0 : -1.0) * (radius_mm > 0.0 ? 1.0 : -1.0);
  const Eigen::Vector2d centre = xy(start) + 0.5 * chord + side * h * left;
  const double sweep = sweep_between(polar_angle(start, centre), polar_angle(end, centre), counter_clockwise);
  out.arc = make_arc(start, end, centre, sweep);
  return out;
}

ArcResult arc_tangent(const ProgramPoint& start, const ProgramPoint& end, const Eigen::Vector2d& tangent_xy) {
  ArcResult out;
  const Eigen::Vector2d d = xy(end) - xy(start);
  const Eigen::Vector2d left(-tangent_xy.y(), tangent_xy.x());
  const double across = d.dot(left);
  if (d.norm() < kSamePointMm || std::abs(across) < 1e-9 * std::max(1.0, d.norm())) {
    out.error = "the end lies on the tangent of the previous element: a line, not an arc (program L)";
    return out;
  }
  const double k = d.squaredNorm() / (2.0 * across);  // signed distance of the centre to the left
  const Eigen::Vector2d centre = xy(start) + k * left;
  const bool ccw = k > 0.0;
  const double sweep = sweep_between(polar_angle(start, centre), polar_angle(end, centre), ccw);
  out.arc = make_arc(start, end, centre, sweep);
  return out;
}

ArcResult arc_polar(const ProgramPoint& start, const Eigen::Vector2d& centre_xy, double sweep_rad, double end_z_mm) {
  ArcResult out;
  const double r = (xy(start) - centre_xy).norm();
  if (!(r > kSamePointMm)) {
    out.error = "the pole CC is the start point (radius 0)";
    return out;
  }
  if (!(std::abs(sweep_rad) > 1e-12)) {
    out.error = "a polar arc through 0 deg";
    return out;
  }
  const double a1 = polar_angle(start, centre_xy) + sweep_rad;
  ProgramPoint end = start;
  end[0] = centre_xy.x() + r * std::cos(a1);
  end[1] = centre_xy.y() + r * std::sin(a1);
  end[2] = end_z_mm;
  out.arc = make_arc(start, end, centre_xy, sweep_rad);
  return out;
}

}  // namespace ncpost::klartext
