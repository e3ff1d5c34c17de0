// SPDX-License-Identifier: Apache-2.0
#pragma once
// The size of an added effect in one number, its standard uncertainty, and whether it is
// physically plausible (diagnose.hpp, step 2). Units mm or rad (`is_angle`):
//   harmonic     amplitude √(cos² + sin²)
//   polynomial   |value| · R^k, R the largest |command| of the axis in the data (mm)
//   squareness   |value|;  reversal: the play (must be positive);  instruments: |offset|
//   drift        the largest drift over the data's time stamps
// Uncertainties by first-order propagation of the parameters' standard deviations (no
// covariance).
#include <string>
#include <vector>

#include "ncpost/compensation/diagnose_candidates.hpp"

namespace ncpost::comp {

struct PlausibleSizes {
  double length_mm = 0.1;   ///< component errors, linear reversal
  double angle_rad = 5e-4;  ///< (≈ 100 arcsec) angular errors, squareness, rotary reversal
  double drift_mm = 0.2;    ///< over the data's time span
  double instrument_mm = 0.5;
  bool valid() const { return length_mm > 0 && angle_rad > 0 && drift_mm > 0 && instrument_mm > 0; }
};

struct EffectSize {
  double size = 0.0;
  double sigma = 0.0;
  bool is_angle = false;
  std::string implausible;  ///< why not plausible; empty if plausible
};

/// `values` / `uncertainty`: the fitted parameters (and held ones, e.g. drift tau).
EffectSize effect_size(const Machine& machine, const std::vector<MeasurementSet>& sets, const Candidate& candidate,
                       const ErrorParameters& values, const ErrorParameters& uncertainty, const PlausibleSizes& limits);

}  // namespace ncpost::comp
