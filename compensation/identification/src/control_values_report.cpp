// SPDX-License-Identifier: Apache-2.0
// The verdict against the user's tolerance and the compensation values as they go into the
// control, sections of the identification report.
#include <fmt/format.h>

#include "identify_report_sections.hpp"
#include "ncpost/compensation/uncertainty_report.hpp"
#include "ncpost/compensation/identify_report.hpp"
#include "ncpost/compensation/parameter_name.hpp"
#include "ncpost/report/html_page.hpp"

namespace ncpost::comp::sections {
namespace {

using report::escape;

/// What a parameter is, in words, for the control table; empty for measuring-only effects.
std::string meaning(const Machine& m, const ParameterSpec& s) {
  const char* comp[6] = {"offset X", "offset Y", "offset Z", "tilt about X", "tilt about Y", "tilt about Z"};
  const auto axis = [&] {
    return s.axis_index >= 0 && s.axis_index < static_cast<int>(m.axes.size())
               ? std::string(1, m.axes[static_cast<std::size_t>(s.axis_index)].letter)
               : std::string("?");
  };
  const std::string c = s.component >= 0 && s.component < 6 ? comp[s.component] : "component";
  switch (s.kind) {
    case ParameterKind::location:
      return "axis " + axis() + " location: " + c;
    case ParameterKind::squareness:
      return "axis " + axis() + " squareness: " + c;
    case ParameterKind::harmonic:
      return fmt::format("axis {} error motion, {} order {} ({})", axis(), c, s.order, s.sine ? "sin" : "cos");
    case ParameterKind::polynomial:
      return fmt::format("axis {} error motion, {} degree {}", axis(), c, s.order);
    case ParameterKind::table:
      return fmt::format("axis {} error motion, {} at {:g} mm", axis(), c, s.at_mm);
    case ParameterKind::reversal:
      return "axis " + axis() + " reversal (backlash)";
    case ParameterKind::coupled:
      return fmt::format("axis {} location: {}, per {} of {}", axis(), c, s.order == 1 ? "rad" : "rad²",
                         m.axes[static_cast<std::size_t>(s.coupled_axis_index)].letter);
    default:
      return "";
  }
}

}  // namespace

std::string control_values_section(const Machine& m, const IdentifyResult& r, ControlFormat format) {
  std::string h =
      "<h2>Compensation values for the control</h2><p class=\"note\">The identified errors of the machine "
      "(ISO 230-1 location errors and the effects added), in µm and µrad, as they are entered in the "
      "control's kinematic description or compensation tables, and as <code>ncpost post --model</code> "
      "compensates them: the value is the error of the real machine against its nominal description "
      "(docs/conventions.md); below the table, the same model in the control's own entries, with its sign "
      "convention. Drift and instrument effects are measuring conditions and are not entered.</p>"
      "<table><tr><th class=n>parameter</th><th class=n>meaning</th><th>value</th><th>± u (1σ)</th>"
      "<th class=n>unit</th></tr>";
  for (std::size_t i = 0; i < r.parameters.size(); ++i) {
    const std::string& n = r.parameters.names()[i];
    const ParseResult p = parse_parameter_name(n, m);
    if (!p.spec) continue;
    const std::string what = meaning(m, *p.spec);
    if (what.empty()) continue;
    const ReportValue v = report_value(m, n, r.parameters.values()[i]);
    const auto u = r.uncertainty.get(n);
    h += fmt::format("<tr><td class=n>{}</td><td class=n>{}</td><td>{:+.2f}</td><td>{}</td><td class=n>{}</td></tr>",
                     escape(n), escape(what), v.value,
                     u ? fmt::format("{:.2f}", report_value(m, n, *u).value) : "given", escape(v.unit));
  }
  return h + "</table>" + control_entries_html(m, r.parameters, format);
}

std::string verdict_section(const IdentifyResult& r, const std::vector<MeasurementSet>& sets,
                            std::optional<double> tol) {
  if (!tol)
    return "<p class=\"note\">No tolerance given (<code>identify --pass-tolerance-um</code>): no pass/fail "
           "verdict.</p>";
  Verdict machine = Verdict::pass, model = Verdict::pass;
  auto worst = [](Verdict a, Verdict b) {
    if (a == Verdict::fail || b == Verdict::fail) return Verdict::fail;
    return a == Verdict::not_proven || b == Verdict::not_proven ? Verdict::not_proven : Verdict::pass;
  };
  std::string rows;
  for (std::size_t i = 0; i < r.files.size(); ++i) {
    const FileResidual& f = r.files[i];
    const UncertaintyBudget b = i < sets.size() ? reading_budget(sets[i]) : UncertaintyBudget{};
    const Verdict before = decide(f.max_nominal_um, b.expanded_um(), *tol);
    const Verdict after = decide(f.max_after_um, b.expanded_um(), *tol);
    machine = worst(machine, before);
    model = worst(model, after);
    rows += fmt::format(
        "<tr><td class=n>{}</td><td>{}</td><td class=\"{}\">{}</td><td>{}</td><td class=\"{}\">{}</td></tr>",
        escape(report::base_name(f.file)), escape(value_with_U(f.max_nominal_um, b)), css_class(before),
        to_string(before), escape(value_with_U(f.max_after_um, b)), css_class(after), to_string(after));
  }
  std::string h = fmt::format(
      "<h2>Verdict against {:g} µm</h2><p>Machine as it is (largest deviation from the nominal machine): <span "
      "class=\"{}\">{}</span>; "
      "with the identified compensation (largest residual the model leaves): <span class=\"{}\">{}</span>.</p>",
      *tol, css_class(machine), to_string(machine), css_class(model), to_string(model));
  h += decision_rule_note_html();
  h += "<table><tr><th class=n>file</th><th>uncompensated max ± U µm</th><th>verdict</th><th>after identification max "
       "± U µm</th>"
       "<th>verdict</th></tr>" +
       rows + "</table>";
  return h;
}

}  // namespace ncpost::comp::sections
