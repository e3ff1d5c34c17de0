// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/export_machine.hpp"
#include "ncpost/kinematics/units.hpp"

#include "ncpost/compensation/export_axis_table.hpp"

#include <fmt/format.h>

#include <set>
#include <stdexcept>

namespace ncpost::comp {

namespace {

std::string vector_text(const Vec3d& v) {
  auto number = [](double x) { return x == 0.0 ? std::string("0") : fmt::format("{:.17g}", x); };
  return fmt::format("[{}, {}, {}]", number(v.x()), number(v.y()), number(v.z()));
}

/// Limits: 15 significant digits, so that -120° read in radians and written back is -120 again.
std::string machine_file_number(double x) { return x == 0.0 ? std::string("0") : fmt::format("{:.15g}", x); }

}  // namespace

MachineExport corrected_machine(const MachineModel& model) {
  const Machine& m = model.machine();
  const ModelLayout& layout = model.layout();
  MachineExport out;
  ErrorParameters location;
  std::set<std::string> left_seen;
  for (std::size_t i = 0; i < layout.size(); ++i) {
    const ParameterSpec& s = layout.spec(static_cast<int>(i));
    if (s.measurement_only()) continue;
    if (s.kind == ParameterKind::location) {
      location.set(s.name, model.values()[i]);
      out.applied.push_back(s.name);
      continue;
    }
    const std::string effect = s.kind == ParameterKind::table ? s.name.substr(0, 3) + ":t" : effect_of(s.name);
    if (!left_seen.insert(effect).second) continue;
    switch (s.kind) {
      case ParameterKind::squareness:
        out.left_out.push_back(effect + " (squareness: a machine file has no direction for a linear axis)");
        break;
      case ParameterKind::reversal:
        out.left_out.push_back(effect +
                               " (reversal: not a geometry; the control's backlash compensation or --format linuxcnc)");
        break;
      default:
        out.left_out.push_back(
            effect + " (component error function: changes with the position, a machine file holds constants)");
        break;
    }
  }
  if (location.empty())
    throw ExportRefusal(
        ExportRefusal::Source::model,
        "the model has no location error of a rotary axis (EX0C, EY0C, EA0C, EB0C, ...): there is nothing to "
        "write into the machine file");
  const MachineModel located(m, location);
  const ErrorFunctor<double> errors = located.errors();
  out.corrected = m;
  out.corrected.name = m.name + "-calibrated";
  for (const std::vector<int>* side : {&m.workpiece_side, &m.tool_side}) {
    Rigidd bed_T_previous;  // the transforms at home of the axes between the bed and the current one
    for (int j : *side) {
      const Axis& axis = m.axes[static_cast<std::size_t>(j)];
      if (axis.is_rotary()) {
        const AxisErrorTerms<double> terms = errors(j, 0.0, true);
        const RotaryLine<double> line = rotary_line<double>(axis, j, terms, 0.0, NominalErrors{});
        Axis& corrected = out.corrected.axes[static_cast<std::size_t>(j)];
        corrected.pivot_mm = bed_T_previous.R * line.point_mm + bed_T_previous.t;
        corrected.direction = (bed_T_previous.R * line.direction).normalized();
      }
      bed_T_previous = bed_T_previous * axis_transform<double>(axis, j, 0.0, 0.0, errors, true);
    }
  }
  return out;
}

std::string format_machine_toml(const Machine& machine, const std::vector<std::string>& notes) {
  std::string out;
  for (const std::string& n : notes) out += "# " + n + "\n";
  out += fmt::format("[machine]\nname = \"{}\"\nchain = \"{}\"\n", machine.name, machine.chain);
  for (const Axis& a : machine.axes) {
    out += "\n";
    for (const std::string& line : machine_axis_lines(a)) out += line + "\n";
  }
  return out;
}

std::vector<std::string> machine_axis_lines(const Axis& a) {
  std::vector<std::string> lines{fmt::format("[axes.{}]", a.letter),
                                 fmt::format("type = \"{}\"", a.is_rotary() ? "rotary" : "linear")};
  if (a.is_rotary()) {
    lines.push_back(fmt::format("direction = {}", vector_text(a.direction)));
    lines.push_back(fmt::format("pivot = {}", vector_text(a.pivot_mm)));
  }
  if (a.limits) {
    const double unit = a.is_rotary() ? kDegPerRad : 1.0;
    lines.push_back(fmt::format("limits = [{}, {}]", machine_file_number(a.limits->min * unit),
                                machine_file_number(a.limits->max * unit)));
  }
  return lines;
}

}  // namespace ncpost::comp
