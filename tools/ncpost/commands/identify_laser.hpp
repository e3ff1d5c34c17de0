// SPDX-License-Identifier: Apache-2.0
#pragma once
// `ncpost identify` on laser interferometer data (issue 7): the 21 errors of the linear axes
// (compensation/laser_identify.hpp), model JSON, text report on stdout, optional HTML report.
#include <string>
#include <vector>

#include "kind_steps.hpp"
#include "ncpost/compensation/identify_report.hpp"
#include "ncpost/compensation/measurement.hpp"

namespace ncpost::cli {

/// The model and (with a `report` path) the HTML report to write; throws Infeasible if the
/// identification fails (after the text report). With `options_ignored` a notice says that
/// --params, --fixed and --loss do not apply (the laser model is the 18 tables, the squareness and
/// the reversal).
IdentifyOutput identify_laser(const Machine& machine, const std::vector<comp::MeasurementSet>& sets,
                              const std::string& report, bool options_ignored = false,
                              const comp::IdentifyReportInputs& report_inputs = {});

}  // namespace ncpost::cli
