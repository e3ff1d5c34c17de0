// SPDX-License-Identifier: Apache-2.0
#pragma once
// Laser interferometer readings predicted by the error model (docs/conventions.md "Measurements",
// docs/formats.md laser CSV; issue 7). A reading is 1000 · the `component` of
// [table_T_tool(q) · tool_point − nominal] (µm), with the set-up at home, minus the same at the
// first row of the run (the instrument is zeroed there).
//
// Reversal: with the `approach` column (ISO 230-2 test cycle: overshoot, then approach) the
// moving axis stands at command + reversal width when approached from above (−1) and at the
// command when approached from below (+1), the dead band of reversal.hpp after an overshoot;
// the other axes stand still on the line (offset 0). Without the column the row order decides
// (prediction.hpp).
#include <vector>

#include "ncpost/compensation/error_model.hpp"
#include "ncpost/compensation/measurement.hpp"

namespace ncpost::comp {

/// The moving axis of a laser set: the `# axis:` key, else the axis whose command varies most.
int laser_moving_axis(const MeasurementSet& set);

/// True if every row of the set carries an approach direction.
bool has_approach(const MeasurementSet& set);

/// Row state of a laser row: reversal offset of the moving axis from its approach direction.
RowState<double> laser_row_state(const ModelLayout& layout, const double* values, int moving_axis,
                                 const MeasurementRow& row);

/// Raw reading (µm, not zeroed) of one row with the error hook `errors` (its state set for the row).
double laser_raw_reading_um(const Machine& machine, const MeasurementSet& set, const MeasurementRow& row,
                            const ErrorFunctor<double>& errors);

/// Predicted e_um of every row (zeroed per run), reversal from the approach column when present
/// (else prediction.hpp's row order).
std::vector<double> predict_laser_set(const Machine& machine, const MeasurementSet& set, const ModelLayout& layout,
                                      const double* values);

}  // namespace ncpost::comp
