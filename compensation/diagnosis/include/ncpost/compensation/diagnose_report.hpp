// SPDX-License-Identifier: Apache-2.0
#pragma once
// Reports of residual analysis (issue 6, step 4): text for the terminal and an HTML section for
// `identify --report` (the identification page of identify_report.hpp with the residual
// analysis added: the effects, residual per file before / after, predicted tool-tip error, the
// residual's signature, and inline-SVG scatter plots of the residual (µm) against each rotary
// angle (deg) and against time (s), basic model in grey, final model in blue).
#include <string>
#include <vector>

#include "ncpost/compensation/diagnose.hpp"
#include "ncpost/compensation/diagnose_tool_tip.hpp"
#include "ncpost/compensation/identify_report.hpp"

namespace ncpost::comp {

std::string text_diagnose_report(const Machine& machine, const std::vector<MeasurementSet>& sets,
                                 const DiagnoseResult& result, const ToolTipComparison& tool_tip);

/// The whole page: html_report of the final fit with the residual analysis inserted.
std::string html_diagnose_report(const Machine& machine, const std::vector<MeasurementSet>& sets,
                                 const DiagnoseResult& result, const ToolTipComparison& tool_tip,
                                 const IdentifyReportInputs& inputs = {});

}  // namespace ncpost::comp
