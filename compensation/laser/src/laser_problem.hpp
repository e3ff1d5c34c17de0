// SPDX-License-Identifier: Apache-2.0
#pragma once
// The least-squares problem of laser identification (laser_identify.hpp; internal): table nodes
// of the measured axes, the model layout, residuals and the Jacobian by central differences
// over the nodes that carry each row (every row is zeroed at its run's first row): a row reads a
// table at its own position only, so the two nodes around it share one pair of readings.
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "ncpost/compensation/error_model.hpp"
#include "ncpost/compensation/measurement.hpp"

namespace ncpost::comp::laser {

constexpr char kComponents[] = "XYZABC";

/// Priority of a component error function in the rank analysis (lower: kept first): positioning,
/// reversal (1), straightness, pitch/yaw, roll.
int priority_of(int axis, int component);

/// Approach directions from the row order where the file has none (rising: +1; a repeated
/// target reverses; the first row of a run: +1).
void fill_approach(MeasurementSet& set);

struct Problem {
  const Machine* machine = nullptr;
  std::vector<MeasurementSet> sets;
  std::array<std::vector<double>, 3> nodes;                   ///< per axis, ascending, with home (empty: not measured)
  std::array<std::array<std::vector<int>, 6>, 3> node_param;  ///< layout index per axis, component, node
  std::array<int, 3> reversal_param{-1, -1, -1};
  std::vector<std::string> names;  ///< layout order
  ModelLayout layout;
  std::vector<int> column_of;  ///< layout index → Jacobian column (−1: fixed home node)
  std::vector<int> param_of;   ///< column → layout index
  std::vector<int> moving;     ///< per set
  Eigen::Index rows = 0;

  /// What a row's raw reading depends on: per function the fitted nodes (layout index, −1: none or
  /// not fitted) around the row's position with their interpolation weights, and the reversal.
  struct Support {
    std::array<int, 2> index;
    std::array<double, 2> weight;
  };
  std::vector<Support> support(int set_index, const MeasurementRow& row) const;
  /// d raw reading / d (the function's value at the row's position) by central differences on the
  /// nodes of `g` (0 when it has none); `values` (layout order) restored on return.
  double value_derivative(int set_index, const MeasurementRow& row, const Support& g,
                          std::vector<double>& values) const;
  /// Raw reading (µm) of a row for the values (layout order).
  double raw(int set_index, const MeasurementRow& row, const std::vector<double>& values) const;
  /// measured − predicted (µm), stacked set by set.
  Eigen::VectorXd residual(const std::vector<double>& values) const;
  /// d prediction / d parameter (µm per mm or rad), columns = fitted parameters.
  Eigen::MatrixXd jacobian(const std::vector<double>& values) const;
};

}  // namespace ncpost::comp::laser
