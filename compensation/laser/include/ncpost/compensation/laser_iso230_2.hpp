// SPDX-License-Identifier: Apache-2.0
#pragma once
// ISO 230-2 (2014) evaluation of a bidirectional positioning test of one linear axis on one
// line: at each target i the mean positional deviations x̄↑_i, x̄↓_i (µm; deviation = actual −
// target as read by the laser, zeroed at each run's first target) and the estimators of the
// standard uncertainty s↑_i, s↓_i over the runs; then
//   reversal value            B_i = x̄↑_i − x̄↓_i,  B = max |B_i|,  mean reversal B̄
//   repeatability             R↑_i = 4 s↑_i,  R↓_i = 4 s↓_i,  R_i = max(2s↑_i + 2s↓_i + |B_i|, R↑_i, R↓_i),
//                             R = max R_i
//   systematic deviation      E = max(x̄↑, x̄↓) − min(x̄↑, x̄↓)
//   mean bidirectional        M = max x̄_i − min x̄_i with x̄_i = (x̄↑_i + x̄↓_i)/2
//   accuracy (bidirectional)  A = max(x̄↑ + 2s↑, x̄↓ + 2s↓) − min(x̄↑ − 2s↑, x̄↓ − 2s↓)
// All in µm. Rows without an approach direction are classified by the row order (rising
// command: +1).
#include <string>
#include <vector>

#include "ncpost/compensation/measurement.hpp"

namespace ncpost::comp {

struct Iso230Target {
  double target_mm = 0.0;
  double mean_up_um = 0.0, mean_down_um = 0.0;
  double s_up_um = 0.0, s_down_um = 0.0;
  int runs_up = 0, runs_down = 0;

  double reversal_um() const { return mean_up_um - mean_down_um; }                    ///< B_i
  double mean_bidirectional_um() const { return 0.5 * (mean_up_um + mean_down_um); }  ///< x̄_i
  /// R_i = max(2s↑_i + 2s↓_i + |B_i|, R↑_i, R↓_i) with R↑_i = 4s↑_i, R↓_i = 4s↓_i.
  double repeatability_um() const;
};

struct Iso230Figures {
  char axis = 'X';
  std::string file;
  std::vector<Iso230Target> targets;
  double accuracy_A_um = 0.0;
  double repeatability_R_um = 0.0;
  double reversal_B_um = 0.0;     ///< max |B_i|
  double mean_reversal_um = 0.0;  ///< B̄
  double systematic_E_um = 0.0;
  double mean_bidirectional_M_um = 0.0;
  bool ok = false;  ///< false if the set is not a bidirectional positioning test
  std::string message;
};

/// Figures of one positioning set (component = moving axis). Needs ≥ 2 runs per direction.
Iso230Figures iso230_2_figures(const MeasurementSet& positioning_set);

}  // namespace ncpost::comp
