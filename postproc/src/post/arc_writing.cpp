// SPDX-License-Identifier: Apache-2.0
// CL circles in the post (poster.hpp): one native G2/G3 block where the program's frame sees the
// arc in a principal plane, else points on the arc within PostOptions::arc_tolerance_mm.
#include <cmath>

#include "ncpost/compensation/nonlinear_block.hpp"
#include "post/poster.hpp"

namespace ncpost::detail {

void Poster::move_along_arc(const cl::Circle& c, const cl::Motion& end, bool rapid) {
  const Vec3d start = previous_.cl.tip_mm;
  const Vec3d stop = end.point.tip_mm;
  const Vec3d n = c.axis;
  const Vec3d r0 = (start - c.center_mm) - (start - c.center_mm).dot(n) * n;
  const Vec3d r1 = (stop - c.center_mm) - (stop - c.center_mm).dot(n) * n;
  auto sweep = angle_about(n, r0, r1, 1e-9);
  if (!sweep || r0.norm() < 1e-9) {
    move_to(end.point, end.where.line, rapid);
    return;
  }
  double angle = *sweep;
  if (angle <= 1e-12) angle += 2.0 * kPi;  // counter-clockwise about the circle axis
  angle += 2.0 * kPi * c.extra_turns;      // a helix of several turns (one pitch over all of them)
  if (c.extra_turns == 0 && native_arc(c, end, rapid, angle)) return;
  const double radius = r0.norm();
  const double tol = std::min(options_.arc_tolerance_mm, 0.5 * radius);
  const double step = 2.0 * std::acos(1.0 - tol / radius);
  const int n_steps = std::max(1, static_cast<int>(std::ceil(angle / step)));
  const double along0 = (start - c.center_mm).dot(n), along1 = (stop - c.center_mm).dot(n);
  const Vec3d axis0 = previous_.cl.axis;
  for (int i = 1; i <= n_steps; ++i) {
    const double t = static_cast<double>(i) / n_steps;
    ClPoint p;
    p.tip_mm = i == n_steps
                   ? stop
                   : c.center_mm + rotation_about<double>(n, t * angle) * r0 + (along0 + t * (along1 - along0)) * n;
    p.axis = nonlinear::slerp(axis0, end.point.axis, t);  // a great circle also between opposite axes
    move_to(p, end.where.line, rapid);
  }
}

/// The arc from the current point to `end` about `c` (sweep `angle` counter-clockwise about the
/// circle axis) as one G2/G3 block, when the program's frame sees it in a principal plane; a
/// helix (the end higher or lower along the axis) carries the third coordinate in the same block.
bool Poster::native_arc(const cl::Circle& c, const cl::Motion& end, bool rapid, double angle) {
  if (!options_.native_arcs || rapid || !writer_.dialect().arcs || !have_position_) return false;
  const Vec3d n = c.axis.normalized();
  const Vec3d start = previous_.cl.tip_mm, stop = end.point.tip_mm;
  if (previous_.cl.axis.cross(n).norm() > 1e-9 || end.point.axis.cross(n).norm() > 1e-9) return false;
  const IkOutcome ik = solver_.solve(end.point, previous_.q, data_);
  if (!ik.ok() || max_abs_step(ik.position->rotary_rad, previous_.q.rotary_rad) > 1e-12) return false;
  const Vec3d centre = c.center_mm + (start - c.center_mm).dot(n) * n;  // in the plane of the arc
  // the arc in the program's frame: W under RTCP, else the linear axes for the fixed rotary angles
  auto frame = [&](const Vec3d& p) -> Vec3d {
    if (plane_) return plane_->words.to_plane(p + home_offset_);
    if (options_.rtcp) return p;
    return solver_.with_rotary(ClPoint{p, n}, previous_.q.rotary_rad, data_).linear_mm;
  };
  const Vec3d xs = frame(start), xe = frame(stop), xc = frame(centre);
  const Vec3d normal = frame(centre + n) - xc;  // the circle axis in the frame (unit: a rigid map)
  int plane_axis = -1;
  for (int k = 0; k < 3; ++k)
    if (std::abs(std::abs(normal[k]) - 1.0) < 1e-9) plane_axis = k;
  if (plane_axis < 0) return false;
  // a helix rises along the circle axis: its radius is measured in the plane of the arc
  const Vec3d to_end = xe - xc;
  const double r_start = (xs - xc).norm(), r_end = (to_end - to_end.dot(normal) * normal).norm();
  // CAM data carry 4 decimals; controls accept a few µm between the start and end radii
  if (r_start < 1e-3 || std::abs(r_start - r_end) > 5e-4 || angle < 1e-6) return false;
  NcArc arc;
  arc.plane = plane_axis == 2 ? 17 : plane_axis == 1 ? 18 : 19;
  arc.clockwise = normal[plane_axis] < 0.0;  // counter-clockwise about the frame's −axis is clockwise about +axis
  for (int k = 0; k < 3; ++k) {
    arc.end_mm[static_cast<std::size_t>(k)] = xe[k];
    arc.centre_offset_mm[static_cast<std::size_t>(k)] = xc[k] - xs[k];
  }
  arc.feed_mm_min = records_.feed_mm_min(options_.default_feed_mm_min);
  write_native_arc(arc, xe, normal, angle, c, end, *ik.position);
  return true;
}

/// Writes the arc block (ending at `xe` in the program's frame, `solved_end` the commands solved
/// for `end`), reads it back under --verify, and moves the post's state to its end.
void Poster::write_native_arc(const NcArc& arc, const Vec3d& xe, const Vec3d& normal, double angle, const cl::Circle& c,
                              const cl::Motion& end, const AxisPosition& solved_end) {
  const WrittenState arc_in_force = read_back_ ? writer_.in_force() : WrittenState{};
  writer_.arc(arc);
  std::optional<ReadBackBlock> written;  // read back (--verify)
  if (read_back_) {
    written = read_written(arc_in_force, previous_.cl, end.point, end.where.line);
    check_arc_words(*written, arc);
    last_rapid_.reset();
    last_was_feed_ = true;
  }
  const std::optional<PerAxis<double>> start_words = last_values_;  // as the control has them
  if (last_values_)
    for (int k = 0; k < 3; ++k) (*last_values_)[static_cast<std::size_t>(k)] = writer_.rounded(k, xe[k]);
  SolvedPoint next{end.point, plane_ ? solver_.with_rotary(end.point, plane_->rotary_rad, data_) : solved_end};
  AxisPosition executed = next.q;
  if (plane_)
    executed = plane_executed(xe);
  else
    for (int i = 0; i < 3; ++i) executed.linear_mm[i] = writer_.rounded(i, next.q.linear_mm[i]);
  if (written && !options_.rtcp) verify_native_arc(*written, arc, start_words, normal, angle, c, end, executed);
  hooks_.advance(executed, data_);
  last_executed_ = executed;
  previous_ = next;
  ++summary_.arcs_out;
}

}  // namespace ncpost::detail
