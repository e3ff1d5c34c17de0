// SPDX-License-Identifier: Apache-2.0
#pragma once
// Human reports of an identification: text for the terminal and a self-contained HTML page
// (inline SVG, no external resources) with the ballbar trajectories as polar plots (measured,
// fitted and nominal-model ΔL against the rotary angle), the parameters in µm / µrad with their
// uncertainty, the identifiability findings and the residual before and after per file.
#include <string>
#include <vector>

#include "ncpost/compensation/identify.hpp"

namespace ncpost::comp {

/// Value of a parameter in report units: µm for lengths, µrad for angles, µm/s etc. for drift.
struct ReportValue {
  double value = 0.0;
  std::string unit;
};
ReportValue report_value(const Machine& machine, const std::string& name, double value_si);

std::string text_report(const Machine& machine, const std::vector<MeasurementSet>& sets, const IdentifyResult& result);
std::string html_report(const Machine& machine, const std::vector<MeasurementSet>& sets, const IdentifyResult& result);

}  // namespace ncpost::comp
