// SPDX-License-Identifier: Apache-2.0
#pragma once
// Plausible sizes of error parameters (issue 14 item 10; bounds in compensation/README.md
// "Model checks"). A model is applied to a real machine: a value no machine could have (a tilt of
// 1000 rad, an offset of a metre) is a wrong file, never a correction to post with.
#include <string>

#include "ncpost/compensation/parameter_name.hpp"

namespace ncpost::comp {

/// The bounds, one per kind of effect (the effect a value has, not the value itself).
struct PlausibleBounds {
  double length_mm = 1.0;       ///< offsets, translational component errors, reversal of a linear axis
  double angle_rad = 0.01;      ///< tilts, zero errors, squareness, angular component errors (0.57°)
  double travel_mm = 1000.0;    ///< polynomial terms: their effect at this distance from zero
  double duration_s = 28800.0;  ///< drift rates: their effect after this time (8 h)
  double tau_min_s = 1.0;       ///< drift time constant
  double tau_max_s = 86400.0;
  double ballbar_mm = 2.0;  ///< ballbar length offset (the bar's measuring range)
  double sphere_mm = 5.0;   ///< sphere centre offset
};

/// Why `value` of the parameter is implausible for its kind (empty if it is plausible).
std::string implausibility(const ParameterSpec& spec, const Machine& machine, double value,
                           const PlausibleBounds& bounds = {});

}  // namespace ncpost::comp
