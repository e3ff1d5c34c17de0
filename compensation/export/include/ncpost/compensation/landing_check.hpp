// SPDX-License-Identifier: Apache-2.0
#pragma once
// The check every axis-table export makes of its own file (issue 25): the table applied as the
// control applies it (`motor`: the drive command the control gives for a commanded position, from
// the very values written in the file), the axis's actual position from the one evaluation of the
// model (axis_positioning_error, export_axis_table.hpp), at evenly spaced commanded positions over the
// travel. What the file claims to hold is then a measured departure, printed in its notes, not a
// promise. Units: mm / rad inside; the notes in µm or µrad.
#include <functional>
#include <string>

#include "ncpost/compensation/export_axis_table.hpp"

namespace ncpost::comp {

/// Commanded positions checked per direction of motion.
inline constexpr int kLandingPositions = 1000;

struct LandingCheck {
  double with_file = 0.0;   ///< largest |actual − commanded| with the file (mm or rad)
  double model_only = 0.0;  ///< the same without it: the model's own error (mm or rad)
  int positions = 0;        ///< commanded positions checked, each direction
  bool both_directions = true;
};

/// The drive command for commanded position n (mm or rad), moving down (`falling`) or up.
using MotorCommand = std::function<double(double n, bool falling)>;

/// Checks `motor` at kLandingPositions commanded positions evenly over the travel, moving up and,
/// with `both_directions`, down.
LandingCheck check_landing(const MachineModel& model, const AxisExport& axis, const MotorCommand& motor,
                           bool both_directions);

/// The note of the check: "Round trip: ..." (one line).
std::string landing_note(const AxisExport& axis, const LandingCheck& check, const std::string& control);

}  // namespace ncpost::comp
