// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/solve/inverse_time.hpp"

namespace ncpost {

double inverse_time_minutes(double tip_path_mm, bool tip_moves, double rotary_travel_deg, double feed_mm_min) {
  if (!(feed_mm_min > 0.0)) return 0.0;
  return (tip_moves ? tip_path_mm : rotary_travel_deg) / feed_mm_min;
}

double feed_for_minutes(double tip_path_mm, bool tip_moves, double rotary_travel_deg, double minutes) {
  if (!(minutes > 0.0)) return 0.0;
  return (tip_moves ? tip_path_mm : rotary_travel_deg) / minutes;
}

namespace {

double refined(const std::function<Vec3d(double)>& tip_at, double t0, const Vec3d& p0, double t1, const Vec3d& p1,
               int depth) {
  const double tm = 0.5 * (t0 + t1);
  const Vec3d pm = tip_at(tm);
  const double chord = (p1 - p0).norm();
  const double halves = (pm - p0).norm() + (p1 - pm).norm();
  // (two levels at least: a path that bows both ways can pass through the chord's midpoint). The polyline's
  // shortfall falls as the square of the step, so halves + (halves - chord) / 3 is the length to the fourth
  // order (Richardson): on a circle of radius 100 mm a piece whose halves add 1e-7 mm to its chord spans 0.4 deg,
  // and the extrapolated length is within 1e-12 mm of the arc (where the plain polyline needed pieces of 0.04 deg,
  // ten times as many tip evaluations, for 1e-9 mm)
  if (depth >= 12 || (depth >= 2 && halves - chord < 1e-7)) return halves + (halves - chord) / 3.0;
  return refined(tip_at, t0, p0, tm, pm, depth + 1) + refined(tip_at, tm, pm, t1, p1, depth + 1);
}

}  // namespace

double tip_path_length_mm(const std::function<Vec3d(double t)>& tip_at) {
  return tip_path_length_mm(tip_at, tip_at(0.0), tip_at(1.0));
}

double tip_path_length_mm(const std::function<Vec3d(double t)>& tip_at, const Vec3d& start_mm, const Vec3d& end_mm) {
  return refined(tip_at, 0.0, start_mm, 1.0, end_mm, 1);
}

}  // namespace ncpost
