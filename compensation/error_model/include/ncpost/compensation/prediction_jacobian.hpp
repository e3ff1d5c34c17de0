// SPDX-License-Identifier: Apache-2.0
#pragma once
// The exact derivatives of the measurement predictions (prediction.hpp) with respect to chosen
// parameters, by reverse-mode differentiation: each row's evaluation is recorded once, with only
// the chosen parameters as variables, and swept back from each of its values. The cost is about
// that of a few plain evaluations per row whatever the number of parameters (issue 26: forward
// mode took one pass of 16-wide derivatives per 16 parameters, 75 % of the residual analysis).
#include <vector>

#include <Eigen/Core>

#include "ncpost/compensation/error_model.hpp"
#include "ncpost/compensation/measurement.hpp"

namespace ncpost::comp {

/// d prediction / d values[columns[j]] (mm per mm or rad; laser values converted from µm by
/// value_unit_mm) for every value of every set, stacked set by set and row by row as the
/// predictions; a laser row relative to its run's first row, as predicted.
Eigen::MatrixXd prediction_jacobian_mm(const Machine& m, const std::vector<MeasurementSet>& sets,
                                       const ModelLayout& layout, const std::vector<double>& values,
                                       const std::vector<int>& columns);

}  // namespace ncpost::comp
