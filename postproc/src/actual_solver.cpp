#include "ncpost/postproc/actual_solver.hpp"

namespace ncpost {

AxisPosition ActualSolver::compensate(const ClPoint& cl, const AxisPosition& nominal, bool nominal_solves_cl,
                                      SolveFigures* figures, std::string& failure) const {
  comp::ActualIkOptions options;
  options.guess_solves_cl = nominal_solves_cl;
  options.tip_tolerance_mm = kPostTipToleranceMm;
  options.axis_tolerance_rad = kPostAxisToleranceRad;
  if (model_.has_reversal()) options.previous_actual = actual_;
  options.home = &home_;
  const comp::ActualIkOutcome r = comp::solve_actual(model_, cl, setup_, nominal, options);
  if (figures) figures->uncompensated_tip_mm = r.start_tip_error_mm;
  if (!r.ok()) {
    failure = "compensated inverse kinematics: " + r.message;
    return nominal;
  }
  if (figures) figures->residual_mm = r.tip_error_mm;
  return *r.position;
}

void ActualSolver::record(const SolveFigures& figures) const {
  if (figures.uncompensated_tip_mm >= 0.0) uncompensated_.add(figures.uncompensated_tip_mm);
  if (figures.residual_mm >= 0.0) max_residual_mm_ = std::max(max_residual_mm_, figures.residual_mm);
}

IkOutcome ActualSolver::solve_quiet(const ClPoint& cl, const AxisPosition& previous, SolveFigures* figures) const {
  IkOutcome o = nominal_.solve(cl, previous);
  if (!o.ok()) return o;
  std::string failure;
  const AxisPosition q = compensate(cl, *o.position, true, figures, failure);
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
  SolveFigures figures;
  const AxisPosition q = compensate(cl, nominal, false, &figures, failure);
  record(figures);
  return failure.empty() ? q : nominal;
}

ToolPoseT<double> ActualSolver::execute(const AxisPosition& q) const {
  return model_.tool_pose(q, setup_, comp::reversal_state(model_, q, actual_));
}

void ActualSolver::advance(const AxisPosition& command) const {
  if (model_.has_reversal()) actual_ = comp::actual_after(model_, command, actual_);
}

std::optional<AxisPosition> ActualSolver::take_up(const AxisPosition& from, const AxisPosition& to) const {
  if (!model_.has_reversal() || !actual_) return std::nullopt;
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
    const double edge = (*actual_)[a] - (move > 0.0 ? lo : hi);
    if (std::abs(edge - from[a]) > 1e-9) {
      q[a] = edge;
      any = true;
    }
  }
  if (!any) return std::nullopt;
  return q;
}

Vec3d ActualSolver::programmed_tip(const ClPoint&, const AxisPosition& q) const {
  // an RTCP control applies the nominal kinematics: program the nominal tip of the compensated
  // commands, so that the control's own inverse gives those commands back
  return nominal_.execute(q).tip_mm;
}

}  // namespace ncpost
