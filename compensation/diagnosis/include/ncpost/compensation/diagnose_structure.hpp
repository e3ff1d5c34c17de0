// SPDX-License-Identifier: Apache-2.0
#pragma once
// Structure left in a residual (issue 17): is what the model leaves at the noise, or does it still
// depend on where a rotary axis stands? For every set, value column (L; dx, dy, dz) and rotary
// axis the set moves, the rows are grouped by the axis's command (its distinct angles round the
// turn, or 36 equal bins when there are more than 72; 12 bins over the range of an axis that does
// not turn and takes more than 24 values) and a one-way analysis of variance compares the spread
// of the group means with the spread within the groups:
//    F = (SSB / (g − 1)) / (SSW / (n − g)),
// which needs no noise level from elsewhere (each set's own scatter is the reference, so a touch
// probe's noise and a ballbar's are each judged by themselves). A column is structured when its
// p-value is below `significance` / (number of columns tested) (Bonferroni).
//
// An effect of two axes together (e.g. an error of C whose amplitude grows with A) can leave no
// structure against either axis alone; along a continuous path (a ballbar run) it still varies
// smoothly where noise does not: von Neumann's ratio η = Σ(r_{i+1} − r_i)² / Σ(r_i − r̄)² (2 for
// noise, variance ≈ 4/n) is tested one-sided, z = (2 − η) / √(4(n − 2)/(n² − 1)), among the same
// Bonferroni family; its rows are grouped in runs of 10 (f_statistic = 2 / η).
//
// The shape of the group means names what is left: "6 per revolution" when one harmonic order
// carries at least 70 % of their variance, "local" when it is a peak at most 120° wide, a linear
// trend for an axis that does not turn, else "irregular"; and the measurement that would resolve
// it (a finer grid of the axis, a second sphere position). Units: µm, degrees.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "ncpost/compensation/measurement.hpp"

namespace ncpost::comp {

struct ResidualStructure {
  std::string file;
  std::string value;  ///< "L", "dx", "dy", "dz", "e_um"
  char axis = 'C';
  int groups = 0;  ///< angles (or bins) the rows were grouped by
  double f_statistic = 0.0;
  double p_value = 1.0;
  double spread_um = 0.0;     ///< rms of the group means about their mean
  double largest_um = 0.0;    ///< largest group mean (signed)
  double at_deg = 0.0;        ///< where it is
  int order = 0;              ///< dominant harmonic order (turning axis), 0 if none dominates
  std::string shape;          ///< e.g. "6 per revolution of C, 2.31 µm", "local: 3.1 µm at 120°, about 30° wide"
  std::string proposal;       ///< the measurement that would resolve it
  std::size_t set_index = 0;  ///< the set (index into the sets) and value column it is in
  int value_index = 0;
  std::vector<int> group_of_row;  ///< the group of each row of the set (the means compared)
};

/// The structured columns of `residual_mm` (stacked as residuals.hpp), strongest first. With
/// `only_type`, only the sets of that type are looked at.
std::vector<ResidualStructure> residual_structure(const Machine& machine, const std::vector<MeasurementSet>& sets,
                                                  const Eigen::VectorXd& residual_mm, double significance,
                                                  const MeasurementType* only_type = nullptr);

/// Every column tested (set, value, axis; and the path test of ballbar runs), with its statistic
/// and grouping, unfiltered: residual_structure keeps the significant ones.
std::vector<ResidualStructure> residual_columns(const Machine& machine, const std::vector<MeasurementSet>& sets,
                                                const Eigen::VectorXd& residual_mm,
                                                const MeasurementType* only_type = nullptr);

}  // namespace ncpost::comp
