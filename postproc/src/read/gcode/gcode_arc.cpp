// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/read/gcode/gcode_arc.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ncpost/kinematics/pose.hpp"

namespace ncpost::gcode {
namespace {

/// Radii may differ between start and end by this much (mm) or this fraction, whichever is larger.
constexpr double kRadiusToleranceMm = 0.01;
constexpr double kRadiusToleranceRelative = 1e-3;
/// Start and end closer than this (mm, in the plane) make a full circle.
constexpr double kSamePointMm = 1e-9;

ArcOutcome finish(const ProgramPoint& start, const ProgramPoint& end, Plane plane, bool clockwise, double c1, double c2,
                  int turns) {
  ArcOutcome out;
  if (turns < 1) {
    out.error = "the number of turns (P) must be a positive integer";
    return out;
  }
  const PlaneAxes ax = axes_of(plane);
  ArcMove a;
  a.start = start;
  a.end = end;
  a.axes = ax;
  a.centre1_mm = c1;
  a.centre2_mm = c2;
  const double s1 = start[ax.a1] - c1, s2 = start[ax.a2] - c2;
  const double e1 = end[ax.a1] - c1, e2 = end[ax.a2] - c2;
  a.radius_start_mm = std::hypot(s1, s2);
  a.radius_end_mm = std::hypot(e1, e2);
  if (!(a.radius_start_mm > kSamePointMm) || !std::isfinite(a.radius_start_mm) || !std::isfinite(a.radius_end_mm)) {
    out.error = "the arc centre coincides with the start point (expected a radius > 0)";
    return out;
  }
  const double dr = std::abs(a.radius_end_mm - a.radius_start_mm);
  const double allowed_mm = std::max(kRadiusToleranceMm, kRadiusToleranceRelative * a.radius_start_mm);
  if (dr > allowed_mm) {
    out.error = fmt::format(
        "the end point is not on the arc: radius {:.4f} mm at the start, {:.4f} mm at the end "
        "(they may differ by {:.4f} mm)",
        a.radius_start_mm, a.radius_end_mm, allowed_mm);
    return out;
  }
  a.angle_start_rad = std::atan2(s2, s1);
  const double angle_end = std::atan2(e2, e1);
  const bool closed = std::hypot(end[ax.a1] - start[ax.a1], end[ax.a2] - start[ax.a2]) <= kSamePointMm;
  double sweep = 0.0;
  if (clockwise) {
    sweep = a.angle_start_rad - angle_end;  // positive amount turned clockwise
  } else {
    sweep = angle_end - a.angle_start_rad;
  }
  sweep = std::fmod(sweep, 2.0 * kPi);
  if (sweep < 0.0) sweep += 2.0 * kPi;
  if (closed || sweep <= 0.0) sweep = 2.0 * kPi;
  sweep += 2.0 * kPi * (turns - 1);
  a.sweep_rad = clockwise ? -sweep : sweep;
  out.arc = a;
  return out;
}

}  // namespace

PlaneAxes axes_of(Plane plane) {
  switch (plane) {
    case Plane::xy:
      return {0, 1, 2};
    case Plane::zx:
      return {2, 0, 1};
    case Plane::yz:
      return {1, 2, 0};
  }
  return {0, 1, 2};
}

ProgramPoint ArcMove::at(double t) const {
  if (t >= 1.0) return end;
  ProgramPoint p;
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = start[i] + t * (end[i] - start[i]);
  const double r = radius_start_mm + t * (radius_end_mm - radius_start_mm);
  const double angle = angle_start_rad + t * sweep_rad;
  p[static_cast<std::size_t>(axes.a1)] = centre1_mm + r * std::cos(angle);
  p[static_cast<std::size_t>(axes.a2)] = centre2_mm + r * std::sin(angle);
  return p;
}

ArcOutcome arc_from_centre(const ProgramPoint& start, const ProgramPoint& end, Plane plane, bool clockwise,
                           double centre1_mm, double centre2_mm, int turns) {
  return finish(start, end, plane, clockwise, centre1_mm, centre2_mm, turns);
}

std::array<double, 2> arc_centre_of(ArcCentre reading, const ProgramPoint& start, PlaneAxes axes, double offset1_mm,
                                    double offset2_mm) {
  const double s1 = start[static_cast<std::size_t>(axes.a1)], s2 = start[static_cast<std::size_t>(axes.a2)];
  switch (reading) {
    case ArcCentre::incremental:
      return {s1 + offset1_mm, s2 + offset2_mm};
    case ArcCentre::centre_to_start:
      return {s1 - offset1_mm, s2 - offset2_mm};
    case ArcCentre::absolute:
      return {offset1_mm, offset2_mm};
  }
  return {s1 + offset1_mm, s2 + offset2_mm};
}

std::string_view arc_centre_name(ArcCentre reading) {
  switch (reading) {
    case ArcCentre::incremental:
      return "incremental";
    case ArcCentre::centre_to_start:
      return "centre-to-start";
    case ArcCentre::absolute:
      return "absolute";
  }
  return "incremental";
}

std::string arc_centre_meaning(ArcCentre reading, std::string_view letters) {
  switch (reading) {
    case ArcCentre::incremental:
      return fmt::format("{} are the vector from the start to the centre", letters);
    case ArcCentre::centre_to_start:
      return fmt::format("{} are the vector from the centre to the start", letters);
    case ArcCentre::absolute:
      return fmt::format("{} are the centre's coordinates", letters);
  }
  return {};
}

ArcOutcome arc_from_radius(const ProgramPoint& start, const ProgramPoint& end, Plane plane, bool clockwise,
                           double radius_mm, int turns) {
  ArcOutcome out;
  const PlaneAxes ax = axes_of(plane);
  const double d1 = end[ax.a1] - start[ax.a1], d2 = end[ax.a2] - start[ax.a2];
  const double chord = std::hypot(d1, d2);
  if (chord <= kSamePointMm) {
    out.error = "an R-format arc needs an end point different from the start point (use I, J, K for a full circle)";
    return out;
  }
  const double r = std::abs(radius_mm);
  const double half = chord / 2.0;
  if (r < half - std::max(kRadiusToleranceMm, kRadiusToleranceRelative * r)) {
    out.error =
        fmt::format("arc radius {:.4f} mm is less than half the distance between its end points ({:.4f} mm)", r, half);
    return out;
  }
  const double h = std::sqrt(std::max(0.0, r * r - half * half));
  // centre to the left of the chord for a short counter-clockwise arc; R < 0 takes the long way
  const double left1 = -d2 / chord, left2 = d1 / chord;
  const double side = ((clockwise ? -1.0 : 1.0) * (radius_mm < 0.0 ? -1.0 : 1.0));
  const double c1 = start[ax.a1] + d1 / 2.0 + side * h * left1;
  const double c2 = start[ax.a2] + d2 / 2.0 + side * h * left2;
  return finish(start, end, plane, clockwise, c1, c2, turns);
}

long arc_segments(const ArcMove& arc, double chord_tolerance_mm) {
  const double r = std::max(arc.radius_start_mm, arc.radius_end_mm);
  const double sweep = std::abs(arc.sweep_rad);
  if (r <= chord_tolerance_mm) return 1;
  // chord error of a segment spanning angle φ: r (1 - cos(φ/2))
  const double step = 2.0 * std::acos(1.0 - chord_tolerance_mm / r);
  const double n = std::ceil(sweep / step);
  if (!(n < static_cast<double>(kMaxArcSegments))) return kMaxArcSegments + 1;
  return std::max(1L, static_cast<long>(n));
}

}  // namespace ncpost::gcode
