// SPDX-License-Identifier: Apache-2.0
#pragma once
// Attribution with structure left (issue 17): when the final model of the diagnosis still leaves
// structure that no candidate explains (diagnose_structure.hpp), is an added effect justified on
// its own evidence, or did it only chase that structure?
//
// In the sets where structure is left, every shape of it against one axis is absorbed by nuisance
// columns: for every value column of such a set and every rotary axis it moves, one indicator per
// group of rows (diagnose_structure's grouping: the axis's angles or bins, runs of 10 rows along
// a ballbar path); what varies within the groups still pins the model's parameters. At the final
// solution (linearised, the exact Jacobian of residuals.hpp) the effect's columns C and the
// residual without it, r_e = r − C·β (β its fitted values), are projected off the span of the
// other fitted parameters and the nuisance columns; the effect is justified when
//   - it keeps a part of its own (separation: the smallest ratio |P c| / |c| over its columns is
//     above `alias_tolerance`), and
//   - the part of r_e it explains there is significant: F = (drop / k) / (S / (m − rank − k)),
//     S = |P r|², the forward selection's partial F test at its own level.
// A term that only chased the unexplained structure loses its evidence; one whose signature
// shows where nothing is left, or across the groups, keeps it.
#include <vector>

#include <Eigen/Core>

#include "ncpost/compensation/diagnose_structure.hpp"
#include "ncpost/compensation/measurement.hpp"

namespace ncpost::comp {

/// One indicator column per group of every column in `columns` (residual_columns) whose set has
/// structure in `left` (residuals stacked as residuals.hpp); `count` the residual's length.
Eigen::MatrixXd structure_nuisance(const std::vector<MeasurementSet>& sets,
                                   const std::vector<ResidualStructure>& columns,
                                   const std::vector<ResidualStructure>& left, Eigen::Index count);

struct OwnEvidence {
  double separation = 0.0;  ///< smallest |P c| / |c| over the effect's columns
  double f_statistic = 0.0;
  double p_value = 1.0;
  double drop_mm2 = 0.0;  ///< the part of the residual it explains beyond the structure (mm²)
};

/// `J` the Jacobian of the final model's fitted parameters (columns), `r` its residual (mm),
/// `effect` the columns of one added effect and `beta` their fitted values,
/// `nuisance` the structure's columns (structure_nuisance).
OwnEvidence own_evidence(const Eigen::MatrixXd& J, const Eigen::VectorXd& r, const std::vector<int>& effect,
                         const Eigen::VectorXd& beta, const Eigen::MatrixXd& nuisance);

}  // namespace ncpost::comp
