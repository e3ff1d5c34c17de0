// SPDX-License-Identifier: Apache-2.0
#pragma once
// ISO 230-2 (2014) per target, as its tables give them (issue 25 item 5): at each target position i
// of a bidirectional positioning line, from the means and standard uncertainties of
// laser_iso230_2.hpp (µm):
//   x̄↑_i, x̄↓_i                 mean positional deviation, each direction
//   2s↑_i, 2s↓_i               twice the estimator of the standard uncertainty
//   B_i = x̄↑_i − x̄↓_i          reversal value
//   x̄_i = (x̄↑_i + x̄↓_i) / 2    mean bidirectional positional deviation
//   R↑_i = 4s↑_i, R↓_i = 4s↓_i  unidirectional repeatability
//   R_i = max(2s↑_i + 2s↓_i + |B_i|, R↑_i, R↓_i)   bidirectional repeatability
#include <string>
#include <vector>

#include "ncpost/compensation/laser_iso230_2.hpp"

namespace ncpost::comp {

struct Iso230TargetRow {
  double target_mm = 0.0;
  int runs_up = 0, runs_down = 0;
  double mean_up_um = 0.0, mean_down_um = 0.0;
  double two_s_up_um = 0.0, two_s_down_um = 0.0;
  double reversal_um = 0.0;                                          ///< B_i
  double mean_bidirectional_um = 0.0;                                ///< x̄_i
  double repeat_up_um = 0.0, repeat_down_um = 0.0, repeat_um = 0.0;  ///< R↑_i, R↓_i, R_i
};

std::vector<Iso230TargetRow> iso230_2_target_rows(const Iso230Figures& figures);

/// The rows as an HTML table headed by the line's file and axis.
std::string iso230_2_target_table_html(const Iso230Figures& figures);

}  // namespace ncpost::comp
