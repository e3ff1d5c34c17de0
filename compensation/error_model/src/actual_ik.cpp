// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/actual_ik.hpp"

#include <fmt/format.h>

#include <Eigen/SVD>
#include <algorithm>
#include <array>
#include <vector>
#include <cmath>
#include <unsupported/Eigen/AutoDiff>

#include "ncpost/compensation/reversal.hpp"
#include "ncpost/kinematics/inverse.hpp"

namespace ncpost::comp {
namespace {

using Jet = Eigen::AutoDiffScalar<Eigen::Matrix<double, kMaxAxes, 1>>;  // d/d(each command)

/// Two unit vectors completing u to an orthonormal basis.
void perpendicular_pair(const Vec3d& u, Vec3d& b1, Vec3d& b2) {
  const Vec3d helper = std::abs(u.x()) < 0.9 ? Vec3d::UnitX() : Vec3d::UnitY();
  b1 = u.cross(helper).normalized();
  b2 = u.cross(b1).normalized();
}

}  // namespace

RowState<double> reversal_state(const MachineModel& model, const AxisPosition& command,
                                const std::optional<AxisPosition>& previous_actual) {
  RowState<double> s;
  if (!previous_actual) return s;
  const int n = static_cast<int>(model.machine().axes.size());
  for (int a = 0; a < n; ++a) {
    const int p = model.layout().reversal_of(a);
    if (p < 0) continue;
    const double width = model.values()[static_cast<std::size_t>(p)];
    s.reversal[static_cast<std::size_t>(a)] =
        dead_band_actual<double>((*previous_actual)[a], command[a], width) - command[a];
  }
  return s;
}

AxisPosition actual_after(const MachineModel& model, const AxisPosition& command,
                          const std::optional<AxisPosition>& previous_actual) {
  const RowState<double> state = reversal_state(model, command, previous_actual);
  AxisPosition actual = command;
  const int n = static_cast<int>(model.machine().axes.size());
  for (int a = 0; a < n; ++a) actual[a] += state.reversal[static_cast<std::size_t>(a)];
  return actual;
}

namespace {

/// Fast path: fixed-point iteration on the nominal closed-form inverse kinematics. The error of
/// the actual machine at q, e(q) = actual(q) − nominal(q), changes slowly with q (its derivative is
/// of the order of the errors, 1e-4 and less), so solving the nominal machine for the CL point
/// minus e(q_k) converges in two or three steps. Gives up (nullopt) when a step leaves the
/// neighbourhood of the nominal solution (near the singular orientation a tiny axis correction can
/// swing the free angle), when the nominal machine has no solution, or without convergence; the
/// caller then runs the Newton iteration.
std::optional<ActualIkOutcome> fixed_point(const MachineModel& model, const ClPoint& cl, const Setup& setup,
                                           const AxisPosition& nominal_guess, const ActualIkOptions& o) {
  const Machine& m = model.machine();
  if (m.rotary_count() != 2) return std::nullopt;
  const Vec3d u = cl.axis.normalized();
  constexpr double kMaxRotaryStepRad = 0.01;
  ActualIkOutcome out;
  AxisPosition q = nominal_guess;
  for (out.iterations = 0; out.iterations < 8; ++out.iterations) {
    const RowState<double> state = reversal_state(model, q, o.previous_actual);
    const ToolPoseT<double> actual = model.tool_pose(q, setup, state, o.home);
    out.tip_error_mm = (actual.tip_mm - cl.tip_mm).norm();
    out.axis_error_rad = std::atan2(actual.axis.cross(u).norm(), actual.axis.dot(u));
    if (out.tip_error_mm <= o.tip_tolerance_mm && out.axis_error_rad <= o.axis_tolerance_rad) {
      out.position = q;
      out.actual = q;
      for (int a = 0; a < 3 + m.rotary_count(); ++a) out.actual[a] += state.reversal[static_cast<std::size_t>(a)];
      out.actual_pose = actual;
      return out;
    }
    // after a step q solves the previous target nominally, so the nominal pose is that target;
    // evaluated all the same (the IK is exact to ~1e-12 mm), except at a guess known to solve a point
    const ToolPoseT<double> nominal = out.iterations == 0 && o.guess_solves
                                          ? ToolPoseT<double>{o.guess_solves->tip_mm, o.guess_solves->axis.normalized()}
                                          : forward(m, q, setup);
    ClPoint target;
    target.tip_mm = cl.tip_mm - (actual.tip_mm - nominal.tip_mm);
    target.axis = (u - (actual.axis - nominal.axis)).normalized();
    const IkOutcome ik = solve(m, target, setup, q);
    if (!ik.ok()) return std::nullopt;
    if (max_abs_step(ik.position->rotary_rad, nominal_guess.rotary_rad) > kMaxRotaryStepRad) return std::nullopt;
    q = *ik.position;
  }
  return std::nullopt;
}

}  // namespace

namespace {

/// Newton–Gauss on the commands; `state_of(q)` gives the reversal offsets at command q.
template <class StateOf>
ActualIkOutcome newton(const MachineModel& model, const ClPoint& cl, const Setup& setup, const AxisPosition& guess,
                       const ActualIkOptions& o, const StateOf& state_of) {
  const Machine& m = model.machine();
  const int n = 3 + m.rotary_count();
  const Vec3d u = cl.axis.normalized();
  Vec3d b1, b2;
  perpendicular_pair(u, b1, b2);
  ActualIkOutcome out;
  AxisPosition q = guess;
  for (out.iterations = 0; out.iterations <= o.max_iterations; ++out.iterations) {
    const RowState<double> state = state_of(q);
    AxisPositionT<Jet> qj;
    for (int i = 0; i < n; ++i) qj[i] = Jet(q[i], kMaxAxes, i);
    const ErrorFunctor<double> f(model.layout(), model.values().data(), state, true);
    const ToolPoseT<Jet> pose = ncpost::tool_pose<Jet>(m, qj, setup, f);
    Eigen::Matrix<double, 5, 1> r;  // tip (3, mm) and tool axis across u (2)
    Eigen::Matrix<double, 5, kMaxAxes> J;
    for (int k = 0; k < 3; ++k) {
      r[k] = pose.tip_mm[k].value() - cl.tip_mm[k];
      J.row(k) = pose.tip_mm[k].derivatives().transpose();
    }
    const Jet p1 = pose.axis.dot(b1.cast<Jet>()), p2 = pose.axis.dot(b2.cast<Jet>());
    r[3] = p1.value();
    r[4] = p2.value();
    J.row(3) = p1.derivatives().transpose();
    J.row(4) = p2.derivatives().transpose();
    Vec3d axis;
    for (int k = 0; k < 3; ++k) axis[k] = pose.axis[k].value();
    out.tip_error_mm = r.head<3>().norm();
    out.axis_error_rad = std::atan2(axis.cross(u).norm(), axis.dot(u));
    // a three-axis machine cannot turn the tool: its axis error is reported, not solved for
    if (out.tip_error_mm <= o.tip_tolerance_mm && (n < 5 || out.axis_error_rad <= o.axis_tolerance_rad)) {
      out.position = q;
      out.actual = q;
      for (int a = 0; a < n; ++a) out.actual[a] += state.reversal[static_cast<std::size_t>(a)];
      return out;
    }
    // a three-axis machine solves the tip only; with rotary axes the tool axis too (least squares
    // with one rotary axis, which turns the tool about one direction only)
    const int rows = n > 3 ? 5 : 3;
    const Eigen::MatrixXd A = J.topLeftCorner(rows, n);
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeThinU | Eigen::ComputeThinV);
    svd.setThreshold(1e-9);
    const Eigen::VectorXd rr = r.head(rows);
    const Eigen::VectorXd step = -svd.solve(rr);
    for (int i = 0; i < n; ++i) q[i] += step[i];
  }
  out.message = fmt::format("no convergence on the actual machine after {} iterations (tip {:.3g} mm, axis {:.3g} rad)",
                            o.max_iterations, out.tip_error_mm, out.axis_error_rad);
  return out;
}

/// The side of its dead band an axis with reversal takes in a solution.
enum class PlaySide { rising, falling, standing };

/// A row state that holds each axis with reversal on a chosen side of its play, for Newton: a
/// rising axis stands at command + min(0, b), a falling one at command + max(0, b) (smooth in the
/// command), a standing one where it stands (its command moves it not at all: a zero column of the
/// Jacobian, which the truncated SVD leaves alone).
RowState<double> held_on(const PerAxis<PlaySide>& side, const AxisPosition& previous_actual) {
  RowState<double> s;
  PerAxis<double> from{};
  for (int a = 0; a < kMaxAxes; ++a) {
    const double far = 1e9;  // beyond any band: the clamp picks the edge of the side
    switch (side[static_cast<std::size_t>(a)]) {
      case PlaySide::rising:
        from[static_cast<std::size_t>(a)] = -far;
        break;
      case PlaySide::falling:
        from[static_cast<std::size_t>(a)] = far;
        break;
      case PlaySide::standing:
        from[static_cast<std::size_t>(a)] = previous_actual[a];
        break;
    }
  }
  s.previous_actual = from;
  return s;
}

/// The actual pose at q from where the axes stand (the dead band evaluated exactly), its errors
/// against the CL point written into `out`; true when within the tolerances.
bool check_exact(const MachineModel& model, const ClPoint& cl, const Setup& setup, const AxisPosition& q,
                 const ActualIkOptions& o, ActualIkOutcome& out) {
  const int n = 3 + model.machine().rotary_count();
  const RowState<double> state = reversal_state(model, q, o.previous_actual);
  const ToolPoseT<double> pose = model.tool_pose(q, setup, state, o.home);
  const Vec3d u = cl.axis.normalized();
  out.tip_error_mm = (pose.tip_mm - cl.tip_mm).norm();
  out.axis_error_rad = std::atan2(pose.axis.cross(u).norm(), pose.axis.dot(u));
  if (out.tip_error_mm > o.tip_tolerance_mm || (n == 5 && out.axis_error_rad > o.axis_tolerance_rad)) return false;
  out.position = q;
  out.actual = q;
  for (int a = 0; a < n; ++a) out.actual[a] += state.reversal[static_cast<std::size_t>(a)];
  out.actual_pose = pose;
  return true;
}

/// Reversal is a play: the actual position of an axis is a non-smooth function of its command
/// (it stands still while the command crosses the band), which Newton on the exact dead band cannot
/// follow where the axis must move little or turn back. Solve instead for where the axes must
/// actually go (the model without offsets, smooth), which tells each axis with reversal the side
/// of its band the motion implies; then solve the commands with every axis held on its side
/// (smooth again), and check the result on the exact dead band. An axis whose needed move is
/// within the tolerances stands still (its command stays where it was, inside the band): crossing
/// the play for a move below the NC words' resolution would only add take-ups. Where the first
/// choice of sides fails the check (a move so small that the offsets' own effect turns it), every
/// other choice is tried: a solution within the limits is never given up for the kink.
ActualIkOutcome solve_with_play(const MachineModel& model, const ClPoint& cl, const Setup& setup,
                                const AxisPosition& nominal_guess, const ActualIkOptions& o) {
  const int n = 3 + model.machine().rotary_count();
  const AxisPosition& from = *o.previous_actual;
  ActualIkOutcome free =
      newton(model, cl, setup, nominal_guess, o, [](const AxisPosition&) { return RowState<double>{}; });
  if (!free.ok()) return free;
  std::vector<int> play_axes;
  PerAxis<PlaySide> implied{};
  implied.fill(PlaySide::rising);
  for (int a = 0; a < n; ++a) {
    if (model.layout().reversal_of(a) < 0) continue;
    play_axes.push_back(a);
    implied[static_cast<std::size_t>(a)] = (*free.position)[a] >= from[a] ? PlaySide::rising : PlaySide::falling;
  }
  // the command of side s for the actual position x of axis a
  auto command_for = [&](int a, PlaySide s, double x) {
    const double b = model.values()[static_cast<std::size_t>(model.layout().reversal_of(a))];
    const double lo = std::min(0.0, b), hi = std::max(0.0, b);
    if (s == PlaySide::rising) return x - lo;
    if (s == PlaySide::falling) return x - hi;
    // standing: anywhere in [from − hi, from − lo]; where the command was, if known
    const double keep = o.previous_command ? (*o.previous_command)[a] : (*free.position)[a];
    return std::clamp(keep, from[a] - hi, from[a] - lo);
  };
  auto attempt = [&](const PerAxis<PlaySide>& side, ActualIkOutcome& out) {
    AxisPosition guess = *free.position;
    for (int a : play_axes) guess[a] = command_for(a, side[static_cast<std::size_t>(a)], (*free.position)[a]);
    const RowState<double> held = held_on(side, from);
    const ActualIkOutcome r = newton(model, cl, setup, guess, o, [&](const AxisPosition&) { return held; });
    out = r;
    out.position.reset();
    return r.ok() && check_exact(model, cl, setup, *r.position, o, out);
  };
  // first the implied sides with every axis whose move is tiny standing; then the implied sides;
  // then every other choice (3^k, k axes with reversal)
  std::vector<PerAxis<PlaySide>> order;
  PerAxis<PlaySide> still = implied;
  for (int a : play_axes) {
    const double move = std::abs((*free.position)[a] - from[a]);
    const double small = a < 3 ? o.tip_tolerance_mm : o.axis_tolerance_rad;
    if (move <= small) still[static_cast<std::size_t>(a)] = PlaySide::standing;
  }
  order.push_back(still);
  if (still != implied) order.push_back(implied);
  const int k = static_cast<int>(play_axes.size());
  int combos = 1;
  for (int i = 0; i < k; ++i) combos *= 3;
  for (int c = 0; c < combos; ++c) {
    PerAxis<PlaySide> side = implied;
    int code = c;
    for (int a : play_axes) {
      side[static_cast<std::size_t>(a)] = static_cast<PlaySide>(code % 3);
      code /= 3;
    }
    if (std::find(order.begin(), order.end(), side) == order.end()) order.push_back(side);
  }
  ActualIkOutcome best;
  bool have_best = false;
  for (const auto& side : order) {
    ActualIkOutcome out;
    if (attempt(side, out)) return out;
    if (!have_best || out.tip_error_mm < best.tip_error_mm) {
      best = out;
      have_best = true;
    }
  }
  best.message = fmt::format(
      "no command on either side of the reversal play reaches the CL point (closest: tip {:.3g} mm, axis {:.3g} rad)",
      best.tip_error_mm, best.axis_error_rad);
  return best;
}

}  // namespace

ActualIkOutcome solve_actual(const MachineModel& model, const ClPoint& cl, const Setup& setup,
                             const AxisPosition& nominal_guess, const ActualIkOptions& o) {
  // with reversal the fixed point may converge on a needless crossing of the play: Newton on sides
  if (o.previous_actual && model.has_reversal()) return solve_with_play(model, cl, setup, nominal_guess, o);
  if (auto fast = fixed_point(model, cl, setup, nominal_guess, o)) return *fast;
  // no history: reversal offsets 0 (approach from below)
  return newton(model, cl, setup, nominal_guess, o, [](const AxisPosition&) { return RowState<double>{}; });
}

}  // namespace ncpost::comp
