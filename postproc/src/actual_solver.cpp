#include "ncpost/postproc/actual_solver.hpp"

namespace ncpost {

AxisPosition ActualSolver::compensate(const ClPoint& cl, const AxisPosition& nominal, std::string& failure) const {
  const comp::RowState<double> state = comp::reversal_state(model_, nominal, actual_);
  uncompensated_.add((model_.tool_pose(nominal, setup_, state).tip_mm - cl.tip_mm).norm());
  comp::ActualIkOptions options;
  if (model_.has_reversal()) options.previous_actual = actual_;
  const comp::ActualIkOutcome r = comp::solve_actual(model_, cl, setup_, nominal, options);
  if (!r.ok()) {
    failure = "compensated inverse kinematics: " + r.message;
    return nominal;
  }
  max_residual_mm_ = std::max(max_residual_mm_, r.tip_error_mm);
  return *r.position;
}

IkOutcome ActualSolver::solve(const ClPoint& cl, const AxisPosition& previous) const {
  IkOutcome o = nominal_.solve(cl, previous);
  if (!o.ok()) return o;
  std::string failure;
  const AxisPosition q = compensate(cl, *o.position, failure);
  if (!failure.empty()) {
    o.position.reset();
    o.failure.message = failure;
    return o;
  }
  o.position = q;
  return o;
}

AxisPosition ActualSolver::with_rotary(const ClPoint& cl, const Eigen::Vector2d& rotary_rad) const {
  // programmed angles (G-code input) are the start; the model then moves them as little as it must
  const AxisPosition nominal = nominal_.with_rotary(cl, rotary_rad);
  std::string failure;
  const AxisPosition q = compensate(cl, nominal, failure);
  return failure.empty() ? q : nominal;
}

ToolPoseT<double> ActualSolver::execute(const AxisPosition& q) const {
  return model_.tool_pose(q, setup_, comp::reversal_state(model_, q, actual_));
}

void ActualSolver::advance(const AxisPosition& command) const {
  if (!model_.has_reversal()) return;
  const comp::RowState<double> state = comp::reversal_state(model_, command, actual_);
  AxisPosition now = command;
  const int n = static_cast<int>(model_.machine().axes.size());
  for (int a = 0; a < n; ++a) now[a] += state.reversal[static_cast<std::size_t>(a)];
  actual_ = now;
}

Vec3d ActualSolver::programmed_tip(const ClPoint&, const AxisPosition& q) const {
  // an RTCP control applies the nominal kinematics: program the nominal tip of the compensated
  // commands, so that the control's own inverse gives those commands back
  return nominal_.execute(q).tip_mm;
}

}  // namespace ncpost
