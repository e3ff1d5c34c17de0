// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/solve/trr_solver.hpp"

#include <fmt/format.h>

#include "ncpost/kinematics/trr_xy_inverse.hpp"
#include "ncpost/machines/input_error.hpp"

namespace ncpost {

AxisPosition trr_slots(const trr::Command& c) {
  AxisPosition q;
  q.linear_mm = Vec3d(c.table_mm.x(), c.table_mm.y(), c.slider_mm.x());
  q.rotary_rad = Eigen::Vector2d(c.slider_mm.y(), c.slider_mm.z());  // V, W (mm: CommandWords says so)
  return q;
}

trr::Command trr_command(const AxisPosition& q) {
  trr::Command c;
  c.table_mm = Eigen::Vector2d(q[0], q[1]);
  c.slider_mm = Vec3d(q[2], q[3], q[4]);
  return c;
}

TrrSolver::TrrSolver(const trr::Kinematics& commanded, const trr::Kinematics& executing,
                     const Vec3d& workpiece_origin_mm)
    : commanded_(commanded), executing_(executing), origin_(workpiece_origin_mm) {
  const trr::Machine& m = commanded.machine();
  axes_.name = m.name;
  axes_.chain = "trr-xy";
  const char letters[] = "XYUVW";
  for (int i = 0; i < 5; ++i) {
    Axis a;
    a.letter = letters[i];
    a.kind = AxisKind::linear;
    a.limits = i < 2 ? m.table_limits[i] : m.slider_limits[i - 2];
    axes_.axes.push_back(a);
  }
}

CommandWords TrrSolver::words() const {
  CommandWords w;
  w.count = 5;
  w.letters = {'X', 'Y', 'U', 'V', 'W'};
  w.angle = {false, false, false, false, false};
  w.rotary_count = 0;
  w.angles_are_programmed = false;
  w.cutter_comp_supported = false;
  w.tilted_plane_capable = false;
  w.branches_chosen = false;
  w.limits_name_the_axis = false;
  return w;
}

IkOutcome TrrSolver::solve_quiet(const ClPoint& cl, const AxisPosition& /*previous*/, SolverData& /*data*/,
                                 SolveFigures* /*figures*/) const {
  return inverse(cl);
}

IkOutcome TrrSolver::inverse(const ClPoint& cl) const {
  ClPoint unit = cl;
  unit.axis.normalize();
  const trr::InverseOutcome ik = trr::inverse(commanded_, unit, origin_);
  IkOutcome out;
  if (!ik.ok()) {
    out.failure.message = ik.failure;
    if (origin_.isZero())
      out.failure.message += "; the workpiece origin is at the TCP's home: set --workpiece-origin below it";
    return out;
  }
  out.position = trr_slots(*ik.command);
  return out;
}

AxisPosition TrrSolver::with_rotary(const ClPoint& cl, const RotaryAngles& /*rotary_rad*/, SolverData& /*data*/) const {
  const IkOutcome o = inverse(cl);
  return o.position.value_or(AxisPosition::zero(2));  // V W
}

ToolPoseT<double> TrrSolver::deviation(const AxisPosition& q, const SolverData& /*data*/) const {
  if (&commanded_ == &executing_) return {Vec3d::Zero(), Vec3d::Zero()};
  const trr::Command c = trr_command(q);
  std::string why;
  const std::optional<trr::ToolPose> nominal = commanded_.tool(c.slider_mm, std::nullopt, &why);
  if (!nominal)
    throw Infeasible(
        fmt::format("the TRR-XY head cannot be solved at U{:.4f} V{:.4f} W{:.4f}: {}", q[2], q[3], q[4], why));
  const ToolPoseT<double> actual = execute(q);
  return {actual.tip_mm - trr::Kinematics::tip_in_workpiece(*nominal, c, origin_), actual.axis - nominal->axis};
}

std::optional<ToolPoseT<double>> TrrSolver::pose(const AxisPosition& q, std::string* why) const {
  const trr::Command c = trr_command(q);
  const std::optional<trr::ToolPose> tool = executing_.tool(c.slider_mm, std::nullopt, why);
  if (!tool) return std::nullopt;
  return ToolPoseT<double>{trr::Kinematics::tip_in_workpiece(*tool, c, origin_), tool->axis};
}

ToolPoseT<double> TrrSolver::execute(const AxisPosition& q) const {
  std::string why;
  const std::optional<ToolPoseT<double>> p = pose(q, &why);
  if (!p)
    throw Infeasible(
        fmt::format("the TRR-XY head cannot be solved at U{:.4f} V{:.4f} W{:.4f}: {}", q[2], q[3], q[4], why));
  return *p;
}

}  // namespace ncpost
