// SPDX-License-Identifier: Apache-2.0
#pragma once
// What a control's kinematics record cannot hold of an error model, as its effect on the workpiece
// (issue 25 item 2): the largest change of the tool tip in W (µm) when the term is removed from the
// model, at representative poses of the machine's travel.
//
// Representative poses (the rule docs/formats.md states): X, Y and Z each at the two quarter points
// of their travel (min + span/4, max - span/4; ±100 mm for an axis without limits), the rotary axis
// nearer the bed at its two limits and 0 (±90° without limits), the other at 0°, 90°, 180° and 270°:
// 8 · 3 · 4 = 96 poses of a two-rotary machine. Tool length 0 (the tip at the spindle gauge point),
// workpiece origin 0 (W = M at home). Units: mm and rad inside, µm in the result.
#include <functional>
#include <string>
#include <vector>

#include "ncpost/compensation/machine_model.hpp"

namespace ncpost::comp {

/// The poses above (commands in mm and rad).
std::vector<AxisPosition> representative_poses(const Machine& machine);

/// The rule above in words, for the exported file ("X -250/250 mm, ..., C 0/90/180/270 deg").
std::string representative_poses_text(const Machine& machine);

/// The model's machine parameters (measurement-only effects never) for which `keep` is true.
ErrorParameters parameters_where(const MachineModel& model, const std::function<bool(const ParameterSpec&)>& keep);

/// Largest tool-tip distance in W (µm) between two models of one machine at `poses`.
double largest_tip_difference_um(const MachineModel& a, const MachineModel& b, const std::vector<AxisPosition>& poses);

/// One term a record cannot hold: a location error by its name, a function of position by its
/// family ("EXX:t", "EZC"), with why and its effect.
struct LeftOutTerm {
  std::string term;
  std::string why;
  double effect_um = 0.0;  ///< largest tip change at the poses with this term alone removed
};

struct LeftOut {
  std::vector<LeftOutTerm> terms;
  double together_um = 0.0;  ///< all of them removed at once: the record against the whole model
  int poses = 0;
  std::string poses_text;
};

/// Every machine term of `model` that `held` rejects, with `why(spec)` and its effect.
LeftOut left_out_of(const MachineModel& model, const std::function<bool(const ParameterSpec&)>& held,
                    const std::function<std::string(const ParameterSpec&)>& why);

/// The `#` lines of a file listing `left` (the text after "Left out").
std::vector<std::string> left_out_lines(const LeftOut& left);

/// A table-table machine (both rotary axes carry the workpiece): indices into Machine::axes of the
/// axis nearer the bed (the tilting axis, Siemens' rotary axis 1) and of the one it carries.
struct TableTableAxes {
  int first = -1;
  int second = -1;
};
/// Throws ExportRefusal (machine at fault) naming `format` when the machine is not one.
TableTableAxes table_table_axes(const Machine& machine, const std::string& format);

}  // namespace ncpost::comp
