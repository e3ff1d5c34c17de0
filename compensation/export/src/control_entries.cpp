// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/control_entries.hpp"

#include <fmt/format.h>

#include "ncpost/compensation/export_isg.hpp"
#include "ncpost/compensation/export_linuxcnc.hpp"
#include "ncpost/compensation/export_machine.hpp"
#include "ncpost/compensation/export_siemens.hpp"

namespace ncpost::comp {

const std::vector<ControlFormatInfo>& control_formats() {
  static const std::vector<ControlFormatInfo> formats{
      {ControlFormat::machine, "machine", "kinematics corrections (the machine file's rotary axis lines)",
       "the pivot points and axis directions a control's kinematic calibration writes (Heidenhain KinematicsOpt, "
       "Siemens CYCLE996): enter them in the control's kinematics description, or post with the corrected machine "
       "file and no --model; values are the actual axis lines, in mm and unit vectors"},
      {ControlFormat::linuxcnc, "linuxcnc", "LinuxCNC COMP_FILE rows (COMP_FILE_TYPE = 1)",
       "one file per joint, [JOINT_n]COMP_FILE with COMP_FILE_TYPE = 1: nominal position, forward trim, reverse trim "
       "(mm or degrees); the trim is added to the commanded position, so it is minus the axis's error"},
      {ControlFormat::siemens, "siemens", "SINUMERIK LEC table ($AA_ENC_COMP)",
       "the program %_N_AX_EEC_INI, MD32700 ENC_COMP_ENABLE = 1: the value at each point is the axis's error (mm or "
       "degrees); a positive value moves the axis in the negative direction"},
      {ControlFormat::isg, "isg", "ISG kernel / Beckhoff TwinCAT CNC leadscrew error compensation (kw.ssfk)",
       "the axis compensation list (achskw*.lis), lr_param.ssfk 1: pos / neg values in 0.1 µm (0.0001°) are the "
       "measured minus the programmed position per direction of motion; set kopf.achs_nr to the control's logical "
       "axis number"},
  };
  return formats;
}

const ControlFormatInfo& control_format_info(ControlFormat format) {
  for (const ControlFormatInfo& f : control_formats())
    if (f.format == format) return f;
  return control_formats().front();
}

std::optional<ControlFormat> parse_control_format(const std::string& name) {
  for (const ControlFormatInfo& f : control_formats())
    if (name == f.name) return f.format;
  return std::nullopt;
}

ControlFormat default_control_format(const Machine& machine) {
  for (const Axis& a : machine.axes)
    if (a.is_rotary()) return ControlFormat::machine;
  return ControlFormat::linuxcnc;
}

std::string control_format_names() {
  std::string names;
  for (const ControlFormatInfo& f : control_formats()) names += (names.empty() ? "" : ", ") + std::string(f.name);
  return names;
}

namespace {

struct AxisEntry {
  std::vector<std::string> lines;     ///< the value lines of the axis's table
  std::vector<std::string> left_out;  ///< the terms acting on the axis the table cannot hold
};

/// One axis's table in `format` (a one-axis table format); ExportRefusal when there is none.
AxisEntry axis_entry(const MachineModel& model, ControlFormat format, char letter) {
  switch (format) {
    case ControlFormat::linuxcnc: {
      const LinuxcncCompTable t = linuxcnc_comp_table(model, letter);
      return {linuxcnc_comp_lines(t), t.axis.left_out};
    }
    case ControlFormat::siemens: {
      const SiemensLecTable t = siemens_lec_table(model, letter);
      return {siemens_lec_lines(t), t.axis.left_out};
    }
    case ControlFormat::isg: {
      const IsgLsecTable t = isg_lsec_table(model, letter);
      return {isg_lsec_lines(t), t.axis.left_out};
    }
    case ControlFormat::machine:
      break;
  }
  return {};
}

}  // namespace

ControlEntries control_entries(const MachineModel& model, ControlFormat format) {
  ControlEntries out;
  out.format = format;
  const std::string name = control_format_info(format).name;
  if (format == ControlFormat::machine) {
    try {
      const MachineExport corrected = corrected_machine(model);
      ControlEntryFile file{"machine file", "--format machine --machine M.toml", {}};
      for (const Axis& a : corrected.corrected.axes)
        if (a.is_rotary())
          for (const std::string& line : machine_axis_lines(a)) file.lines.push_back(line);
      out.files.push_back(file);
      for (const std::string& s : corrected.left_out) out.not_held.push_back("the machine file: " + s);
    } catch (const ExportRefusal& e) {
      out.not_held.push_back(std::string("the machine file: ") + e.what());
    }
    return out;
  }
  try {  // location errors: the machine file's, never a one-axis table's
    const MachineExport located = corrected_machine(model);
    out.not_held.push_back(
        fmt::format("location errors {}: a one-axis table cannot move an axis line (--control "
                    "machine, or export --format machine)",
                    fmt::join(located.applied, ", ")));
  } catch (const ExportRefusal&) {
  }
  for (const Axis& a : model.machine().axes) {
    try {
      AxisEntry entry = axis_entry(model, format, a.letter);
      out.files.push_back({fmt::format("axis {}", a.letter), fmt::format("--format {} --axis {}", name, a.letter),
                           std::move(entry.lines)});
      for (const std::string& s : entry.left_out)  // location errors: listed once, above
        if (s.find("(location error of") == std::string::npos)
          out.not_held.push_back(fmt::format("axis {}: {}", a.letter, s));
    } catch (const ExportRefusal& e) {
      out.not_held.push_back(fmt::format("axis {}: {}", a.letter, e.what()));
    }
  }
  return out;
}

}  // namespace ncpost::comp
