// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/solve/tolerance_subdivider.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "ncpost/kinematics/inverse.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/postproc/solve/play_subdivision.hpp"

namespace ncpost {
namespace {

/// Where the block starts at (or within a few µrad of) a singular pose, its exact solution swings
/// the free angle within the first millionths of the block: the solutions at these parameters
/// are compared with the start's.
constexpr double kSingularProbeT[] = {1e-6, 1e-5, 1e-4, 1e-3};
constexpr double kSingularJumpRad = 1e-3;   ///< a rotary change above this ...
constexpr double kSingularPaceFactor = 10;  ///< ... and this many times the block's own pace is a swing
constexpr double kTurnAxisDriftRad = 1e-3;  ///< the turn may tilt the tool axis this little (near-singular)
constexpr int kMaxTurnBlocks = 4096;
/// A start whose tool axis is this far (rad) from every singular pose cannot swing: the free angle
/// moves about (axis change) / sin(distance), under 20 times the axis's own change here, while the
/// probes look for a change of >= 1 mrad within the first 1e-6 of the block (axis change <= 3.2 µrad).
constexpr double kSwingClearRad = 0.05;

/// `words` with `value` as printed by "{}" replaced by its 4 significant digits (the compensation
/// library prints the inner tolerance in full).
std::string rounded_in(std::string words, double value) {
  const std::string full = fmt::format("{}", value), shortened = fmt::format("{:.4g}", value);
  for (std::size_t at = 0; (at = words.find(full, at)) != std::string::npos; at += shortened.size())
    words.replace(at, full.size(), shortened);
  return words;
}

/// The free-angle change from `from` to `to` when `pole_axis` (the start's or the end's CL axis)
/// is exactly the singular pose (the tool axis along the inner rotary axis, where that angle is
/// free): the CL axis leaves or reaches the pole on a great circle (slerp) whose azimuth is the other
/// end's all along, so the free axis turns in place there, however small the tilt. nullopt: not
/// exactly singular, or no turn needed.
std::optional<RotaryAngles> swing_at_pole(const Machine& machine, const Vec3d& pole_axis, const SolvedPoint& from,
                                          const SolvedPoint& to) {
  if (!may_have_free_rotary(machine, pole_axis)) return std::nullopt;  // (far from any pole: most blocks)
  for (const RotarySolution& r : rotary_solutions(machine, pole_axis)) {
    if (r.free_axis < 0) continue;
    RotaryAngles d = RotaryAngles::Zero(2);
    d[r.free_axis] = to.q.rotary_rad[r.free_axis] - from.q.rotary_rad[r.free_axis];
    if (std::abs(d[r.free_axis]) <= kSingularJumpRad) return std::nullopt;
    return d;
  }
  return std::nullopt;
}

/// The swing of a block that starts exactly at the singular pose (the free angle kept from before):
/// turned to the end solution's angle before the block.
std::optional<RotaryAngles> exactly_singular_swing(const Machine& machine, const SolvedPoint& from,
                                                   const SolvedPoint& to) {
  return swing_at_pole(machine, from.cl.axis, from, to);
}

/// The swing of a block that starts within a few µrad of the singular pose: the exact solutions
/// just after the start swing the free angle within the first millionths of the block; the
/// farthest probe that still swings far faster than the block's pace gives it (only the swinging
/// axis turns). nullopt: no such swing.
std::optional<RotaryAngles> near_singular_swing(const Machine& machine, const KinematicModel& solver, SolverData& data,
                                                const SolvedPoint& from, const SolvedPoint& to) {
  if (!may_have_free_rotary(machine, from.cl.axis, kSwingClearRad)) return std::nullopt;  // (most blocks)
  const ClPoint probe = nonlinear::cl_at(from.cl, to.cl, kSingularProbeT[0]);
  // cheap screen on the nominal closed form (no linear axes): does any rotary solution just after
  // the start lie near the start's angles?
  for (const RotarySolution& r : rotary_solutions(machine, probe.axis)) {
    double jump = 0.0;
    for (int k = 0; k < 2; ++k) {
      const double d = r.rotary_rad[k] - from.q.rotary_rad[k];
      jump = std::max(jump, std::abs(d - 2.0 * kPi * std::round(d / (2.0 * kPi))));
    }
    if (r.free_axis < 0 && jump <= 0.5 * kSingularJumpRad) return std::nullopt;
  }
  const double pace_rad = max_abs_step(to.q.rotary_rad, from.q.rotary_rad);
  std::optional<RotaryAngles> swing;
  for (double t : kSingularProbeT) {
    const IkOutcome o = solver.solve_quiet(nonlinear::cl_at(from.cl, to.cl, t), from.q, data, nullptr);
    if (!o.ok()) break;
    const RotaryAngles d = o.position->rotary_rad - from.q.rotary_rad;
    if (d.cwiseAbs().maxCoeff() <= std::max(kSingularJumpRad, kSingularPaceFactor * t * pace_rad)) break;
    swing = d;
  }
  if (!swing) return std::nullopt;
  // only the swinging (free) axis turns; the other keeps its angle, so the tool axis stays put
  const int free = std::abs((*swing)[1]) > std::abs((*swing)[0]) ? 1 : 0;
  (*swing)[1 - free] = 0.0;
  return swing;
}

/// The blocks that turn the rotary axes by `swing` from `from` with the tool tip standing still
/// on the start point and the tool axis unchanged (it lies along the turning axis), each turn
/// block within `tolerance_mm` of that point on the machine of `errors`. Empty when the turn
/// cannot be done in place (it would tilt the tool axis).
template <class Errors>
std::vector<SolvedPoint> turn_in_place(const Machine& machine, const Setup& setup, const KinematicModel& solver,
                                       SolverData& data, const SolvedPoint& from, const RotaryAngles& swing,
                                       const Errors& errors, double tolerance_mm) {
  auto node = [&](double s) {
    return SolvedPoint{from.cl, solver.with_rotary(from.cl, from.q.rotary_rad + s * swing, data)};
  };
  auto tilt_ok = [&](const SolvedPoint& p) {
    return nonlinear::angle_between(solver.execute(p.q, data).axis, from.cl.axis) <= kTurnAxisDriftRad;
  };
  // the linear axes follow the tip round the turning axis on a circle of radius r: start from the
  // chord count for r, then double until every turn block is within
  const double swing_rad = swing.cwiseAbs().maxCoeff();
  const double ds = std::min(1.0, 0.01 / swing_rad);
  const double radius_mm = (node(ds).q.linear_mm - from.q.linear_mm).norm() / (ds * swing_rad);
  const double step = 2.0 * std::acos(std::max(-1.0, 1.0 - tolerance_mm / std::max(radius_mm, tolerance_mm)));
  for (int n = std::max(1, static_cast<int>(std::ceil(swing_rad / step))); n <= kMaxTurnBlocks; n *= 2) {
    std::vector<SolvedPoint> turn;
    SolvedPoint a{from.cl, from.q};
    bool within = true;
    for (int k = 1; k <= n && within; ++k) {
      const SolvedPoint b = node(static_cast<double>(k) / n);
      if (!tilt_ok(b)) return {};
      const nonlinear::NonlinearError e = nonlinear::nonlinear_error(
          machine, setup, nonlinear::ClBlock{from.cl, from.cl, a.q, b.q}, errors, nonlinear::fast_error_options());
      within = e.max_error_mm <= tolerance_mm;
      turn.push_back(b);
      a = b;
    }
    if (within) return turn;
  }
  return {};
}

/// The blocks that turn the free rotary angle at the block's start, where the tool axis lies
/// (exactly, or within a few µrad) along the inner rotary axis — so the angle is undetermined and
/// the post kept the previous one — to the angle the block's solution leaves with, in place
/// (turn_in_place). Empty when the start is not singular or the swing cannot be done in place.
template <class Errors>
std::vector<SolvedPoint> turn_at_singular_start(const Machine& machine, const Setup& setup,
                                                const KinematicModel& solver, SolverData& data, const SolvedPoint& from,
                                                const SolvedPoint& to, const Errors& errors, double tolerance_mm) {
  if (machine.rotary_count() != 2 || nonlinear::angle_between(from.cl.axis, to.cl.axis) < 1e-9) return {};
  std::optional<RotaryAngles> swing = exactly_singular_swing(machine, from, to);
  if (!swing) swing = near_singular_swing(machine, solver, data, from, to);
  if (!swing) return {};
  return turn_in_place(machine, setup, solver, data, from, *swing, errors, tolerance_mm);
}

/// The swing at an end exactly at the singular pose whose programmed free angle is not the one the
/// block arrives with (the start's: the great circle to the pole keeps its azimuth); turned after it.
std::optional<RotaryAngles> singular_end_swing(const Machine& machine, const SolvedPoint& from, const SolvedPoint& to) {
  if (machine.rotary_count() != 2 || nonlinear::angle_between(from.cl.axis, to.cl.axis) < 1e-9) return std::nullopt;
  return swing_at_pole(machine, to.cl.axis, from, to);
}

/// The commands the block arrives with at a singular end (the free angle of the start's).
AxisPosition arrival_at_singular_end(const Machine& machine, const KinematicModel& solver, SolverData& data,
                                     const SolvedPoint& from, const SolvedPoint& to) {
  RotaryAngles rotary = to.q.rotary_rad;
  if (const auto d = singular_end_swing(machine, from, to)) rotary -= *d;
  return solver.with_rotary(to.cl, rotary, data);
}

/// The turn in place at a singular end from the arrival angle to the programmed one (empty: none).
template <class Errors>
std::vector<SolvedPoint> turn_at_singular_end(const Machine& machine, const Setup& setup, const KinematicModel& solver,
                                              SolverData& data, const SolvedPoint& from, const SolvedPoint& to,
                                              const Errors& errors, double tolerance_mm) {
  const std::optional<RotaryAngles> swing = singular_end_swing(machine, from, to);
  if (!swing) return {};
  const SolvedPoint arrival{to.cl, arrival_at_singular_end(machine, solver, data, from, to)};
  return turn_in_place(machine, setup, solver, data, arrival, *swing, errors, tolerance_mm);
}

}  // namespace

double rotary_reach_mm(const Machine& machine, const Setup& setup, const ClPoint& a, const ClPoint& b) {
  double reach = 0.0;
  for (const auto& axis : machine.axes) {
    if (!axis.is_rotary()) continue;
    for (const ClPoint* p : {&a, &b})
      reach = std::max(reach, (setup.workpiece_origin_mm + p->tip_mm - axis.pivot_mm).norm() + setup.tool_length_mm);
  }
  return reach;
}

namespace {

/// The subdivider on `machine`; `actual` is `solver` when it is the actual machine of a model.
Subdivider subdivider_of(const Machine& machine, const Setup& setup, const KinematicModel& solver,
                         const ActualSolver* actual, const nonlinear::CompensationOptions& options,
                         const Dialect& dialect) {
  // with reversal the adaptive subdivision follows the play, take-ups included (play_subdivision.hpp)
  const bool with_play = actual && actual->model().has_reversal() && options.method == nonlinear::Method::adaptive;
  auto cut_block = [&machine, setup, &solver, actual, options, linear = dialect.linear_decimals,
                    angle = dialect.angle_decimals](const SolvedPoint& from, const SolvedPoint& to, SolverData& data) {
    nonlinear::CompensationOptions c = options;
    c.rounding_allowance_mm =
        std::min(0.5 * c.tolerance_mm,
                 nonlinear::rounding_allowance_mm(linear, angle, rotary_reach_mm(machine, setup, from.cl, to.cl)));
    const double inner_tolerance_mm = c.tolerance_mm - c.rounding_allowance_mm;
    // inserted points are not CL points of the input: the solver's figures are left as they are
    auto ik = [&solver, &data](const ClPoint& cl, const AxisPosition& previous) {
      return solver.solve_quiet(cl, previous, data, nullptr);
    };
    if (actual && actual->model().has_reversal() && c.method == nonlinear::Method::adaptive) {
      std::string failure;
      const WordSteps steps{std::pow(10.0, -linear), deg_to_rad(std::pow(10.0, -angle))};
      std::vector<SolvedPoint> points = subdivide_with_play(machine, setup, *actual, data, from, to, c, steps, failure);
      if (!failure.empty()) throw Infeasible(failure);
      return points;
    }
    auto cut = [&](const auto& errors) {
      std::vector<SolvedPoint> points =
          turn_at_singular_start(machine, setup, solver, data, from, to, errors, inner_tolerance_mm);
      const SolvedPoint start = points.empty() ? from : SolvedPoint{from.cl, points.back().q};
      // a block that ends exactly at the singular pose with another free angle than it arrives
      // with (G-code input programs it): arrive with the approach's angle, then turn in place
      const std::vector<SolvedPoint> end_turn =
          turn_at_singular_end(machine, setup, solver, data, start, to, errors, inner_tolerance_mm);
      const SolvedPoint end =
          end_turn.empty() ? to : SolvedPoint{to.cl, arrival_at_singular_end(machine, solver, data, start, to)};
      const nonlinear::ClBlock block{start.cl,
                                     end.cl,
                                     start.q,
                                     end.q,
                                     points.empty() ? from.executed : std::nullopt,
                                     end_turn.empty() ? to.executed : std::nullopt};
      const nonlinear::SplitBlock split = nonlinear::compensate_block(machine, setup, block, errors, ik, c);
      if (!split.ok())
        throw Infeasible(fmt::format("the move cannot be cut within the tolerance {:.4g} mm: {}", c.tolerance_mm,
                                     rounded_in(split.failure, inner_tolerance_mm)));
      points.reserve(points.size() + split.nodes.size() + end_turn.size());
      for (const auto& node : split.nodes) points.push_back({node.cl, node.q});
      for (const SolvedPoint& p : end_turn) points.push_back(p);
      return points;
    };
    return actual ? cut(actual->errors_from(data.stands)) : cut(NominalErrors{});
  };
  return Subdivider(cut_block, with_play);
}

}  // namespace

Subdivider make_tolerance_subdivider(const NominalSolver& solver, const nonlinear::CompensationOptions& options,
                                     const Dialect& dialect) {
  return subdivider_of(solver.machine(), solver.setup(), solver, nullptr, options, dialect);
}

Subdivider make_tolerance_subdivider(const ActualSolver& solver, const nonlinear::CompensationOptions& options,
                                     const Dialect& dialect) {
  return subdivider_of(solver.machine(), solver.setup(), solver, &solver, options, dialect);
}

}  // namespace ncpost
