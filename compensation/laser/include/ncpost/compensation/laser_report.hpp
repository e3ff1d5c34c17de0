// SPDX-License-Identifier: Apache-2.0
#pragma once
// Human reports of a laser identification (issue 7): text for stdout, self-contained HTML with a
// plot per error function (SVG). Values in µm and µrad; ISO 230-2 figures per positioning line;
// squareness from the straightness slopes (ISO 230-1); what the lines cannot see.
#include <string>

#include "ncpost/compensation/identify_report.hpp"
#include "ncpost/compensation/laser_identify.hpp"

namespace ncpost::comp {

std::string laser_text_report(const Machine& machine, const LaserIdentifyResult& result);
/// With the provenance (the sets' files and the inputs' with SHA-256), the ISO 230-2
/// bidirectional plot of every positioning line (x̄↑, x̄↓ ± 2s, reversal B_i, tick values in µm
/// and mm), the error functions, and with a tolerance a pass/fail of each line's accuracy A.
std::string laser_html_report(const Machine& machine, const LaserIdentifyResult& result,
                              const std::vector<MeasurementSet>& sets = {}, const IdentifyReportInputs& inputs = {});

}  // namespace ncpost::comp
