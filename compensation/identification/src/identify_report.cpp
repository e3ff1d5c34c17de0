// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/identify_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ncpost/compensation/parameter_name.hpp"
#include "identify_report_sections.hpp"
#include "ncpost/report/html_page.hpp"
#include "report_text.hpp"

namespace ncpost::comp {
namespace {

using report::base_name;
using report::escape;

}  // namespace

ReportValue report_value(const Machine& m, const std::string& name, double v) {
  const ParseResult p = parse_parameter_name(name, m);
  if (!p.spec) return {v, ""};
  const ParameterSpec& s = *p.spec;
  if (s.kind == ParameterKind::reversal)
    return m.axes[static_cast<std::size_t>(s.axis_index)].is_rotary() ? ReportValue{v * 1e6, "µrad"} : ReportValue{v * 1e3, "µm"};
  if (s.kind == ParameterKind::drift) {
    switch (s.drift) {
      case DriftBasis::linear: return {v * 1e3 * 3600.0, "µm/h"};
      case DriftBasis::quadratic: return {v * 1e3 * 3600.0 * 3600.0, "µm/h²"};
      case DriftBasis::exponential: return {v * 1e3, "µm"};
      case DriftBasis::time_constant: return {v, "s"};
    }
  }
  if (s.kind == ParameterKind::polynomial) {
    const std::string per = s.order == 1 ? "/mm" : fmt::format("/mm^{}", s.order);
    return s.component >= 3 ? ReportValue{v * 1e6, "µrad" + per} : ReportValue{v * 1e3, "µm" + per};
  }
  return s.is_angle() ? ReportValue{v * 1e6, "µrad"} : ReportValue{v * 1e3, "µm"};
}

std::string text_report(const Machine& m, const std::vector<MeasurementSet>& sets, const IdentifyResult& r) {
  std::string o = fmt::format("identification of {} from {} file(s), {} values: {}\n", m.name, sets.size(),
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
    o += fmt::format("  {:<24} {:>8.2f} / {:<8.2f}      {:>8.3f} / {:<8.3f}\n", base_name(f.file), f.rms_nominal_um, f.max_nominal_um,
                     f.rms_after_um, f.max_after_um);
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
  std::string h = report::page_start(p);
  h += "<p>" + escape(r.message) + "</p>";
  h += sections::verdict_section(r, in.pass_tolerance_um);
  h += sections::control_values_section(m, r, in.control.value_or(default_control_format(m)));
  h += "<h2>Parameters</h2><table><tr><th class=n>name</th><th>value</th><th>± uncertainty</th><th class=n>unit</th></tr>";
  for (std::size_t i = 0; i < r.parameters.size(); ++i) {
    const std::string& n = r.parameters.names()[i];
    const ReportValue v = report_value(m, n, r.parameters.values()[i]);
    const auto u = r.uncertainty.get(n);
    h += fmt::format("<tr><td class=n>{}</td><td>{:.3f}</td><td>{}</td><td class=n>{}</td></tr>", escape(n), v.value,
                     u ? fmt::format("{:.3f}", report_value(m, n, *u).value) : "given", escape(v.unit));
  }
  h += "</table>";
  const Identifiability& id = r.identifiability;
  h += fmt::format("<h2>Identifiability</h2><p>Rank {} of {} parameters (column-scaled Jacobian).</p>", id.rank, id.parameters);
  if (!id.combinations.empty()) {
    h += "<p>Not separable by these data (held at their prior value, not fitted):</p><ul>";
    for (const auto& c : id.combinations) h += "<li>" + escape(c) + "</li>";
    h += "</ul>";
  }
  h += "<p>Singular values:";
  for (Eigen::Index i = 0; i < r.rank.singular_values.size(); ++i) h += fmt::format(" {:.3g}", r.rank.singular_values[i]);
  h += "</p><h2>Residual</h2><table><tr><th class=n>file</th><th>values</th><th>nominal rms µm</th><th>nominal max µm</th><th>identified rms µm</th><th>identified max µm</th></tr>";
  for (const auto& f : r.files)
    h += fmt::format("<tr><td class=n>{}</td><td>{}</td><td>{:.2f}</td><td>{:.2f}</td><td>{:.3f}</td><td>{:.3f}</td></tr>",
                     escape(base_name(f.file)), f.values, f.rms_nominal_um, f.max_nominal_um, f.rms_after_um, f.max_after_um);
  h += "</table>";
  std::string ballbar, sphere;
  for (std::size_t s = 0; s < sets.size() && s < r.fitted.size() && s < r.nominal.size(); ++s) {
    if (sets[s].type == MeasurementType::ballbar)
      ballbar += sections::ballbar_section(m, sets[s], r.fitted[s], r.nominal[s], in.pass_tolerance_um);
    else if (sets[s].type == MeasurementType::sphere)
      sphere += sections::sphere_section(m, sets[s], r.fitted[s], r.nominal[s]);
  }
  if (!ballbar.empty())
    h += "<h2 id=\"ballbar\">Ballbar tests</h2><p class=\"note\">ΔL = L − bar length (µm) against the angle of the axis that turns most "
         "(0° to the right, counter-clockwise positive), about a base circle; rings in µm. Left: measured, predicted by "
         "the identified model and by the nominal model; right: what the identified model leaves, on its own scale. "
         "ISO 230-4 figures from ΔL as the radial deviation.</p>" + ballbar;
  if (!sphere.empty()) h += "<h2>Sphere probing</h2>" + sphere;
  return h + report::page_end();
}

}  // namespace ncpost::comp
