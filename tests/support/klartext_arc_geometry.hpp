// SPDX-License-Identifier: Apache-2.0
#pragma once
// The circular paths of Heidenhain Klartext for the tests' interpreter (klartext_interpreter.hpp),
// written from the TNC 640 user manual's "Path contours - Cartesian / polar coordinates" as the
// tests read them, independently of the product's klartext_arc:
//   C X Y DR±        about the pole CC from the current point to X Y; DR+ counter-clockwise (seen
//                    from +Z), DR- clockwise; the radius is the start's distance from the pole;
//   CR X Y R± DR±    from the current point to X Y with radius |R|: R+ the arc of at most 180°,
//                    R- the one beyond; its centre on the chord's perpendicular bisector, to the
//                    left of the chord (start -> end) when the arc turns counter-clockwise and is
//                    the short one, or turns clockwise and is the long one;
//   CP IPA± [IZ±] DR± about the pole by the signed angle IPA (several turns possible), Z changing
//                    in proportion (a helix).
// All in the program's X Y plane; the radius stays that of the start.
#include <Eigen/Dense>

#include <cmath>
#include <stdexcept>

namespace ncpost::test {

/// An arc in the X Y plane: centre, the start's polar angle and radius, the signed sweep (> 0
/// counter-clockwise) and the Z change along it.
struct KlartextArc {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius_mm = 0.0;
  double start_rad = 0.0;
  double sweep_rad = 0.0;
  double dz_mm = 0.0;

  /// The point at fraction t of the arc (X Y), Z from `z0_mm`.
  Eigen::Vector3d at(double t, double z0_mm) const {
    const double a = start_rad + t * sweep_rad;
    return {centre.x() + radius_mm * std::cos(a), centre.y() + radius_mm * std::sin(a), z0_mm + t * dz_mm};
  }
};

/// The sweep from angle a0 to a1 in the direction asked, in (0, 2 pi] (a full circle when they meet).
inline double directed_sweep_rad(double a0, double a1, bool ccw) {
  double s = std::remainder(a1 - a0, 2 * M_PI);  // (-pi, pi]
  if (ccw && s <= 1e-12) s += 2 * M_PI;
  if (!ccw && s >= -1e-12) s -= 2 * M_PI;
  return s;
}

/// C X Y DR±: about the pole.
inline KlartextArc arc_about_pole(const Eigen::Vector2d& from, const Eigen::Vector2d& pole, const Eigen::Vector2d& to,
                                  bool ccw) {
  KlartextArc a;
  a.centre = pole;
  a.radius_mm = (from - pole).norm();
  a.start_rad = std::atan2(from.y() - pole.y(), from.x() - pole.x());
  a.sweep_rad = directed_sweep_rad(a.start_rad, std::atan2(to.y() - pole.y(), to.x() - pole.x()), ccw);
  return a;
}

/// CR X Y R± DR±: by its radius.
inline KlartextArc arc_by_radius(const Eigen::Vector2d& from, const Eigen::Vector2d& to, double r_signed_mm, bool ccw) {
  const double r = std::abs(r_signed_mm);
  const Eigen::Vector2d chord = to - from;
  const double half = chord.norm() / 2;
  if (half > r + 1e-9) throw std::runtime_error("the test interpreter: CR with a radius shorter than half the chord");
  const Eigen::Vector2d left(-chord.y() / chord.norm(), chord.x() / chord.norm());
  const double h = std::sqrt(std::max(0.0, r * r - half * half));
  const bool centre_left = ccw == (r_signed_mm > 0);
  KlartextArc a;
  a.centre = from + chord / 2 + (centre_left ? h : -h) * left;
  a.radius_mm = r;
  a.start_rad = std::atan2(from.y() - a.centre.y(), from.x() - a.centre.x());
  a.sweep_rad = directed_sweep_rad(a.start_rad, std::atan2(to.y() - a.centre.y(), to.x() - a.centre.x()), ccw);
  return a;
}

/// CP IPA± IZ±: about the pole by the signed angle.
inline KlartextArc arc_polar_step(const Eigen::Vector2d& from, const Eigen::Vector2d& pole, double ipa_deg,
                                  double dz_mm) {
  KlartextArc a;
  a.centre = pole;
  a.radius_mm = (from - pole).norm();
  a.start_rad = std::atan2(from.y() - pole.y(), from.x() - pole.x());
  a.sweep_rad = ipa_deg * M_PI / 180.0;
  a.dz_mm = dz_mm;
  return a;
}

}  // namespace ncpost::test
