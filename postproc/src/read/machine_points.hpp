// SPDX-License-Identifier: Apache-2.0
#pragma once
// Where the control's machine coordinates count from, for the readers that move in them (G-code
// G28/G53, Sinumerik SUPA/G53 and G75): the machine file's points of an axis (docs/formats.md).
#include <optional>

#include "ncpost/kinematics/machine.hpp"

namespace ncpost {

/// The axis's reference point (G28's target, the zero of G53), a command in M (mm or rad): the
/// machine file's `reference`; Z without one goes to the top of its travel, as a control's does.
/// nullopt where neither is given.
inline std::optional<double> reference_or_top(const Axis& axis) {
  if (axis.reference) return axis.reference;
  if (axis.letter == 'Z' && axis.limits) return axis.limits->max;
  return std::nullopt;
}

}  // namespace ncpost
