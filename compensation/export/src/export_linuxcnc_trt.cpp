// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/export_linuxcnc_trt.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cmath>

#include "ncpost/compensation/export_axis_table.hpp"

namespace ncpost::comp {

namespace {

/// +1 or -1 when `d` is ±unit(component) exactly, else 0.
int sign_along(const Vec3d& d, int component) {
  if (!(d - Vec3d::Unit(component)).isZero(1e-12) && !(d + Vec3d::Unit(component)).isZero(1e-12)) return 0;
  return d[component] > 0 ? 1 : -1;
}

bool is_offset(const ParameterSpec& s) { return s.kind == ParameterKind::location && s.component < 3; }

std::string why_left_out(const ParameterSpec& s, const Machine& m) {
  if (s.kind == ParameterKind::location) {
    const Axis& a = m.axes[static_cast<std::size_t>(s.axis_index)];
    const int about = s.component - 3;
    if (std::abs(a.direction[about]) > 0.5)
      return fmt::format(
          "zero error of {}: trt kinematics have none; it could go to the joint's HOME_OFFSET "
          "(INI), not written here",
          a.letter);
    return fmt::format("tilt of the {} line: trt kinematics assume it along {}", a.letter,
                       std::abs(a.direction.x()) > 0.5   ? 'X'
                       : std::abs(a.direction.y()) > 0.5 ? 'Y'
                                                         : 'Z');
  }
  if (s.kind == ParameterKind::coupled) return "location changing with another axis: trt kinematics hold constants";
  if (s.kind == ParameterKind::squareness) return "squareness: trt kinematics assume orthogonal linear axes";
  if (s.kind == ParameterKind::reversal) return "reversal: the joint's BACKLASH or a COMP_FILE (--format linuxcnc)";
  return "error motion of an axis: a COMP_FILE of that axis (--format linuxcnc) holds its positioning part";
}

std::string number(double x) { return fmt::format("{:.9f}", std::abs(x) < 5e-10 ? 0.0 : x); }

}  // namespace

TrtKinematics linuxcnc_trt_kinematics(const MachineModel& model) {
  const Machine& m = model.machine();
  const TableTableAxes axes = table_table_axes(m, "--format linuxcnc-trt");
  const Axis& tilt = m.axes[static_cast<std::size_t>(axes.first)];
  const Axis& rotary = m.axes[static_cast<std::size_t>(axes.second)];
  const int tilt_about = tilt.letter == 'A' ? 0 : tilt.letter == 'B' ? 1 : -1;
  const int tilt_sign = tilt_about < 0 ? 0 : sign_along(tilt.direction, tilt_about);
  const int rotary_sign = rotary.letter == 'C' ? sign_along(rotary.direction, 2) : 0;
  if (tilt_sign == 0 || rotary_sign == 0 || tilt_sign != rotary_sign)
    throw ExportRefusal(
        ExportRefusal::Source::machine,
        fmt::format("LinuxCNC's trt kinematics take a tilting table A along X (or B along Y) carrying a rotary table "
                    "C along Z, both turning the table the same way (directions [1,0,0]/[0,1,0] and [0,0,1], or "
                    "all negative); '{}' has {} along [{}] carrying {} along [{}]",
                    m.name, tilt.letter, fmt::join(tilt.direction, ", "), rotary.letter,
                    fmt::join(rotary.direction, ", ")));
  bool any_location = false;
  for (const ParameterSpec& s : model.layout().specs())
    any_location = any_location || s.kind == ParameterKind::location;
  if (!any_location)
    throw ExportRefusal(ExportRefusal::Source::model,
                        "the model has no location error of a rotary axis (EY0A, EX0C, ...): there is nothing to "
                        "write into the kinematics");
  TrtKinematics k;
  k.tilt_letter = tilt.letter;
  k.module = tilt.letter == 'A' ? "xyzac-trt-kins" : "xyzbc-trt-kins";
  k.conventional = tilt_sign < 0;
  const MachineModel held(m, parameters_where(model, is_offset));
  const ErrorFunctor<double> errors = held.errors();
  const auto line_point = [&](int j) {
    const Axis& a = m.axes[static_cast<std::size_t>(j)];
    return rotary_line<double>(a, j, errors(j, 0.0, true), 0.0, NominalErrors{}).point_mm;
  };
  const Vec3d c_point = line_point(axes.second);
  const Vec3d tilt_point = line_point(axes.first);
  k.x_rot_point_mm = c_point.x();
  k.y_rot_point_mm = c_point.y();
  k.z_rot_point_mm = c_point.z();
  if (k.tilt_letter == 'A') {
    k.y_offset_mm = tilt_point.y() - c_point.y();
  } else {
    k.x_offset_mm = tilt_point.x() - c_point.x();
  }
  k.z_offset_mm = tilt_point.z() - c_point.z();
  for (const ParameterSpec& s : model.layout().specs())
    if (is_offset(s)) k.held.push_back(s.name);
  k.left_out = left_out_of(model, is_offset, [&](const ParameterSpec& s) { return why_left_out(s, m); });
  return k;
}

std::string format_linuxcnc_trt(const TrtKinematics& k, const MachineModel& model, const ExportSource& source) {
  const Machine& m = model.machine();
  const std::string& p = k.module;
  std::vector<std::string> notes{
      fmt::format("ncpost {} export --format linuxcnc-trt: the rotary axes' line offsets of model '{}'", source.version,
                  source.model_path),
      fmt::format("(machine '{}', {}) as LinuxCNC {} parameters (src/emc/kinematics/trtfuncs.c).", m.name,
                  source.machine_path.empty() ? std::string("no file") : "'" + source.machine_path + "'", p),
      fmt::format("Use: loadrt {} coordinates=xyz{}c, then these setp lines (a HAL file of the configuration).", p,
                  static_cast<char>(std::tolower(k.tilt_letter))),
      "Convention: lengths in mm in joint coordinates = ncpost's machine frame M (the tool tip with X Y Z at 0 is",
      "its origin); if the control's joint zero differs, add that offset to the three rot-point values.",
      k.tilt_letter == 'A'
          ? "The C line passes through (x-rot-point, y-rot-point) along Z; the A line through (y-rot-point + y-offset,"
            " z-rot-point + z-offset) along X; x-offset is not used by xyzac."
          : "The C line passes through (x-rot-point, y-rot-point) along Z; the B line through (x-rot-point + x-offset,"
            " z-rot-point + z-offset) along Y; y-offset is not used by xyzbc.",
      k.conventional
          ? "conventional-directions = 1: positive commands turn the table right-handed about -X/-Y and -Z (pin of"
            " LinuxCNC 2.10; an older LinuxCNC refuses the setp: it has only the other sense)."
          : "conventional-directions = 0 (the default, not set here): positive commands turn the table right-handed"
            " about +X/+Y and +Z.",
      fmt::format(
          "Zero errors (E{0}0{0}, EC0C) have no pin here: a model's zero error is listed as left out below; the",
          k.tilt_letter),
      "joint's HOME_OFFSET in the INI file could hold it (with the workpiece set up at home, that of the tilting",
      "axis turns the C line, that of C has no effect).",
      "tool-offset is not set here: net it to motion.tooloffset.z (the tool length), as LinuxCNC's trt configurations "
      "do.",
      fmt::format("Held: {}", k.held.empty() ? std::string("none (the nominal pivots)")
                                             : fmt::format("{}", fmt::join(k.held, ", ")))};
  for (const std::string& line : left_out_lines(k.left_out)) notes.push_back(line);
  std::string out;
  for (const std::string& n : notes) out += "# " + n + "\n";
  out += fmt::format("setp {}.x-rot-point {}\n", p, number(k.x_rot_point_mm));
  out += fmt::format("setp {}.y-rot-point {}\n", p, number(k.y_rot_point_mm));
  out += fmt::format("setp {}.z-rot-point {}\n", p, number(k.z_rot_point_mm));
  out += fmt::format("setp {}.x-offset {}\n", p, number(k.x_offset_mm));
  out += fmt::format("setp {}.y-offset {}\n", p, number(k.y_offset_mm));
  out += fmt::format("setp {}.z-offset {}\n", p, number(k.z_offset_mm));
  if (k.conventional) out += fmt::format("setp {}.conventional-directions 1\n", p);
  return out;
}

}  // namespace ncpost::comp
