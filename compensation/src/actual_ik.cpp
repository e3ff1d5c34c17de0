#include "ncpost/compensation/actual_ik.hpp"

#include <fmt/format.h>

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <unsupported/Eigen/AutoDiff>

#include "ncpost/compensation/reversal.hpp"
#include "ncpost/kinematics/inverse.hpp"

namespace ncpost::comp {
namespace {

using Jet = Eigen::AutoDiffScalar<Eigen::Matrix<double, 5, 1>>;

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
      for (int a = 0; a < 5; ++a) out.actual[a] += state.reversal[static_cast<std::size_t>(a)];
      out.actual_pose = actual;
      return out;
    }
    // after a step q solves the previous target nominally, so the nominal pose is that target;
    // evaluated all the same (the IK is exact to ~1e-12 mm), except at a guess known to solve a point
    const ToolPoseT<double> nominal =
        out.iterations == 0 && o.guess_solves
            ? ToolPoseT<double>{o.guess_solves->tip_mm, o.guess_solves->axis.normalized()}
            : forward(m, q, setup);
    ClPoint target;
    target.tip_mm = cl.tip_mm - (actual.tip_mm - nominal.tip_mm);
    target.axis = (u - (actual.axis - nominal.axis)).normalized();
    const IkOutcome ik = solve(m, target, setup, q);
    if (!ik.ok()) return std::nullopt;
    if ((ik.position->rotary_rad - nominal_guess.rotary_rad).cwiseAbs().maxCoeff() > kMaxRotaryStepRad) return std::nullopt;
    q = *ik.position;
  }
  return std::nullopt;
}

}  // namespace

namespace {

/// Newton–Gauss on the commands; `state_of(q)` gives the reversal offsets at command q.
template <class StateOf>
ActualIkOutcome newton(const MachineModel& model, const ClPoint& cl, const Setup& setup,
                       const AxisPosition& guess, const ActualIkOptions& o, const StateOf& state_of) {
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
    for (int i = 0; i < 5; ++i) {
      const double v = i < n ? q[i] : 0.0;
      qj[i] = i < n ? Jet(v, 5, i) : Jet(v, Eigen::Matrix<double, 5, 1>::Zero());
    }
    const ErrorFunctor<double> f(model.layout(), model.values().data(), state, true);
    const ToolPoseT<Jet> pose = ncpost::tool_pose<Jet>(m, qj, setup, f);
    Eigen::Matrix<double, 5, 1> r;
    Eigen::Matrix<double, 5, 5> J;
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
    // a three-axis machine solves the tip only
    const Eigen::MatrixXd A = n == 5 ? Eigen::MatrixXd(J) : Eigen::MatrixXd(J.topLeftCorner(3, n));
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeThinU | Eigen::ComputeThinV);
    svd.setThreshold(1e-9);
    const Eigen::VectorXd rr = n == 5 ? Eigen::VectorXd(r) : Eigen::VectorXd(r.head(3));
    const Eigen::VectorXd step = -svd.solve(rr);
    for (int i = 0; i < n; ++i) q[i] += step[i];
  }
  out.message = fmt::format("no convergence on the actual machine after {} iterations (tip {:.3g} mm, axis {:.3g} rad)",
                            o.max_iterations, out.tip_error_mm, out.axis_error_rad);
  return out;
}

/// The Newton routes of solve_actual (the fixed point did not converge).
ActualIkOutcome solve_by_newton(const MachineModel& model, const ClPoint& cl, const Setup& setup,
                                const AxisPosition& nominal_guess, const ActualIkOptions& o) {
  const int n = 3 + model.machine().rotary_count();
  if (n == 3 && o.previous_actual && model.has_reversal()) {
    // Three-axis machine with reversal: the dead band makes the actual position a non-smooth
    // function of the command (it stands still inside the band), which Newton cannot follow.
    // Solve for where the axes must actually go (no offsets), then fix each offset by the
    // direction from where the axis stands (rising: min(0, b), falling: max(0, b)) and solve
    // the commands with those offsets held.
    const ActualIkOutcome free = newton(model, cl, setup, nominal_guess, o, [](const AxisPosition&) { return RowState<double>{}; });
    if (!free.ok()) return free;
    RowState<double> fixed;
    AxisPosition guess = *free.position;
    for (int a = 0; a < 3; ++a) {
      const int p = model.layout().reversal_of(a);
      if (p < 0) continue;
      const double b = model.values()[static_cast<std::size_t>(p)];
      const bool rising = (*free.position)[a] >= (*o.previous_actual)[a];
      fixed.reversal[static_cast<std::size_t>(a)] = rising ? std::min(0.0, b) : std::max(0.0, b);
      guess[a] -= fixed.reversal[static_cast<std::size_t>(a)];
    }
    return newton(model, cl, setup, guess, o, [&](const AxisPosition&) { return fixed; });
  }
  return newton(model, cl, setup, nominal_guess, o,
                [&](const AxisPosition& q) { return reversal_state(model, q, o.previous_actual); });
}

}  // namespace

ActualIkOutcome solve_actual(const MachineModel& model, const ClPoint& cl, const Setup& setup,
                             const AxisPosition& nominal_guess, const ActualIkOptions& o) {
  if (auto fast = fixed_point(model, cl, setup, nominal_guess, o)) return *fast;
  return solve_by_newton(model, cl, setup, nominal_guess, o);
}

}  // namespace ncpost::comp
