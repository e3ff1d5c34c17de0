// SPDX-License-Identifier: Apache-2.0
#pragma once
// Residuals and their exact Jacobian for identification: predicted − measured for every value
// of every measurement set, in mm (laser values converted from µm), stacked set by set, row by
// row (prediction.hpp). The Jacobian with respect to chosen parameters comes from reverse-mode
// differentiation through the same templated chain (prediction_jacobian.hpp).
#include <vector>

#include <Eigen/Core>

#include "ncpost/compensation/error_model.hpp"
#include "ncpost/compensation/measurement.hpp"

namespace ncpost::comp {

struct ResidualProblem {
  const Machine* machine = nullptr;
  const std::vector<MeasurementSet>* sets = nullptr;
  ModelLayout layout;

  Eigen::Index residual_count() const;
  /// Predicted values (file units) of every set for the parameter values (layout order).
  std::vector<std::vector<double>> predictions(const std::vector<double>& values) const;
  /// predicted − measured (mm).
  Eigen::VectorXd residuals(const std::vector<double>& values) const;
  /// d residuals / d values[columns[j]] (mm per mm or rad), exact.
  Eigen::MatrixXd jacobian(const std::vector<double>& values, const std::vector<int>& columns) const;
};

}  // namespace ncpost::comp
