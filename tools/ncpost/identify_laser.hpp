#pragma once
// `ncpost identify` on laser interferometer data (issue 7): the 21 errors of the linear axes
// (compensation/laser_identify.hpp), model JSON, text report on stdout, optional HTML report.
#include <string>
#include <vector>

#include "ncpost/compensation/measurement.hpp"

namespace ncpost::cli {

/// Returns the exit code; throws Infeasible if the identification fails.
int identify_laser(const Machine& machine, const std::vector<comp::MeasurementSet>& sets, const std::string& output,
                   const std::string& report);

}  // namespace ncpost::cli
