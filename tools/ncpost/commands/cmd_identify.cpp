// SPDX-License-Identifier: Apache-2.0
// ncpost identify: fit error parameters to measurements (README "Worked example" and docs/metrology.md "Closing the
// loop").
#include <fmt/format.h>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "commands.hpp"
#include "file_checks.hpp"
#include "number_checks.hpp"
#include "tolerance_option.hpp"
#include "identify_laser.hpp"
#include "machine_kind.hpp"
#include "ncpost/postproc/write/atomic_file.hpp"
#include "ncpost/compensation/conditions_report.hpp"
#include "ncpost/compensation/control_entries.hpp"
#include "ncpost/compensation/decision_rule.hpp"
#include "ncpost/compensation/diagnose_report.hpp"
#include "ncpost/compensation/identify.hpp"
#include "ncpost/compensation/identify_report.hpp"
#include "ncpost/compensation/identify_summary.hpp"
#include "ncpost/compensation/laser_identify.hpp"
#include "ncpost/compensation/measurement_files.hpp"
#include "ncpost/compensation/model_json.hpp"
#include "ncpost/compensation/parameter_name.hpp"
#include "ncpost/compensation/thermal_correction.hpp"
#include "ncpost/machines/load.hpp"
#include "ncpost/machines/machine_record.hpp"

namespace ncpost::cli {

namespace {

std::vector<std::string> split_list(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ',')) {
    item.erase(0, item.find_first_not_of(" \t"));
    item.erase(item.find_last_not_of(" \t") + 1);
    if (!item.empty()) out.push_back(item);
  }
  return out;
}

/// The readers' notices and the temperature warnings on stderr; the conditions on stdout when a
/// file gives any (issue 25 item 3).
void print_conditions(const std::vector<comp::MeasurementSet>& sets) {
  bool any = false;
  for (const auto& s : sets) {
    for (const auto& n : s.notices) fmt::print(stderr, "notice: {}\n", n);
    any = any || s.conditions.any();
  }
  const std::vector<std::string> warnings = comp::temperature_warnings(sets);
  for (const auto& w : warnings) fmt::print(stderr, "ncpost: warning: {}\n", w);
  if (any || !warnings.empty()) fmt::print("{}", comp::conditions_text(sets));
}

/// Residual analysis (issue 6): basic fit, effects added by evidence, before/after report.
IdentifyOutput run_diagnose(const Machine& m, const std::vector<comp::MeasurementSet>& sets,
                            const std::vector<std::string>& names, const comp::IdentifyOptions& o,
                            const std::string& report, const comp::IdentifyReportInputs& inputs) {
  comp::DiagnoseOptions d;
  d.identify = o;
  if (isatty(fileno(stderr))) d.progress = [](const std::string& s) { fmt::print(stderr, "diagnose: {}\n", s); };
  const comp::DiagnoseResult r = comp::diagnose(m, sets, names, d);
  const comp::ToolTipComparison tt = comp::within_measured_region(
      comp::compare_tool_tip(m, r.final_fit.parameters, r.basic.parameters, r.final_fit.uncertainty,
                             r.final_fit.covariance),
      m, sets, r.final_fit.parameters, r.basic.parameters, r.final_fit.uncertainty, r.final_fit.covariance);
  fmt::print("{}", comp::text_report(m, sets, r.final_fit));
  fmt::print("{}", comp::text_diagnose_report(m, sets, r, tt));
  if (!r.final_fit.converged) throw Infeasible("the fit " + r.final_fit.message);
  IdentifyOutput out;
  out.model_json = comp::format_model_json(comp::to_model_file(m, r));
  if (!report.empty()) {
    out.report_html = comp::html_diagnose_report(m, sets, r, tt, inputs);
    out.summary_html = comp::summary_page_html(comp::identification_summary(m, sets, r.final_fit, inputs, report));
  }
  return out;
}

}  // namespace

/// The serial machines: the basic model and --params fitted to ballbar, sphere or laser data, with
/// the residual analysis unless --no-diagnose.
IdentifyOutput identify_serial(const IdentifyArgs& a) {
  const Machine m = machines::load_as<Machine>(a.machine);
  const comp::Tolerances tolerances = tolerances_from(a.tolerance, a.machine);  // over the machine file's
  const MachineRecord record = load_machine_record(a.machine);
  const std::vector<comp::MeasurementSet> sets = comp::read_measurement_files(a.data, m);
  print_conditions(sets);
  comp::IdentifyReportInputs report_inputs{a.machine, a.output, a.pass_tolerance_um, std::nullopt};
  report_inputs.machine_record = record;
  report_inputs.tolerances = tolerances;
  if (!a.control.empty()) report_inputs.control = comp::parse_control_format(a.control);
  if (comp::all_laser(sets))  // issue 7
    return identify_laser(m, sets, a.report, !a.params.empty() || !a.fixed.empty() || a.loss != "squared",
                          report_inputs);
  std::vector<std::string> names = a.no_basic ? std::vector<std::string>{} : comp::basic_parameters(m);
  for (const auto& n : split_list(a.params)) {
    const comp::ParseResult r = comp::parse_parameter_name(n, m);
    if (!r.spec) throw UsageError(fmt::format("--params: '{}': {}", n, r.error));
    if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
  }
  comp::IdentifyOptions o;
  o.loss = a.loss == "huber" ? comp::Loss::huber : a.loss == "cauchy" ? comp::Loss::cauchy : comp::Loss::squared;
  o.loss_scale_um = a.loss_scale_um;
  for (const auto& item : split_list(a.fixed)) {
    const auto eq = item.find('=');
    if (eq == std::string::npos) throw UsageError(fmt::format("--fixed expects NAME=VALUE, found '{}'", item));
    const std::string n = item.substr(0, eq);
    const comp::ParseResult r = comp::parse_parameter_name(n, m);
    if (!r.spec) throw UsageError(fmt::format("--fixed: '{}': {}", n, r.error));
    // mm or rad: no location or scale error of a real machine comes near a metre or a radian
    o.fixed.set(n, finite_number(item.substr(eq + 1), "--fixed " + n, -1000.0, 1000.0, "mm or rad"));
  }
  if (names.empty()) throw UsageError("nothing to identify: give --params or drop --no-basic");
  if (!a.no_diagnose) return run_diagnose(m, sets, names, o, a.report, report_inputs);
  const comp::IdentifyResult r = comp::identify(m, sets, names, o);
  fmt::print("{}", comp::text_report(m, sets, r));
  if (!r.converged) throw Infeasible("the fit " + r.message);
  IdentifyOutput out;
  out.model_json = comp::format_model_json(comp::to_model_file(m, r));
  if (!a.report.empty()) {
    out.report_html = comp::html_report(m, sets, r, report_inputs);
    out.summary_html = comp::summary_page_html(comp::identification_summary(m, sets, r, report_inputs, a.report));
  }
  return out;
}

void add_identify(CLI::App& app, Action& action) {
  auto a = std::make_shared<IdentifyArgs>();
  CLI::App* sub = app.add_subcommand("identify", "Identify geometric errors from measurements");
  sub->add_option("--machine", a->machine, "machine definition (TOML)")->required();
  sub->add_option("--params", a->params,
                  "parameters to fit besides the basic model (location errors of the rotary axes), comma-separated, "
                  "e.g. EC0Y,ECC:h2:cos,ECC:h2:sin,reversal:A");
  sub->add_flag("--no-basic", a->no_basic, "fit only the --params (no location errors)");
  sub->add_option("--fixed", a->fixed,
                  "known parameters held at a value, NAME=VALUE comma-separated (mm, rad), e.g. EB0B=1e-5,EC0C=0");
  sub->add_option("--loss", a->loss, "squared (default), huber or cauchy (outlier-robust)")
      ->check(CLI::IsMember({"squared", "huber", "cauchy"}));
  sub->add_option("--loss-scale-um", a->loss_scale_um, "scale of the robust loss (µm, default 3)")
      ->check(finite_in(0.0, 10000.0, "µm", Bound::open));
  sub->add_flag("--no-diagnose", a->no_diagnose, "fit the basic model only (no residual analysis)");
  sub->add_option("--report", a->report, "self-contained HTML report");
  sub->add_option("--pass-tolerance-um", a->pass_tolerance_um,
                  "tolerance (µm) for the report's pass/fail verdicts: largest deviation per file, ISO 230-4 G")
      ->check(finite_in(0.0, 10000.0, "µm", Bound::open));
  sub->add_option(
      "--tolerance", a->tolerance,
      "tolerances per figure kind for the report's ISO 14253-1 verdicts, KIND=µm comma-separated: ISO 230-2 "
      "A, B, E, M, R and ISO 230-4 G, e.g. G=10,A=8,R=3 (over the machine file's [tolerances])");
  std::vector<std::string> control_names;
  for (const comp::ControlFormatInfo& f : comp::control_formats()) control_names.push_back(f.name);
  sub->add_option("--control", a->control,
                  "the report's compensation values as this control's own entries, the lines `ncpost export --format` "
                  "writes: machine (kinematics corrections; the default with a rotary axis), linuxcnc (the default "
                  "without), siemens, isg")
      ->check(CLI::IsMember(control_names));
  sub->add_option("-o,--output", a->output, "model JSON to write")->required();
  sub->add_option("data", a->data, "measurement CSV files (ballbar, sphere, laser)")->required();
  sub->callback([&action, a] {
    action = [a] {
      std::vector<NamedPath> inputs{{"--machine", a->machine}};
      for (const auto& f : a->data) inputs.push_back({"data", f});
      check_files({{"-o", a->output},
                   {"--report", a->report},
                   {"--report (its summary)", a->report.empty() ? std::string() : comp::summary_path(a->report)}},
                  inputs);
      const IdentifyOutput out = machine_kind(a->machine).identify(*a);
      write_file_atomically(a->output, out.model_json);
      if (!a->report.empty()) write_file_atomically(a->report, out.report_html);
      if (!a->report.empty() && !out.summary_html.empty())
        write_file_atomically(comp::summary_path(a->report), out.summary_html);
      fmt::print("{}", out.closing);
      return 0;
    };
  });
}

}  // namespace ncpost::cli
