// SPDX-License-Identifier: Apache-2.0
#pragma once
// A cheap upper bound of a block's nonlinear error, to skip the exact maximisation
// (nonlinear_error.hpp) for blocks far within the tolerance (dense paths: nearly all of them).
//
// The executed tip x(t) (W) is a fixed point carried through the chain
//   table_T_tool(t) = T_ws[n−1]^-1 ⋯ T_ws[0]^-1 · T_ts[0] ⋯ T_ts[m−1]
// whose factors move at constant rates in t (q linear in t). From the innermost factor outward,
// with s and a the bounds on the speed and acceleration (d/dt, mm) of the point entering a factor:
//   linear axis, travel Δ:            s += |Δ|
//   rotary axis, travel ω (rad), ρ = distance of the point from the axis line at t = 0:
//                                     a = ω²(ρ + s) + 2|ω|s + a ;  s = |ω|(ρ + s) + s
// (|R''(p − c)| = ω²·dist, |R'p'| <= |ω||p'|). The chord deviation is then |x(t) − chord(t)| <=
// t(1 − t)/2 · max|x''| <= a/8, and the distance from the CL segment is at most that plus the
// larger end-point mismatch |x(0) − p0|, |x(1) − p1|. The tool axis is turned by the rotations
// only: |a_axis''| <= (Σ|ω|)², giving the orientation bound likewise.
// An actual machine whose errors are all constants (location errors, squareness: `rigid_chain`) is
// a rigid chain of the same kind with its axis lines moved: the same bound holds on its own lines,
// starting from the TCP carried through its set-up at home. Where the errors change along the
// block (component error functions, tables, reversal) — straightness and angular errors over a
// long linear move bow the tip by µm even on a three-axis machine — the bound is taken on the
// nominal lines and the deviation of the actual from the nominal executed tip away from its own
// chord, sampled at t = ¼, ½, ¾ (the error functions are smooth: polynomials of degree <= 3,
// harmonics, tables), is added with a factor 1.5; it is bounded through the actual executed tip's
// own chord deviation plus the nominal bound. Units: mm, rad; W.
#include <algorithm>
#include <cmath>
#include <type_traits>

#include "ncpost/compensation/nonlinear_block.hpp"

namespace ncpost::nonlinear {

struct NonlinearBound {
  double error_mm = 0.0;         ///< >= the exact largest distance from the CL segment
  double orientation_rad = 0.0;  ///< >= the exact largest orientation error
};

/// True when the error hook describes a rigid chain (every term a constant of the machine).
template <class Errors>
bool rigid_chain(const Errors& errors) {
  if constexpr (std::is_same_v<Errors, NominalErrors>)
    return true;
  else if constexpr (requires { errors.constant_in_command(); })
    return errors.constant_in_command();
  else
    return false;
}

template <class Errors>
NonlinearBound nonlinear_bound(const ExecutedBlock<Errors>& executed, const Machine& machine, const Setup& setup) {
  const ClBlock& b = executed.block();
  // A rigid actual chain (location errors, squareness) is bounded on its own axis lines, exactly
  // like the nominal one; other error hooks on the nominal lines plus the sampled model bow below.
  const bool rigid = rigid_chain(executed.errors());
  double speed = 0.0, accel = 0.0, omega_sum = 0.0;
  // the TCP, in the frame of the innermost tool-side body (= M at home), through the set-up at home
  Vec3d point = rigid ? executed.home_tool_inverse().t : Vec3d::Zero();
  auto apply = [&](int index, bool inverse) {
    const Axis& axis = machine.axes[static_cast<std::size_t>(index)];
    const double travel = b.to[index] - b.from[index];
    const double q = b.from[index];
    Rigidd at_start = rigid ? axis_transform<double>(axis, index, q, setup.tool_length_mm, executed.errors(), false)
                            : axis_transform<double>(axis, index, q, setup.tool_length_mm, NominalErrors{}, false);
    if (inverse) at_start = at_start.inverse();
    if (axis.is_rotary()) {
      const RotaryLine<double> line =
          rigid ? rotary_line<double>(axis, index, executed.errors()(index, q, false), setup.tool_length_mm,
                                      executed.errors())
                : rotary_line<double>(axis, index, AxisErrorTerms<double>{}, setup.tool_length_mm, NominalErrors{});
      const Vec3d r = point - line.point_mm;
      const double rho = (r - r.dot(line.direction) * line.direction).norm() + speed;
      const double w = std::abs(travel);
      accel = w * w * rho + 2.0 * w * speed + accel;
      speed = w * rho + speed;
      omega_sum += w;
    } else {
      const Vec3d direction =
          rigid ? Vec3d(axis.direction + executed.errors()(index, q, false).direction_offset) : axis.direction;
      speed += std::abs(travel) * direction.norm();
    }
    point = at_start.apply(point);
  };
  for (auto it = machine.tool_side.rbegin(); it != machine.tool_side.rend(); ++it) apply(*it, false);
  for (int index : machine.workpiece_side) apply(index, true);

  const ToolPoseT<double> x0 = b.from_pose ? *b.from_pose : executed.pose_at(b.from);
  const ToolPoseT<double> x1 = b.to_pose ? *b.to_pose : executed.pose_at(b.to);
  const double mismatch = std::max((x0.tip_mm - b.start.tip_mm).norm(), (x1.tip_mm - b.end.tip_mm).norm());
  NonlinearBound out;
  out.error_mm = accel / 8.0 + mismatch;
  if (!rigid) {
    // x(t) = n(t) + d(t): the nominal execution n, bounded above, plus the model's offset d. The
    // chord deviation of d is at most that of x plus that of n (<= accel/8), so sampling x alone
    // (no nominal evaluations) bounds it: 1.5·(max sampled chord deviation of x + accel/8).
    double bow_mm = 0.0;
    for (double t : {0.25, 0.5, 0.75}) {
      const Vec3d x = executed.pose_at(lerp(b.from, b.to, t)).tip_mm;
      bow_mm = std::max(bow_mm, (x - ((1.0 - t) * x0.tip_mm + t * x1.tip_mm)).norm());
    }
    out.error_mm += 1.5 * (bow_mm + accel / 8.0);
  }
  const double chord = std::max(std::cos(0.5 * angle_between(x0.axis, x1.axis)), 1e-3);
  const double axis_mismatch = std::max(angle_between(x0.axis, b.start.axis), angle_between(x1.axis, b.end.axis));
  out.orientation_rad = std::asin(std::min(1.0, omega_sum * omega_sum / 8.0 / chord)) + 2.0 * axis_mismatch;
  return out;
}

}  // namespace ncpost::nonlinear
