// SPDX-License-Identifier: Apache-2.0
#pragma once
// Looking at a residual directly (issue 6, step 2): its spectrum against each rotary angle, its
// correlation with the direction each axis last moved (reversal) and with time. Descriptive
// statistics for the report; the choice of effects is made by fitting (diagnose.hpp).
//
// Residual = predicted − measured, per value (ballbar L; sphere dx, dy, dz; laser e), in µm.
//   spectrum    least-squares fit of c0 + Σ_k (a_k cos kq + b_k sin kq), k = 1..4, q the rotary
//               command (rad); amplitude_um[k−1] = √(a_k² + b_k²). Only where q takes at least 9
//               distinct values over at least 270° (the harmonics separate only over most of a turn).
//   reversal    direction d = +1 if the axis last moved up (the first row counts as from below),
//               −1 if it last moved down; Pearson correlation of the residual with d and the
//               mean residual of falling minus rising rows (µm). Only axes that move both ways.
//   time        Pearson correlation with the time stamp and the least-squares slope (µm/h).
#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "ncpost/compensation/measurement.hpp"

namespace ncpost::comp {

struct SpectrumLine {
  std::string file;
  int value = 0;  ///< value column (0 for L, 0..2 for dx dy dz)
  char axis = 'C';
  std::array<double, 4> amplitude_um{};
};

struct DirectionLine {
  std::string file;
  int value = 0;
  char axis = 'C';
  double correlation = 0.0;
  double falling_minus_rising_um = 0.0;
};

struct TimeLine {
  std::string file;
  int value = 0;
  double correlation = 0.0;
  double slope_um_per_h = 0.0;
};

struct ResidualSignature {
  std::vector<SpectrumLine> spectrum;
  std::vector<DirectionLine> reversal;
  std::vector<TimeLine> time;
};

/// `residual_mm`: stacked as residuals.hpp (set by set, row by row, value by value).
ResidualSignature residual_signature(const Machine& machine, const std::vector<MeasurementSet>& sets,
                                     const Eigen::VectorXd& residual_mm);

/// Noise level estimated from the data alone: successive differences of the residual along
/// continuous (ballbar, laser) sets, σ² = Σ(r_{i+1} − r_i)² / (2(n − 1)) pooled — systematic
/// errors vary slowly between neighbouring rows and drop out. Without such sets, the rms of the
/// residual (an upper bound). µm.
double noise_from_differences_um(const std::vector<MeasurementSet>& sets, const Eigen::VectorXd& residual_mm);

/// Name of a value column for reports: "L", "dx", "dy", "dz", "e_um".
std::string value_name(const MeasurementSet& set, int value);

}  // namespace ncpost::comp
