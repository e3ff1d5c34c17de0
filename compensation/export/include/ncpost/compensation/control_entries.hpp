// SPDX-License-Identifier: Apache-2.0
#pragma once
// The compensation values of a model as they are entered in one control (issue 17, "the
// compensation values as they will be entered in the control"; `identify --control FORMAT`): the
// very lines `ncpost export --format FORMAT` writes, without the notes, per file (one per axis for
// the one-axis tables, the rotary axes' sections for the machine file), and for every axis a format
// cannot hold, why. The formats and their texts are data (control_formats()).
#include <optional>
#include <string>
#include <vector>

#include "ncpost/compensation/machine_model.hpp"

namespace ncpost::comp {

enum class ControlFormat { machine, linuxcnc, siemens, isg };

struct ControlFormatInfo {
  ControlFormat format;
  const char* name;   ///< the --format / --control word
  const char* title;  ///< what the control calls the entries
  const char* where;  ///< where they are entered, and the sign, in one sentence
};

/// Every format, the default (machine) first.
const std::vector<ControlFormatInfo>& control_formats();
const ControlFormatInfo& control_format_info(ControlFormat format);
std::optional<ControlFormat> parse_control_format(const std::string& name);
/// The entries a report shows unless told: the kinematics corrections (machine) when the machine has a
/// rotary axis, else the LinuxCNC rows (a three-axis machine's errors are its axes' tables).
ControlFormat default_control_format(const Machine& machine);
/// "machine, linuxcnc, siemens, isg"
std::string control_format_names();

struct ControlEntryFile {
  std::string heading;             ///< e.g. "axis X" or "machine file"
  std::string export_arguments;    ///< the `ncpost export` arguments that write the whole file
  std::vector<std::string> lines;  ///< exactly as in the exported file
};

struct ControlEntries {
  ControlFormat format = ControlFormat::machine;
  std::vector<ControlEntryFile> files;
  std::vector<std::string> not_held;  ///< "axis Y: why" / "the machine file: why"
};

/// The entries of `model` for `format`: each axis the format can hold, in the machine's order.
ControlEntries control_entries(const MachineModel& model, ControlFormat format);

}  // namespace ncpost::comp
