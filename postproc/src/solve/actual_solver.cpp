// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/solve/actual_solver.hpp"

namespace ncpost {

namespace {

bool same(const AxisPosition& a, const AxisPosition& b) { return a == b; }

}  // namespace

ToolPoseT<double> ActualSolver::error_at(const AxisPosition& q, SolverData& data) const {
  const SolverData::LastError& kept = data.last_error;
  if (kept.owner == this && same(kept.q, q)) return kept.error;
  const ToolPoseT<double> actual = model_.tool_pose(q, setup_, {}, &home_);
  keep_error(q, actual, data);
  return kept.error;
}

void ActualSolver::keep_error(const AxisPosition& q, const ToolPoseT<double>& actual, SolverData& data) const {
  const ToolPoseT<double> nominal = nominal_.execute(q);
  data.last_error = {this, q, {actual.tip_mm - nominal.tip_mm, actual.axis - nominal.axis}};
}

AxisPosition ActualSolver::compensate(const ClPoint& cl, const AxisPosition& guess,
                                      const std::optional<ClPoint>& guess_solves, SolverData& data,
                                      SolveFigures* figures, std::string& failure,
                                      std::optional<ToolPoseT<double>>* executed,
                                      const std::optional<AxisPosition>& previous,
                                      const std::optional<AxisPosition>& stands) const {
  comp::ActualIkOptions options;
  options.guess_solves = guess_solves;
  options.tip_tolerance_mm = kPostTipToleranceMm;
  options.axis_tolerance_rad = kPostAxisToleranceRad;
  if (model_.has_reversal()) {
    options.previous_actual = stands;
    options.previous_command = previous;
  }
  options.home = &home_;
  const comp::ActualIkOutcome r = comp::solve_actual(model_, cl, setup_, guess, options);
  if (!r.ok()) {
    failure = "compensated inverse kinematics: " + r.message;
    return guess;
  }
  if (figures) figures->residual_mm = r.tip_error_mm;
  if (r.actual_pose && !model_.has_reversal()) {
    keep_error(*r.position, *r.actual_pose, data);
    if (executed) *executed = r.actual_pose;  // without reversal: the pose of every later execution
  }
  return *r.position;
}

IkOutcome ActualSolver::solve_quiet(const ClPoint& cl, const AxisPosition& previous, SolverData& data,
                                    SolveFigures* figures) const {
  return solve_standing(cl, previous, data, figures, data.stands);
}

IkOutcome ActualSolver::solve_standing(const ClPoint& cl, const AxisPosition& previous, SolverData& data,
                                       SolveFigures* figures, const std::optional<AxisPosition>& stands) const {
  // The start: the nominal solution of the CL point less the machine's error at the previous
  // commands (its error changes little from one point to the next), on the post's choice of
  // solution; the compensated IK then usually converges at once. With reversal the error depends
  // on the direction of the move: start from the nominal solution of the CL point itself.
  ClPoint start = cl;
  if (!model_.has_reversal()) {
    const ToolPoseT<double> e = error_at(previous, data);
    start.tip_mm = cl.tip_mm - e.tip_mm;
    start.axis = (cl.axis.normalized() - e.axis).normalized();
  }
  IkOutcome o = nominal_.solve(start, previous);
  if (!o.ok() && !model_.has_reversal()) {
    start = cl;  // the shifted point out of reach (at a limit): the CL point itself
    o = nominal_.solve(start, previous);
  }
  if (!o.ok()) return o;
  if (figures && measure_uncompensated_) {
    // the tip error of the uncompensated program: the nominal commands of the CL point, executed
    const bool from_cl = start.tip_mm == cl.tip_mm && start.axis == cl.axis;
    const IkOutcome plain = from_cl ? o : nominal_.solve(cl, previous);
    if (plain.ok())
      figures->uncompensated_tip_mm =
          (model_.tool_pose(*plain.position, setup_, comp::reversal_state(model_, *plain.position, stands), &home_)
               .tip_mm -
           cl.tip_mm)
              .norm();
  }
  std::string failure;
  std::optional<ToolPoseT<double>> executed;
  const AxisPosition q = compensate(cl, *o.position, start, data, figures, failure, &executed, previous, stands);
  if (!failure.empty()) {
    o.position.reset();
    o.failure.message = failure;
    return o;
  }
  o.position = q;
  o.executed = executed;
  return o;
}

AxisPosition ActualSolver::with_rotary(const ClPoint& cl, const RotaryAngles& rotary_rad, SolverData& data) const {
  // programmed angles (G-code input) are the start; the model then moves them as little as it must
  const AxisPosition nominal = nominal_.with_rotary(cl, rotary_rad);
  std::string failure;
  SolveFigures figures;
  if (measure_uncompensated_)
    figures.uncompensated_tip_mm =
        (model_.tool_pose(nominal, setup_, comp::reversal_state(model_, nominal, data.stands), &home_).tip_mm -
         cl.tip_mm)
            .norm();
  const AxisPosition q =
      compensate(cl, nominal, std::nullopt, data, &figures, failure, nullptr, std::nullopt, data.stands);
  data.record(figures);
  return failure.empty() ? q : nominal;
}

std::vector<AxisPosition> ActualSolver::branches(const ClPoint& cl, const AxisPosition& previous,
                                                 SolverData& data) const {
  std::vector<AxisPosition> out;
  const std::optional<AxisPosition> previous_command =
      model_.has_reversal() ? std::optional<AxisPosition>(previous) : std::nullopt;
  for (const AxisPosition& nominal : admissible_solutions(model_.machine(), cl, setup_, previous)) {
    std::string failure;
    const AxisPosition q = compensate(cl, nominal, cl, data, nullptr, failure, nullptr, previous_command, data.stands);
    if (failure.empty()) out.push_back(q);
  }
  return out;
}

ToolPoseT<double> ActualSolver::deviation(const AxisPosition& q, const SolverData& data) const {
  const ToolPoseT<double> actual = execute(q, data);
  const ToolPoseT<double> nominal = nominal_.execute(q);
  return {actual.tip_mm - nominal.tip_mm, actual.axis - nominal.axis};
}

ToolPoseT<double> ActualSolver::execute(const AxisPosition& q, const SolverData& data) const {
  return model_.tool_pose(q, setup_, comp::reversal_state(model_, q, data.stands));
}

void ActualSolver::advance(const AxisPosition& command, SolverData& data) const {
  if (model_.has_reversal()) data.stands = comp::actual_after(model_, command, data.stands);
}

std::optional<AxisPosition> ActualSolver::take_up(const AxisPosition& from, const AxisPosition& to,
                                                  const SolverData& data) const {
  const std::optional<AxisPosition>& actual = data.stands;
  if (!model_.has_reversal() || !actual) return std::nullopt;
  AxisPosition q = from;
  bool any = false;
  const int n = static_cast<int>(model_.machine().axes.size());
  for (int a = 0; a < n; ++a) {
    const int p = model_.layout().reversal_of(a);
    const double move = to[a] - from[a];
    if (p < 0 || std::abs(move) < 1e-9) continue;
    const double band = model_.values()[static_cast<std::size_t>(p)];
    const double lo = std::min(0.0, band), hi = std::max(0.0, band);
    // the edge of the band the new direction runs on: rising actual = command + lo, falling + hi
    const double edge = (*actual)[a] - (move > 0.0 ? lo : hi);
    if (std::abs(edge - from[a]) > 1e-9) {
      q[a] = edge;
      any = true;
    }
  }
  if (!any) return std::nullopt;
  return q;
}

bool ActualSolver::reaches(const ClPoint& cl, const AxisPosition& q, const std::optional<AxisPosition>& stands) const {
  const ToolPoseT<double> pose = model_.tool_pose(q, setup_, comp::reversal_state(model_, q, stands), &home_);
  const Vec3d u = cl.axis.normalized();
  const double axis_rad = std::atan2(pose.axis.cross(u).norm(), pose.axis.dot(u));
  return (pose.tip_mm - cl.tip_mm).norm() <= kPostTipToleranceMm &&
         (model_.machine().rotary_count() == 0 || axis_rad <= kPostAxisToleranceRad);
}

Vec3d ActualSolver::programmed_tip(const ClPoint&, const AxisPosition& q) const {
  // an RTCP control applies the nominal kinematics: program the nominal tip of the compensated
  // commands, so that the control's own inverse gives those commands back
  return nominal_.execute(q).tip_mm;
}

}  // namespace ncpost
