// SPDX-License-Identifier: Apache-2.0
#pragma once
// LinuxCNC's joint compensation file (`[JOINT_n]COMP_FILE`, `[AXIS_n]` before 2.8) for one axis of an
// error model, COMP_FILE_TYPE = 1 (LinuxCNC docs, docs/src/config/ini-config.adoc, "[JOINT_<num>]
// Sections": "Type 1: The second value specifies positive offset from nominal while traveling in
// the positive direction. The third value specifies the negative offset from nominal while
// traveling in a negative direction"; at most 256 rows, nominals ascending).
//
// How LinuxCNC applies it (src/emc/motion/usrmotintf.cc usrmotLoadComp, control.c
// compute_screw_comp, command.c EMCMOT_SET_JOINT_COMP): each row is nominal, forward trim, reverse
// trim; the trim of the direction of the joint's commanded velocity, interpolated linearly in the
// commanded position between nominals (the end rows' trims held beyond them; kept while the joint
// stands), is added to the commanded position to give the motor command. So each trim here is the
// correction t with (n + t) + e(n + t) = n, e the model's positioning error of the axis for that
// direction (export_axis_table.hpp): about −e(n). The rows include, per direction, the commanded
// position x + e(x) where the drive passes each node x of a table, where t has its kinks
// (export_nodes.hpp), so that a table round-trips exactly. Rows come first: LinuxCNC stops reading at the
// first line that is not three numbers, so the notes follow the rows (a comment on top would leave
// the table empty without a message).
// Units: mm for linear axes, degrees for rotary axes (LinuxCNC machine units with LINEAR_UNITS = mm).
#include <array>
#include <string>
#include <vector>

#include "ncpost/compensation/export_axis_table.hpp"
#include "ncpost/compensation/landing_check.hpp"

namespace ncpost::comp {

/// Where an exported file comes from, for its notes.
struct ExportSource {
  std::string model_path;
  std::string machine_path;  ///< "" when the machine was not given
  std::string version;       ///< ncpost's version
};

struct LinuxcncCompTable {
  AxisExport axis;
  /// nominal, forward trim, reverse trim: mm (linear) or degrees (rotary)
  std::vector<std::array<double, 3>> rows;
  LandingCheck landing;  ///< the rows applied as LinuxCNC applies them, against the model
};

/// LinuxCNC's limit on rows per joint (EMCMOT_COMP_SIZE).
inline constexpr int kLinuxcncMaxRows = 256;

/// The table of axis `letter`; std::invalid_argument as describe_axis_export.
LinuxcncCompTable linuxcnc_comp_table(const MachineModel& model, char letter);

/// The rows as LinuxCNC reads them: nominal, forward trim, reverse trim (no notes).
std::vector<std::string> linuxcnc_comp_lines(const LinuxcncCompTable& table);

/// The file: the rows, then `#` notes (type, sign convention, what is held and left out).
std::string format_linuxcnc_comp(const LinuxcncCompTable& table, const MachineModel& model, const ExportSource& source);

/// The notes every exported table shares: held terms, left-out terms, where the travel reaches
/// beyond a table's nodes, other axes (one line each).
std::vector<std::string> export_notes(const AxisExport& axis, const std::string& other_axes_hint);

}  // namespace ncpost::comp
