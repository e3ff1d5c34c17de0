// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/landing_check.hpp"
#include "ncpost/kinematics/units.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace ncpost::comp {

namespace {}

LandingCheck check_landing(const MachineModel& model, const AxisExport& a, const MotorCommand& motor,
                           bool both_directions) {
  LandingCheck c;
  c.positions = kLandingPositions;
  c.both_directions = both_directions;
  // a continuous axis: one turn, its end the same position as its start
  const int last = a.continuous ? kLandingPositions : kLandingPositions - 1;
  auto off = [&](double actual, double n) {
    return std::abs(a.rotary ? std::remainder(actual - n, kTwoPi) : actual - n);
  };
  for (int k = 0; k < kLandingPositions; ++k) {
    const double n = a.travel_min + (a.travel_max - a.travel_min) * k / std::max(last, 1);
    for (bool falling : {false, true}) {
      if (falling && !both_directions) continue;
      const double m = motor(n, falling);
      c.with_file = std::max(c.with_file, off(m + axis_positioning_error(model, a.axis_index, m, falling), n));
      c.model_only = std::max(c.model_only, off(n + axis_positioning_error(model, a.axis_index, n, falling), n));
    }
  }
  return c;
}

std::string landing_note(const AxisExport& a, const LandingCheck& c, const std::string& control) {
  const char* unit = a.rotary ? "µrad" : "µm";
  const double to_micro = a.rotary ? 1e6 : 1e3;
  return fmt::format(
      "Round trip: applied as {} applies it, this file puts {} within {:.4f} {} of the commanded position at "
      "{} positions over the travel{} (the model's error there without it: up to {:.3f} {}).",
      control, a.letter, c.with_file * to_micro, unit, c.positions,
      c.both_directions ? ", each direction" : ", moving up", c.model_only * to_micro, unit);
}

}  // namespace ncpost::comp
