// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/identify_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ncpost/compensation/conditions_report.hpp"
#include "ncpost/compensation/parameter_name.hpp"
#include "ncpost/compensation/uncertainty_report.hpp"
#include "identify_report_sections.hpp"
#include "ncpost/report/html_page.hpp"
#include "report_text.hpp"

namespace ncpost::comp {
namespace {

using report::base_name;
using report::escape;

/// Two ballbar files are runs of one test when their set-up and commanded rows are the same.
bool same_test(const MeasurementSet& a, const MeasurementSet& b) {
  if (a.type != MeasurementType::ballbar || b.type != MeasurementType::ballbar || a.rows.size() != b.rows.size() ||
      a.bar_length_mm != b.bar_length_mm || a.table_ball_mm != b.table_ball_mm || a.tool_ball_mm != b.tool_ball_mm)
    return false;
  for (std::size_t k = 0; k < a.rows.size(); ++k)
    if (!(a.rows[k].command == b.rows[k].command)) return false;
  return true;
}

/// G of every file of the same test as sets[s] (itself included) when it was run more than once.
std::vector<double> repeated_G_um(const Machine& m, const std::vector<MeasurementSet>& sets, std::size_t s) {
  std::vector<double> out;
  for (const auto& other : sets)
    if (same_test(sets[s], other)) {
      const auto f = sections::ballbar_figures(m, other).both;
      if (f.ok) out.push_back(f.G_um);
    }
  if (out.size() < 2) out.clear();
  return out;
}

}  // namespace

std::optional<double> tolerance_for(const IdentifyReportInputs& in, const std::string& kind) {
  if (const auto t = in.tolerances.of(kind)) return t;
  if (kind == "G" || kind == "A") return in.pass_tolerance_um;
  return std::nullopt;
}

ReportValue report_value(const Machine& m, const std::string& name, double v) {
  const ParseResult p = parse_parameter_name(name, m);
  if (!p.spec) return {v, ""};
  const ParameterSpec& s = *p.spec;
  if (s.kind == ParameterKind::reversal)
    return m.axes[static_cast<std::size_t>(s.axis_index)].is_rotary() ? ReportValue{v * 1e6, "µrad"}
                                                                      : ReportValue{v * 1e3, "µm"};
  if (s.kind == ParameterKind::drift) {
    switch (s.drift) {
      case DriftBasis::linear:
        return {v * 1e3 * 3600.0, "µm/h"};
      case DriftBasis::quadratic:
        return {v * 1e3 * 3600.0 * 3600.0, "µm/h²"};
      case DriftBasis::exponential:
        return {v * 1e3, "µm"};
      case DriftBasis::time_constant:
        return {v, "s"};
    }
  }
  if (s.kind == ParameterKind::polynomial) {
    const std::string per = s.order == 1 ? "/mm" : fmt::format("/mm^{}", s.order);
    return s.component >= 3 ? ReportValue{v * 1e6, "µrad" + per} : ReportValue{v * 1e3, "µm" + per};
  }
  return s.is_angle() ? ReportValue{v * 1e6, "µrad"} : ReportValue{v * 1e3, "µm"};
}

std::string text_report(const Machine& m, const std::vector<MeasurementSet>& sets, const IdentifyResult& r) {
  std::string o = fmt::format(
      "identification of {} from {} file(s), {} values: {}\n", m.name, sets.size(),
      [&] {
        std::size_t n = 0;
        for (const auto& f : r.files) n += f.values;
        return n;
      }(),
      r.message);
  o += "parameters (value ± standard uncertainty):\n";
  for (std::size_t i = 0; i < r.parameters.size(); ++i) {
    const std::string& n = r.parameters.names()[i];
    const ReportValue v = report_value(m, n, r.parameters.values()[i]);
    const auto u = r.uncertainty.get(n);
    if (u)
      o += fmt::format("  {:<14} {:>11.3f} ± {:<8.3f} {}\n", n, v.value, report_value(m, n, *u).value, v.unit);
    else
      o += fmt::format("  {:<14} {:>11.3f}   (given) {}\n", n, v.value, v.unit);
  }
  const Identifiability& id = r.identifiability;
  o += fmt::format("identifiability: rank {} of {} parameters\n", id.rank, id.parameters);
  for (const auto& c : id.combinations) o += "  not separable: " + c + "\n";
  o += "residual (µm):            nominal rms / max      identified rms / max\n";
  for (const auto& f : r.files)
    o += fmt::format("  {:<24} {:>8.2f} / {:<8.2f}      {:>8.3f} / {:<8.3f}\n", base_name(f.file), f.rms_nominal_um,
                     f.max_nominal_um, f.rms_after_um, f.max_after_um);
  o += fmt::format("  {:<24} {:>8.2f} / {:<8.2f}      {:>8.3f} / {:<8.3f}\n", "all", r.rms_nominal_um, r.max_nominal_um,
                   r.rms_after_um, r.max_after_um);
  return o;
}

std::string html_report(const Machine& m, const std::vector<MeasurementSet>& sets, const IdentifyResult& r,
                        const IdentifyReportInputs& in) {
  report::Provenance p;
  p.title = "Identification of " + m.name;
  p.machine = m.name + (in.machine_file.empty() ? std::string() : " (" + in.machine_file + ")");
  p.model = "identified here" + (in.model_file.empty() ? std::string() : ", written to " + in.model_file);
  if (!in.machine_file.empty()) p.inputs.push_back({"machine file", in.machine_file});
  for (const auto& s : sets) p.inputs.push_back({std::string(to_string(s.type)) + " data", s.file});
  if (in.pass_tolerance_um) p.extra.push_back({"pass tolerance", fmt::format("{:g} µm", *in.pass_tolerance_um)});
  for (const auto& [kind, t] : in.tolerances.by_kind_um)
    p.extra.push_back({"tolerance " + kind, fmt::format("{:g} µm", t)});
  add_condition_rows(p, in, sets);
  std::string h = report::page_start(p);
  h += "<p>" + escape(r.message) + "</p>";
  h += conditions_html(sets);
  h += sections::verdict_section(r, sets, in.pass_tolerance_um);
  h += sections::control_values_section(m, r, in.control.value_or(default_control_format(m)));
  h += "<h2>Parameters</h2><p class=\"note\">u: the fit's standard uncertainty (s² (JᵀJ)⁻¹; it holds the random part "
       "of the instrument and the repeatability as far as the residual shows them); U = 2u (k = 2). A systematic error "
       "of the instrument or of the temperature correction is not propagated into the parameters: see the figures' "
       "budgets.</p><table><tr><th class=n>name</th><th>value</th><th>u (1σ)</th><th>U (k = 2)</th><th "
       "class=n>unit</th></tr>";
  for (std::size_t i = 0; i < r.parameters.size(); ++i) {
    const std::string& n = r.parameters.names()[i];
    const ReportValue v = report_value(m, n, r.parameters.values()[i]);
    const auto u = r.uncertainty.get(n);
    const double u_shown = u ? report_value(m, n, *u).value : 0.0;
    h += fmt::format("<tr><td class=n>{}</td><td>{:.3f}</td><td>{}</td><td>{}</td><td class=n>{}</td></tr>", escape(n),
                     v.value, u ? fmt::format("{:.3f}", u_shown) : "given",
                     u ? fmt::format("{:.3f}", 2.0 * u_shown) : "—", escape(v.unit));
  }
  h += "</table>";
  const Identifiability& id = r.identifiability;
  h += fmt::format("<h2>Identifiability</h2><p>Rank {} of {} parameters (column-scaled Jacobian).</p>", id.rank,
                   id.parameters);
  if (!id.combinations.empty()) {
    h += "<p>Not separable by these data (held at their prior value, not fitted):</p><ul>";
    for (const auto& c : id.combinations) h += "<li>" + escape(c) + "</li>";
    h += "</ul>";
  }
  h += "<p>Singular values:";
  for (Eigen::Index i = 0; i < r.rank.singular_values.size(); ++i)
    h += fmt::format(" {:.3g}", r.rank.singular_values[i]);
  h += "</p><h2>Residual</h2><table><tr><th class=n>file</th><th>values</th><th>nominal rms µm</th><th>nominal max "
       "µm</th><th>identified rms µm</th><th>identified max µm</th></tr>";
  for (const auto& f : r.files)
    h += fmt::format(
        "<tr><td class=n>{}</td><td>{}</td><td>{:.2f}</td><td>{:.2f}</td><td>{:.3f}</td><td>{:.3f}</td></tr>",
        escape(base_name(f.file)), f.values, f.rms_nominal_um, f.max_nominal_um, f.rms_after_um, f.max_after_um);
  h += "</table>";
  std::string ballbar, sphere;
  for (std::size_t s = 0; s < sets.size() && s < r.fitted.size() && s < r.nominal.size(); ++s) {
    if (sets[s].type == MeasurementType::ballbar)
      ballbar += sections::ballbar_section(m, sets[s], r.fitted[s], r.nominal[s], tolerance_for(in, "G"),
                                           repeated_G_um(m, sets, s), sections::opposite_run(m, sets, s));
    else if (sets[s].type == MeasurementType::sphere)
      sphere += sections::sphere_section(m, sets[s], r.fitted[s], r.nominal[s]);
  }
  if (!ballbar.empty())
    h +=
        "<h2 id=\"ballbar\">Ballbar tests</h2><p class=\"note\">ΔL = L − bar length (µm) against the angle of the axis "
        "that turns most "
        "(0° to the right, counter-clockwise positive), about a base circle; rings in µm. Left: measured, predicted by "
        "the identified model and by the nominal model; right: what the identified model leaves, on its own scale. "
        "ISO 230-4 figures from ΔL as the radial deviation.</p>" +
        (tolerance_for(in, "G") ? decision_rule_note_html() : std::string()) + ballbar;
  if (!sphere.empty()) h += "<h2>Sphere probing</h2>" + sphere;
  return h + report::page_end();
}

}  // namespace ncpost::comp
