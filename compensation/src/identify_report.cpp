// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/identify_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ncpost/compensation/parameter_name.hpp"
#include "report_text.hpp"

namespace ncpost::comp {
namespace {

using report::base_name;
using report::escape;

/// Polar plot angle of each row: the rotary axis that turns most (e.g. C, 0..360°).
std::vector<double> polar_angles(const MeasurementSet& s) {
  int axis = 3;
  double best = -1.0;
  for (int a = 3; a < 5; ++a) {
    double lo = 1e9, hi = -1e9;
    for (const auto& r : s.rows) {
      lo = std::min(lo, r.command[a]);
      hi = std::max(hi, r.command[a]);
    }
    if (hi - lo > best) {
      best = hi - lo;
      axis = a;
    }
  }
  std::vector<double> out;
  for (const auto& r : s.rows) out.push_back(r.command[axis]);
  return out;
}

std::string polar_svg(const MeasurementSet& s, const std::vector<double>& fitted, const std::vector<double>& nominal) {
  const std::vector<double> ang = polar_angles(s);
  std::vector<double> meas, fit, nom;
  for (std::size_t k = 0; k < s.rows.size(); ++k) {
    meas.push_back(1e3 * (s.rows[k].value[0] - s.bar_length_mm));
    fit.push_back(1e3 * (fitted[k] - s.bar_length_mm));
    nom.push_back(1e3 * (nominal[k] - s.bar_length_mm));
  }
  double span = 1.0;
  for (double v : meas) span = std::max(span, std::abs(v));
  span = std::ceil(span / 5.0) * 5.0;
  const double c = 170.0, r0 = 90.0, gain = 70.0 / span;  // ΔL = ±span maps to r0 ± 70 px
  auto path = [&](const std::vector<double>& v, const char* colour, double width) {
    std::string d;
    for (std::size_t k = 0; k < v.size(); ++k) {
      const double r = r0 + gain * v[k];
      d += fmt::format("{}{:.2f},{:.2f} ", k == 0 ? "M" : "L", c + r * std::cos(ang[k]), c - r * std::sin(ang[k]));
    }
    return fmt::format(R"(<path d="{}" fill="none" stroke="{}" stroke-width="{}"/>)", d, colour, width);
  };
  std::string svg = R"(<svg xmlns="http://www.w3.org/2000/svg" width="340" height="360" viewBox="0 0 340 360">)";
  for (double g : {-span, -span / 2, 0.0, span / 2, span})
    svg += fmt::format(R"(<circle cx="{}" cy="{}" r="{:.1f}" fill="none" stroke="#ccc" stroke-width="{}"/>)", c, c,
                       r0 + gain * g, g == 0.0 ? 1.5 : 0.7);
  svg += fmt::format(R"(<text x="{}" y="{}" font-size="10" fill="#888">{:+g} µm</text>)", c + 3, c - r0 - 70 - 2, span);
  svg += fmt::format(R"(<text x="{}" y="{}" font-size="10" fill="#888">0</text>)", c + 3, c - r0 - 2);
  svg += path(nom, "#bbb", 1.0) + path(meas, "#1f5fbf", 1.2) + path(fit, "#d0402b", 1.2);
  svg += R"(<text x="10" y="352" font-size="11"><tspan fill="#1f5fbf">measured</tspan>  <tspan fill="#d0402b">fitted</tspan>  <tspan fill="#999">nominal model</tspan></text>)";
  return svg + "</svg>";
}

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

std::string html_report(const Machine& m, const std::vector<MeasurementSet>& sets, const IdentifyResult& r) {
  std::string h = R"(<!DOCTYPE html><html><head><meta charset="utf-8"><title>ncpost identify</title><style>
body{font-family:sans-serif;margin:2em;color:#222}table{border-collapse:collapse}td,th{padding:2px 10px;border-bottom:1px solid #ddd;text-align:right}
th{background:#f3f3f3}td.n,th.n{text-align:left}.plots{display:flex;flex-wrap:wrap;gap:1em}.plot{border:1px solid #eee;padding:.5em}
</style></head><body>)";
  h += fmt::format("<h1>Identification of {}</h1><p>{}</p>", escape(m.name), escape(r.message));
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
  h += "</table><h2>Ballbar trajectories</h2><p>ΔL = L − bar length against the rotary angle (polar).</p><div class=plots>";
  for (std::size_t s = 0; s < sets.size(); ++s) {
    if (sets[s].type != MeasurementType::ballbar || sets[s].rows.size() < 8) continue;
    h += fmt::format("<div class=plot><div>{}</div>{}</div>", escape(base_name(sets[s].file)), polar_svg(sets[s], r.fitted[s], r.nominal[s]));
  }
  return h + "</div></body></html>\n";
}

}  // namespace ncpost::comp
