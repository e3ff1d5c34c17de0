// SPDX-License-Identifier: Apache-2.0
#pragma once
// The one-page summary (summary_page.hpp) of an identification from ballbar or sphere data, and of
// a laser identification: the figures the full report judges, the same values and verdicts.
//   every data file   its largest deviation from the nominal machine and the largest residual the
//                     model leaves, ± U of one reading (reading_budget), judged against
//                     --pass-tolerance-um
//   every ballbar     ISO 230-4 G (and of each direction, and H, where both were run) ± U, judged
//                     against the G tolerance
//   the model         its parameters ± U = 2u (µm, µrad)
//   laser lines       ISO 230-2 A, B, E, M, R ± U, each kind judged against its tolerance
#include <string>
#include <vector>

#include "ncpost/compensation/identify_report.hpp"
#include "ncpost/compensation/laser_identify.hpp"
#include "ncpost/compensation/summary_page.hpp"

namespace ncpost::comp {

/// `report_path`: the full report it sits beside (linked).
IdentificationSummary identification_summary(const Machine& machine, const std::vector<MeasurementSet>& sets,
                                             const IdentifyResult& result, const IdentifyReportInputs& inputs,
                                             const std::string& report_path);

IdentificationSummary laser_identification_summary(const Machine& machine, const std::vector<MeasurementSet>& sets,
                                                   const LaserIdentifyResult& result,
                                                   const IdentifyReportInputs& inputs, const std::string& report_path);

}  // namespace ncpost::comp
