// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/identify_summary.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "identify_report_sections.hpp"
#include "ncpost/compensation/conditions_report.hpp"
#include "ncpost/compensation/thermal_correction.hpp"
#include "ncpost/compensation/uncertainty_report.hpp"
#include "ncpost/report/html_page.hpp"

namespace ncpost::comp {
namespace {

/// More parameters than this go to the full report only (the summary stays one page).
constexpr std::size_t kParametersShown = 12;

/// The figure judged by ISO 14253-1 against `tol` (no verdict without a tolerance).
SummaryFigure judged(const std::string& what, double value_um, const UncertaintyBudget& b, std::optional<double> tol,
                     const std::string& kind) {
  SummaryFigure f{what, value_with_U(value_um, b) + " µm", "", ""};
  if (tol) {
    f.verdict = to_string(decide(value_um, b.expanded_um(), *tol));
    f.against = fmt::format("{} ≤ {:g} µm", kind, *tol);
  }
  return f;
}

/// One file's conditions in words (without its name).
std::string conditions_of(const MeasurementSet& set) {
  const MeasurementConditions& c = set.conditions;
  return fmt::format(
      "measured {}; {}; instrument {}{}; operator {}; {}", c.date.empty() ? "(date not given)" : c.date,
      c.temperature_c ? fmt::format("{:.2f} °C", *c.temperature_c) : std::string("temperature not given"),
      c.instrument.empty() ? "not given" : c.instrument, c.serial.empty() ? "" : " (serial " + c.serial + ")",
      c.operator_name.empty() ? "not given" : c.operator_name, correction_text(set));
}

IdentificationSummary common(const Machine& m, const std::vector<MeasurementSet>& sets, const IdentifyReportInputs& in,
                             const std::string& title, const std::string& report_path) {
  IdentificationSummary s;
  s.title = title;
  s.facts.push_back({"machine", m.name});
  if (!in.machine_record.serial.empty()) s.facts.push_back({"machine serial", in.machine_record.serial});
  if (!in.machine_record.owner.empty()) s.facts.push_back({"owner", in.machine_record.owner});
  if (!in.model_file.empty()) s.facts.push_back({"model written", report::base_name(in.model_file)});
  if (!in.machine_file.empty()) s.inputs.push_back({"machine file", in.machine_file});
  std::vector<std::pair<std::string, std::string>> grouped;  // conditions → the files under them, in order
  for (const MeasurementSet& set : sets) {
    s.inputs.push_back({"data", set.file});
    const std::string text = conditions_of(set);
    auto same = std::find_if(grouped.begin(), grouped.end(), [&](const auto& g) { return g.first == text; });
    if (same == grouped.end())
      grouped.push_back({text, report::base_name(set.file)});
    else
      same->second += ", " + report::base_name(set.file);
  }
  for (const auto& [text, files] : grouped) s.conditions.push_back(files + ": " + text);
  for (const std::string& w : temperature_warnings(sets)) s.warnings.push_back(w);
  s.full_report = report_path;
  return s;
}

std::pair<std::string, std::string> residual_fact(double rms_nominal, double max_nominal, double rms_after,
                                                  double max_after) {
  return {"residual (rms / max)",
          fmt::format("machine without errors {:.2f} / {:.2f} µm; with the model {:.2f} / {:.2f} µm", rms_nominal,
                      max_nominal, rms_after, max_after)};
}

void add_ballbar_figures(IdentificationSummary& s, const Machine& m, const std::vector<MeasurementSet>& sets,
                         std::size_t i, const IdentifyReportInputs& in) {
  const MeasurementSet& set = sets[i];
  const sections::BallbarFigures f = sections::ballbar_figures(m, set);
  if (!f.both.ok) return;
  const UncertaintyBudget b = circularity_budget(set, {});
  const std::string name = report::base_name(set.file);
  const std::optional<double> tol = tolerance_for(in, "G");
  s.figures.push_back(judged(name + ": G (ISO 230-4)", f.both.G_um, b, tol, "G"));
  // the other direction in another file: H of the pair, once (at the counter-clockwise file)
  if (const MeasurementSet* other = sections::opposite_run(m, sets, i); other && f.both.direction > 0)
    s.figures.push_back({name + " with " + report::base_name(other->file) + ": hysteresis H",
                         fmt::format("{:.2f} µm", *sections::two_file_hysteresis_um(m, set, *other)), "", ""});
  if (f.both.direction != 0) return;
  if (f.ccw.ok) s.figures.push_back(judged(name + ": G counter-clockwise", f.ccw.G_um, b, tol, "G"));
  if (f.cw.ok) s.figures.push_back(judged(name + ": G clockwise", f.cw.G_um, b, tol, "G"));
  if (f.both.H_um >= 0) s.figures.push_back({name + ": hysteresis H", fmt::format("{:.2f} µm", f.both.H_um), "", ""});
}

/// One positioning line in one row: A, B, E, M, R ± U; the verdict the worst of the kinds that have a tolerance.
SummaryFigure iso230_2_line(const Iso230Figures& g, const MeasurementSet& set, const IdentifyReportInputs& in) {
  const std::pair<char, double> kinds[] = {{'A', g.accuracy_A_um},
                                           {'B', g.reversal_B_um},
                                           {'E', g.systematic_E_um},
                                           {'M', g.mean_bidirectional_M_um},
                                           {'R', g.repeatability_R_um}};
  SummaryFigure f{fmt::format("{}: ISO 230-2 of {}", report::base_name(g.file), g.axis), "", "", ""};
  std::optional<Verdict> worst;
  std::string lacks;  // the sources missing from any kind's budget, said once for the row
  for (const auto& [kind, value] : kinds) {
    const UncertaintyBudget b = iso230_2_budget(set, g, kind);
    f.value += fmt::format("{}{} {:.2f} ± {:.2f}", f.value.empty() ? "" : "; ", kind, value, b.expanded_um());
    if (!b.complete() && lacks.find(b.missing()) == std::string::npos)
      lacks += (lacks.empty() ? "" : ", ") + b.missing();
    const auto tol = tolerance_for(in, std::string(1, kind));
    if (!tol) continue;
    const Verdict v = decide(value, b.expanded_um(), *tol);
    f.against += fmt::format("{}{} ≤ {:g}", f.against.empty() ? "" : ", ", kind, *tol);
    if (!worst || v == Verdict::fail || (v == Verdict::not_proven && *worst == Verdict::pass)) worst = v;
  }
  f.value += " µm" + (lacks.empty() ? std::string() : " (U lacks " + lacks + ")");
  if (worst) f.verdict = to_string(*worst), f.against += " µm";
  return f;
}

}  // namespace

IdentificationSummary identification_summary(const Machine& m, const std::vector<MeasurementSet>& sets,
                                             const IdentifyResult& r, const IdentifyReportInputs& in,
                                             const std::string& report_path) {
  IdentificationSummary s = common(m, sets, in, "Identification of " + m.name, report_path);
  s.facts.push_back(residual_fact(r.rms_nominal_um, r.max_nominal_um, r.rms_after_um, r.max_after_um));
  for (std::size_t i = 0; i < r.files.size() && i < sets.size(); ++i) {
    const UncertaintyBudget b = reading_budget(sets[i]);
    const std::string name = report::base_name(r.files[i].file);
    s.figures.push_back(judged(name + ": largest deviation, machine as it is", r.files[i].max_nominal_um, b,
                               in.pass_tolerance_um, "deviation"));
    s.figures.push_back(judged(name + ": largest residual with the model", r.files[i].max_after_um, b,
                               in.pass_tolerance_um, "deviation"));
  }
  for (std::size_t i = 0; i < sets.size(); ++i)
    if (sets[i].type == MeasurementType::ballbar) add_ballbar_figures(s, m, sets, i, in);
  const std::size_t shown = std::min(r.parameters.size(), kParametersShown);
  for (std::size_t i = 0; i < shown; ++i) {
    const std::string& n = r.parameters.names()[i];
    const ReportValue v = report_value(m, n, r.parameters.values()[i]);
    const auto u = r.uncertainty.get(n);
    s.figures.push_back({"parameter " + n,
                         u ? fmt::format("{:.3f} ± {:.3f} {}", v.value, 2.0 * report_value(m, n, *u).value, v.unit)
                           : fmt::format("{:.3f} {} (given, not fitted)", v.value, v.unit),
                         "", ""});
  }
  if (shown < r.parameters.size())
    s.warnings.push_back(fmt::format("{} more parameters in the full report", r.parameters.size() - shown));
  for (const std::string& c : r.identifiability.combinations) s.warnings.push_back(c);
  return s;
}

IdentificationSummary laser_identification_summary(const Machine& m, const std::vector<MeasurementSet>& sets,
                                                   const LaserIdentifyResult& r, const IdentifyReportInputs& in,
                                                   const std::string& report_path) {
  IdentificationSummary s = common(m, sets, in, "Laser identification of " + m.name, report_path);
  s.facts.push_back(residual_fact(r.rms_nominal_um, r.max_nominal_um, r.rms_after_um, r.max_after_um));
  for (const Iso230Figures& g : r.iso230)
    for (const MeasurementSet& set : sets)
      if (set.file == g.file) s.figures.push_back(iso230_2_line(g, set, in));
  for (std::size_t i = 0; i < r.squareness.size(); ++i)
    s.figures.push_back(
        {"squareness " + r.squareness.names()[i], fmt::format("{:.2f} µrad", r.squareness.values()[i] * 1e6), "", ""});
  for (const std::string& u : r.unseen) s.warnings.push_back("not seen by these lines: " + u);
  return s;
}

}  // namespace ncpost::comp
