// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/kinematics_left_out.hpp"
#include "ncpost/kinematics/units.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "ncpost/compensation/export_axis_table.hpp"

namespace ncpost::comp {

namespace {

constexpr double kUnlimitedLinearMm = 100.0;     ///< quarter points of an axis without limits
constexpr double kUnlimitedTiltRad = kPi / 2.0;  ///< limits of a tilting axis without limits

/// The positions one axis takes among the representative poses (mm or rad).
std::vector<double> axis_positions(const Axis& axis, bool outer_rotary) {
  if (!axis.is_rotary()) {
    if (!axis.limits) return {-kUnlimitedLinearMm, kUnlimitedLinearMm};
    const double quarter = 0.25 * (axis.limits->max - axis.limits->min);
    return {axis.limits->min + quarter, axis.limits->max - quarter};
  }
  if (outer_rotary) return {0.0, kPi / 2.0, kPi, 1.5 * kPi};
  if (!axis.limits) return {-kUnlimitedTiltRad, 0.0, kUnlimitedTiltRad};
  std::vector<double> at{axis.limits->min, axis.limits->max};
  if (axis.limits->contains(0.0)) at.insert(at.begin() + 1, 0.0);
  return at;
}

/// The index of the rotary axis nearer the bed (its side's chain order), or -1.
int inner_rotary(const Machine& m) {
  for (const std::vector<int>* side : {&m.workpiece_side, &m.tool_side})
    for (int j : *side)
      if (m.axes[static_cast<std::size_t>(j)].is_rotary()) return j;
  return -1;
}

std::string short_number(double x) { return fmt::format("{:g}", std::abs(x) < 1e-9 ? 0.0 : x); }

/// The family a term is listed under (export_machine.cpp groups the same way).
std::string group_of(const ParameterSpec& s) {
  if (s.kind == ParameterKind::location) return s.name;
  if (s.kind == ParameterKind::table) return s.name.substr(0, 3) + ":t";
  return effect_of(s.name);
}

}  // namespace

std::vector<AxisPosition> representative_poses(const Machine& machine) {
  const int inner = inner_rotary(machine);
  std::vector<AxisPosition> poses{AxisPosition::zero(machine.rotary_count())};
  for (std::size_t i = 0; i < machine.axes.size(); ++i) {
    const Axis& a = machine.axes[i];
    std::vector<AxisPosition> grown;
    for (const AxisPosition& q : poses)
      for (double v : axis_positions(a, a.is_rotary() && static_cast<int>(i) != inner)) {
        AxisPosition p = q;
        p[static_cast<int>(i)] = v;
        grown.push_back(p);
      }
    poses = std::move(grown);
  }
  return poses;
}

std::string representative_poses_text(const Machine& machine) {
  const int inner = inner_rotary(machine);
  std::vector<std::string> parts;
  for (std::size_t i = 0; i < machine.axes.size(); ++i) {
    const Axis& a = machine.axes[i];
    const double unit = a.is_rotary() ? kDegPerRad : 1.0;
    std::vector<std::string> values;
    for (double v : axis_positions(a, a.is_rotary() && static_cast<int>(i) != inner))
      values.push_back(short_number(v * unit));
    parts.push_back(fmt::format("{} {} {}", a.letter, fmt::join(values, "/"), a.is_rotary() ? "deg" : "mm"));
  }
  return fmt::format("{}", fmt::join(parts, ", "));
}

ErrorParameters parameters_where(const MachineModel& model, const std::function<bool(const ParameterSpec&)>& keep) {
  ErrorParameters out;
  const ModelLayout& layout = model.layout();
  for (std::size_t i = 0; i < layout.size(); ++i) {
    const ParameterSpec& s = layout.spec(static_cast<int>(i));
    if (!s.measurement_only() && keep(s)) out.set(s.name, model.values()[i]);
  }
  return out;
}

double largest_tip_difference_um(const MachineModel& a, const MachineModel& b, const std::vector<AxisPosition>& poses) {
  const Setup setup{Vec3d::Zero(), 0.0};
  double largest_mm = 0.0;
  for (const AxisPosition& q : poses)
    largest_mm = std::max(largest_mm, (a.tool_pose(q, setup).tip_mm - b.tool_pose(q, setup).tip_mm).norm());
  return largest_mm * 1e3;
}

LeftOut left_out_of(const MachineModel& model, const std::function<bool(const ParameterSpec&)>& held,
                    const std::function<std::string(const ParameterSpec&)>& why) {
  const Machine& m = model.machine();
  LeftOut out;
  const std::vector<AxisPosition> poses = representative_poses(m);
  out.poses = static_cast<int>(poses.size());
  out.poses_text = representative_poses_text(m);
  const ModelLayout& layout = model.layout();
  std::map<std::string, std::string> seen;  // group -> why, in the order first met (kept in `order`)
  std::vector<std::string> order;
  for (std::size_t i = 0; i < layout.size(); ++i) {
    const ParameterSpec& s = layout.spec(static_cast<int>(i));
    if (s.measurement_only() || held(s)) continue;
    if (seen.emplace(group_of(s), why(s)).second) order.push_back(group_of(s));
  }
  if (order.empty()) return out;
  for (const std::string& group : order) {
    const MachineModel without(m,
                               parameters_where(model, [&](const ParameterSpec& s) { return group_of(s) != group; }));
    out.terms.push_back({group, seen[group], largest_tip_difference_um(model, without, poses)});
  }
  const MachineModel held_only(m, parameters_where(model, held));
  out.together_um = largest_tip_difference_um(model, held_only, poses);
  return out;
}

std::vector<std::string> left_out_lines(const LeftOut& left) {
  if (left.terms.empty()) return {"Left out: nothing"};
  std::vector<std::string> lines{
      fmt::format("Left out (NOT in this record, {} term(s)); each with the largest change of the tool tip on the",
                  left.terms.size()),
      fmt::format("workpiece (um) when it alone is removed from the model, at {} poses of the travel:", left.poses),
      fmt::format("  {}", left.poses_text), "  (tool length 0: the tip at the spindle gauge point; W = M at home)"};
  for (const LeftOutTerm& t : left.terms)
    lines.push_back(fmt::format("  {:<10} {:10.3f} um  {}", t.term, t.effect_um, t.why));
  lines.push_back(
      fmt::format("  all together: {:.3f} um (this record against the whole model at those poses)", left.together_um));
  return lines;
}

TableTableAxes table_table_axes(const Machine& machine, const std::string& format) {
  std::vector<int> rotary;
  for (int j : machine.workpiece_side)
    if (machine.axes[static_cast<std::size_t>(j)].is_rotary()) rotary.push_back(j);
  bool head_rotary = false;
  for (int j : machine.tool_side) head_rotary = head_rotary || machine.axes[static_cast<std::size_t>(j)].is_rotary();
  if (rotary.size() != 2 || head_rotary)
    throw ExportRefusal(ExportRefusal::Source::machine,
                        fmt::format("{} is written for a table-table machine (two rotary axes carrying the workpiece, "
                                    "none in the head); '{}' has the chain '{}'",
                                    format, machine.name, machine.chain));
  return {rotary[0], rotary[1]};
}

}  // namespace ncpost::comp
