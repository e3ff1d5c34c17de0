// SPDX-License-Identifier: Apache-2.0
#pragma once
// Human reports of an identification: text for the terminal and a self-contained HTML page
// (inline SVG, no external resources; the shared pieces of ncpost::report) naming every input with
// its SHA-256, the machine (with its serial and owner), the model, the date and the version; the
// measurement conditions and dates (conditions_report.hpp); ISO 14253-1 verdicts of figures with
// their expanded uncertainty and budget (uncertainty_report.hpp); the compensation values for the control (µm, µrad,
// and as the chosen control's own entries, control_entries.hpp); the parameters with their uncertainty, the
// identifiability findings and the residual before and after per file; the ballbar tests as polar plots labelled with
// angles and the axes moved (measured, identified and nominal-model ΔL, and the residual on its own scale) with ISO
// 230-4 figures, feed and direction; the sphere-probing positions with their dispersion per axis before and after.
#include <optional>
#include <string>
#include <vector>

#include "ncpost/compensation/control_entries.hpp"
#include "ncpost/compensation/decision_rule.hpp"
#include "ncpost/compensation/identify.hpp"
#include "ncpost/machines/machine_record.hpp"

namespace ncpost::comp {

/// Value of a parameter in report units: µm for lengths, µrad for angles, µm/s etc. for drift.
struct ReportValue {
  double value = 0.0;
  std::string unit;
};
ReportValue report_value(const Machine& machine, const std::string& name, double value_si);

std::string text_report(const Machine& machine, const std::vector<MeasurementSet>& sets, const IdentifyResult& result);
/// What the HTML report names besides the data (each file with its SHA-256) and the verdict's tolerance.
struct IdentifyReportInputs {
  std::string machine_file;                 ///< hashed in the provenance table
  std::string model_file;                   ///< the model written (-o)
  std::optional<double> pass_tolerance_um;  ///< `identify --pass-tolerance-um`: pass/fail verdicts
  /// `identify --control`: the control's own entries; unset: default_control_format(machine)
  std::optional<ControlFormat> control;
  /// The machine file's `serial` and `owner` (machine_record.hpp), shown beside its name.
  MachineRecord machine_record = {};
  /// One tolerance per figure kind (µm; decision_rule.hpp): `identify --tolerance` over the
  /// machine file's [tolerances].
  Tolerances tolerances = {};
};

/// The tolerance of a figure kind: `tolerances`, else for G and A the --pass-tolerance-um.
std::optional<double> tolerance_for(const IdentifyReportInputs& inputs, const std::string& kind);

/// The model's values as `format`'s own entries (control_entries.hpp): the lines `ncpost export`
/// writes, per file, and what the format cannot hold; an HTML section of the identification reports.
std::string control_entries_html(const Machine& machine, const ErrorParameters& parameters, ControlFormat format);

std::string html_report(const Machine& machine, const std::vector<MeasurementSet>& sets, const IdentifyResult& result,
                        const IdentifyReportInputs& inputs = {});

}  // namespace ncpost::comp
