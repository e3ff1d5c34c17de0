// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/laser_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include "ncpost/compensation/conditions_report.hpp"
#include "ncpost/compensation/laser_iso230_targets.hpp"
#include "ncpost/compensation/uncertainty_report.hpp"
#include "ncpost/report/html_page.hpp"
#include "ncpost/report/xy_chart.hpp"
#include "report_text.hpp"

namespace ncpost::comp {
namespace {

using report::escape;

double shown(const LaserFunction& f, double v) { return f.is_angle() ? v * 1e6 : v * 1e3; }
const char* unit(const LaserFunction& f) { return f.is_angle() ? "µrad" : "µm"; }

/// The identified table (and its polynomial) in µm / µrad, with tick values.
std::string svg_plot(const LaserFunction& f) {
  report::XySeries table{"table", "#1f5fbf", f.nodes_mm, {}, {}, {}, false, true};
  for (double v : f.values) table.y.push_back(shown(f, v));
  report::XySeries poly{"p1..p3", "#e09020", {}, {}, {}, {}, true, false};
  const double x0 = f.nodes_mm.front(), x1 = f.nodes_mm.back();
  for (int k = 0; k <= 60; ++k) {
    const double x = x0 + (x1 - x0) * k / 60.0;
    poly.x.push_back(x);
    poly.y.push_back(shown(f, f.polynomial[0] * x + f.polynomial[1] * x * x + f.polynomial[2] * x * x * x));
  }
  std::vector<report::XySeries> series{table, poly};
  report::XySeries unseen{"not seen", "#d0402b", {}, {}, {}, {}, false, true};
  for (std::size_t i = 0; i < f.nodes_mm.size(); ++i)
    if (!f.seen[i]) unseen.x.push_back(f.nodes_mm[i]), unseen.y.push_back(shown(f, f.values[i]));
  if (!unseen.x.empty()) series.push_back(unseen);
  report::XyFrame fr;
  fr.title = fmt::format("{} ({} of {})", f.name(), f.kind(), f.axis);
  fr.x_label = fmt::format("{} (mm)", f.axis);
  fr.y_label = unit(f);
  fr.width = 420;
  fr.height = 240;
  return report::xy_chart(fr, series);
}

/// ISO 230-2 bidirectional plot of one positioning line: x̄↑ and x̄↓ with ± 2s, and B_i.
std::string iso230_plot(const Iso230Figures& g) {
  report::XySeries up{"x̄↑ ± 2s", "#1f5fbf", {}, {}, {}, {}, false, true};
  report::XySeries down{"x̄↓ ± 2s", "#d0402b", {}, {}, {}, {}, false, true};
  report::XySeries reversal{"reversal B_i", "#2a8a3a", {}, {}, {}, {}, true, true};
  for (const auto& t : g.targets) {
    up.x.push_back(t.target_mm), up.y.push_back(t.mean_up_um);
    up.lo.push_back(t.mean_up_um - 2 * t.s_up_um), up.hi.push_back(t.mean_up_um + 2 * t.s_up_um);
    down.x.push_back(t.target_mm), down.y.push_back(t.mean_down_um);
    down.lo.push_back(t.mean_down_um - 2 * t.s_down_um), down.hi.push_back(t.mean_down_um + 2 * t.s_down_um);
    reversal.x.push_back(t.target_mm), reversal.y.push_back(t.reversal_um());
  }
  report::XyFrame fr;
  fr.title =
      fmt::format("{}: axis {}, A {:.2f} R {:.2f} B {:.2f} E {:.2f} M {:.2f} µm", report::base_name(g.file), g.axis,
                  g.accuracy_A_um, g.repeatability_R_um, g.reversal_B_um, g.systematic_E_um, g.mean_bidirectional_M_um);
  fr.x_label = fmt::format("target position {} (mm)", g.axis);
  fr.y_label = "positional deviation (µm)";
  fr.width = 560;
  fr.height = 300;
  return report::xy_chart(fr, {up, down, reversal});
}

struct Figure {
  char kind;
  double (*value)(const Iso230Figures&);
};
constexpr Figure kFigures[] = {
    {'A', [](const Iso230Figures& g) { return g.accuracy_A_um; }},
    {'B', [](const Iso230Figures& g) { return g.reversal_B_um; }},
    {'E', [](const Iso230Figures& g) { return g.systematic_E_um; }},
    {'M', [](const Iso230Figures& g) { return g.mean_bidirectional_M_um; }},
    {'R', [](const Iso230Figures& g) { return g.repeatability_R_um; }},
};

/// ISO 230-2 figures of every positioning line with U (k = 2), the ISO 14253-1 verdict of each kind
/// that has a tolerance, and the budgets (uncertainty_budget.hpp).
std::string iso230_2_verdicts_html(const LaserIdentifyResult& r, const std::vector<MeasurementSet>& sets,
                                   const IdentifyReportInputs& in) {
  std::string h = decision_rule_note_html() + "<table><tr><th class=n>line</th><th>axis</th>";
  for (const Figure& f : kFigures) {
    const std::string kind(1, f.kind);
    h += fmt::format("<th>{} ± U µm</th>", kind);
    if (const auto t = tolerance_for(in, kind)) h += fmt::format("<th>{} ≤ {:g} µm</th>", kind, *t);
  }
  h += "</tr>";
  std::string budgets;
  for (const auto& g : r.iso230) {
    const MeasurementSet* set = nullptr;
    for (const auto& s : sets)
      if (s.file == g.file) set = &s;
    if (!set) continue;
    h += fmt::format("<tr><td class=n>{}</td><td>{}</td>", escape(report::base_name(g.file)), g.axis);
    budgets += fmt::format(
        "<table><tr><th class=n colspan=\"6\">uncertainty budget of {} (ISO 230-9), u µm</th></tr>"
        "<tr><th class=n>source</th>",
        escape(report::base_name(g.file)));
    std::vector<UncertaintyBudget> of_kind;
    for (const Figure& f : kFigures) {
      of_kind.push_back(iso230_2_budget(*set, g, f.kind));
      h += "<td>" + escape(value_with_U(f.value(g), of_kind.back())) + "</td>" +
           verdict_cell(f.value(g), of_kind.back(), tolerance_for(in, std::string(1, f.kind)));
      budgets += fmt::format("<th>{}</th>", f.kind);
    }
    h += "</tr>";
    budgets += "<th class=n>from (A; B, R where they differ)</th></tr>";
    for (std::size_t line = 0; line < of_kind[0].lines.size(); ++line) {
      budgets += "<tr><td class=n>" + escape(of_kind[0].lines[line].source) + "</td>";
      for (const auto& b : of_kind)
        budgets += line < b.lines.size() && b.lines[line].given ? fmt::format("<td>{:.3f}</td>", b.lines[line].u_um)
                                                                : "<td>—</td>";
      std::string notes = of_kind[0].lines[line].note;
      for (std::size_t k : {std::size_t{1}, std::size_t{4}})
        if (line < of_kind[k].lines.size() && of_kind[k].lines[line].note != notes)
          notes += fmt::format("; {}: {}", kFigures[k].kind, of_kind[k].lines[line].note);
      budgets += "<td class=n>" + escape(notes) + "</td></tr>";
    }
    budgets += "<tr><th class=n>U (k = 2)</th>";
    for (const auto& b : of_kind) budgets += fmt::format("<th>{:.3f}</th>", b.expanded_um());
    budgets += "<th class=n></th></tr></table>";
  }
  return h + "</table>" + budgets;
}

}  // namespace

std::string laser_text_report(const Machine& m, const LaserIdentifyResult& r) {
  std::string o = fmt::format("laser identification of {}: {} readings; {}\n", m.name, r.readings, r.message);
  if (!r.ok) return o;
  o += fmt::format(
      "residual: machine without errors {:.2f} µm rms / {:.2f} max; fitted {:.2f} / {:.2f}; "
      "model as written (ISO 230-1 reference) {:.2f} / {:.2f}\n",
      r.rms_nominal_um, r.max_nominal_um, r.rms_fit_um, r.max_fit_um, r.rms_after_um, r.max_after_um);
  o += "\nISO 230-2 per positioning line (µm): A accuracy, R repeatability, B reversal (mean), E systematic, M mean\n";
  for (const auto& g : r.iso230)
    o += fmt::format("  {:<12} {}  A {:7.2f}  R {:6.2f}  B {:6.2f} ({:+6.2f})  E {:7.2f}  M {:7.2f}\n",
                     g.file.substr(g.file.find_last_of('/') + 1), g.axis, g.accuracy_A_um, g.repeatability_R_um,
                     g.reversal_B_um, g.mean_reversal_um, g.systematic_E_um, g.mean_bidirectional_M_um);
  o += "\nerror functions (values at every target; ISO 230-1 reference; p1..p3 fitted through home; the curve between\n"
       "targets by leave-one-out cross-validation)\n";
  for (const auto& f : r.functions) {
    double lo = 0, hi = 0, sig = 0;
    for (std::size_t i = 0; i < f.values.size(); ++i) {
      lo = std::min(lo, shown(f, f.values[i]));
      hi = std::max(hi, shown(f, f.values[i]));
      sig = std::max(sig, shown(f, f.sigma[i]));
    }
    o += fmt::format(
        "  {} {:<18} {:>4}: {:8.2f} … {:8.2f} {} (±{:.2f}){}; p1..p3 {:.4g} {:.4g} {:.4g}, fit rms {:.2f}\n", f.name(),
        f.kind(), f.axis, lo, hi, unit(f), sig,
        f.fully_seen() ? "" : (f.partly_seen() ? " PARTLY UNSEEN" : " NOT SEEN"), f.polynomial[0], f.polynomial[1],
        f.polynomial[2], shown(f, f.polynomial_rms));
    if (f.component >= 'X' && f.component != f.axis)
      o += fmt::format(
          "      straightness {:.2f} µm about its least-squares line, slope {:.2f} µrad moved into squareness\n",
          f.iso_straightness_um, f.iso_slope * 1e6);
    o += f.curve.basis == LaserBasis::linear
             ? fmt::format("      between targets: linear (leave-one-out rms {:.2f} {})\n",
                           shown(f, f.curve.cv_linear_rms), unit(f))
             : fmt::format("      between targets: {} (leave-one-out rms {:.2f} {}; linear {:.2f}), {} nodes\n",
                           f.curve.label(), shown(f, f.curve.cv_rms), unit(f), shown(f, f.curve.cv_linear_rms),
                           f.curve.nodes_mm.size());
  }
  o += "\nsquareness (from the straightness slopes)\n";
  for (std::size_t i = 0; i < r.squareness.size(); ++i)
    o += fmt::format("  {} = {:.2f} µrad\n", r.squareness.names()[i], r.squareness.values()[i] * 1e6);
  for (std::size_t i = 0; i < r.reversal.size(); ++i)
    o += fmt::format("  {} = {:.2f} ± {:.2f} µm\n", r.reversal.names()[i], r.reversal.values()[i] * 1e3,
                     r.reversal_sigma.values()[i] * 1e3);
  if (r.unseen.empty()) {
    o += "\nevery error of the measured axes is seen by these lines\n";
  } else {
    o += "\nNOT SEEN by these lines (held at 0 in the model, no value invented):\n";
    for (const auto& u : r.unseen) o += "  " + u + "\n";
    for (const auto& c : r.combinations) o += "    " + c + "\n";
  }
  return o;
}

std::string laser_html_report(const Machine& m, const LaserIdentifyResult& r, const std::vector<MeasurementSet>& sets,
                              const IdentifyReportInputs& in) {
  report::Provenance p;
  p.title = "Laser identification of " + m.name;
  p.machine = m.name + (in.machine_file.empty() ? std::string() : " (" + in.machine_file + ")");
  p.model = "identified here" + (in.model_file.empty() ? std::string() : ", written to " + in.model_file);
  if (!in.machine_file.empty()) p.inputs.push_back({"machine file", in.machine_file});
  for (const auto& s : sets) p.inputs.push_back({"laser data", s.file});
  if (in.pass_tolerance_um)
    p.extra.push_back({"pass tolerance", fmt::format("{:g} µm (ISO 230-2 accuracy A)", *in.pass_tolerance_um)});
  for (const auto& [kind, t] : in.tolerances.by_kind_um)
    p.extra.push_back({"tolerance " + kind, fmt::format("{:g} µm", t)});
  add_condition_rows(p, in, sets);
  std::string h = report::page_start(p);
  if (!r.iso230.empty()) {
    h += "<h2 id=\"iso230-2\">ISO 230-2 bidirectional positioning</h2><p class=\"note\">Mean positional deviation at "
         "each target "
         "approached from below (x̄↑) and from above (x̄↓) with ± 2s over the runs, and the reversal value "
         "B_i = x̄↑ − x̄↓; A accuracy, R repeatability, B reversal, E systematic deviation, M mean bidirectional "
         "deviation (µm).</p>";
    h += "<div class=\"plots\">";
    for (const auto& g : r.iso230) h += "<div class=\"plot\">" + iso230_plot(g) + "</div>";
    h += "</div>";
    h += iso230_2_verdicts_html(r, sets, in);  // the figures ± U, verdicts and budgets below the plots
    h += "<h3>Per target</h3>";
    for (const auto& g : r.iso230) h += iso230_2_target_table_html(g);
  }
  h += conditions_html(sets);
  h += "<h2>Summary</h2><pre>" + escape(laser_text_report(m, r)) + "</pre>";
  h += "<h2>Compensation values for the control</h2>" +
       control_entries_html(m, r.parameters, in.control.value_or(default_control_format(m)));
  h += "<h2>Error functions</h2><p class=\"note\">Blue: identified table at every target (red: nodes the lines do not "
       "see), orange dashed: fitted polynomial p1..p3; µm for positioning and straightness, µrad for roll, pitch, "
       "yaw.</p>"
       "<div class=\"plots\">";
  for (const auto& f : r.functions) h += "<div class=\"plot\">" + svg_plot(f) + "</div>";
  return h + "</div>" + report::page_end();
}

}  // namespace ncpost::comp
