// SPDX-License-Identifier: Apache-2.0
#pragma once
// Test helper of the axis-table exports (LinuxCNC, ISG): where an axis actually is, along itself,
// at a drive command, by the model's chain, for applying an exported table as the control does.
#include "ncpost/compensation/machine_model.hpp"
#include "ncpost/kinematics/forward.hpp"

namespace ncpost::test {

/// Where axis `axis` actually is (mm, or rad for a rotary axis) at command `q`, moving down
/// (`falling`, the reversal of the model taken) or up.
inline double actual_position(const comp::MachineModel& model, int axis, double q, bool falling) {
  const Machine& m = model.machine();
  comp::RowState<double> state;
  if (const int r = model.layout().reversal_of(axis); r >= 0 && falling) state.reversal[axis] = model.values()[r];
  AxisPosition command = home_of(m);
  command[axis] = q;
  const Axis& a = m.axes[axis];
  if (!a.is_rotary()) return model.tool_pose(command, Setup{}, state).tip_mm.dot(a.direction);
  // rotary: how far a point on a radius turns about the axis, as an angle
  const ChainPose<double> pose = chain_pose<double>(m, command, 0.0, model.errors(state));
  const Rigidd& body = a.side == Side::workpiece ? pose.bed_T_table : pose.bed_T_tool;
  const Vec3d radial = a.direction.unitOrthogonal();
  const Vec3d turned = body.R * radial;
  return std::atan2(a.direction.dot(radial.cross(turned)), radial.dot(turned));
}

}  // namespace ncpost::test
