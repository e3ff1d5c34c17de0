// SPDX-License-Identifier: Apache-2.0
#pragma once
// The measurement conditions in the identification reports (issue 25 item 3): the machine's
// serial and owner and the measurement dates in the provenance table; a section with each file's
// date, temperature, expansion coefficient, the correction to 20 °C applied (ISO 1,
// thermal_correction.hpp), instrument, serial and operator; the warnings about temperatures that
// disagree, and the reader's notices (unknown keys). Text for the terminal, HTML for the page.
#include <string>
#include <vector>

#include "ncpost/compensation/identify_report.hpp"
#include "ncpost/compensation/measurement.hpp"
#include "ncpost/report/html_page.hpp"

namespace ncpost::comp {

/// Adds the rows "machine serial", "machine owner" (when given) and "measured" (the files' dates,
/// or "not given") to the provenance table.
void add_condition_rows(report::Provenance& provenance, const IdentifyReportInputs& inputs,
                        const std::vector<MeasurementSet>& sets);

/// How the file's values were corrected to 20 °C, in words ("L / 1.0000403 (largest change
/// 4.03 µm)", "not corrected: no temperature given", ...).
std::string correction_text(const MeasurementSet& set);

/// The section "Measurement conditions" (HTML).
std::string conditions_html(const std::vector<MeasurementSet>& sets);

/// The same for the terminal: one line per file, then the warnings.
std::string conditions_text(const std::vector<MeasurementSet>& sets);

}  // namespace ncpost::comp
