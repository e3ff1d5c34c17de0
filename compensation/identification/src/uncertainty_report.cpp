// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/uncertainty_report.hpp"

#include <fmt/format.h>

#include "ncpost/report/html_page.hpp"

namespace ncpost::comp {

using report::escape;

std::string value_with_U(double value_um, const UncertaintyBudget& b) {
  if (!(b.expanded_um() > 0.0))
    return fmt::format("{:.2f} (U unknown: {} not given)", value_um, b.complete() ? "nothing" : b.missing());
  std::string s = fmt::format("{:.2f} ± {:.2f}", value_um, b.expanded_um());
  if (!b.complete()) s += " (U lacks " + b.missing() + ")";
  return s;
}

std::string verdict_cell(double value_um, const UncertaintyBudget& b, std::optional<double> tolerance_um) {
  if (!tolerance_um) return "";
  const Verdict v = decide(value_um, b.expanded_um(), *tolerance_um);
  return fmt::format("<td class=\"{}\">{}</td>", css_class(v), to_string(v));
}

std::string budget_table_html(const std::string& figure, const UncertaintyBudget& b) {
  std::string h = fmt::format(
      "<table><tr><th class=n colspan=\"3\">uncertainty budget of {} (ISO 230-9)</th></tr>"
      "<tr><th class=n>source</th><th>u µm</th><th class=n>from</th></tr>",
      escape(figure));
  for (const BudgetLine& l : b.lines)
    h += fmt::format("<tr><td class=n>{}</td><td>{}</td><td class=n>{}</td></tr>", escape(l.source),
                     l.given ? fmt::format("{:.3f}", l.u_um) : std::string("—"), escape(l.note));
  h += fmt::format(
      "<tr><td class=n>combined u<sub>c</sub></td><td>{:.3f}</td><td class=n>√Σu²</td></tr>"
      "<tr><th class=n>expanded U (k = 2)</th><th>{:.3f}</th><th class=n>{}</th></tr></table>",
      b.combined_um(), b.expanded_um(),
      b.complete() ? std::string("complete") : escape("incomplete: " + b.missing() + " not given"));
  return h;
}

std::string decision_rule_note_html() {
  return "<p class=\"note\">Verdicts by the ISO 14253-1 decision rule: <b>PASS</b> only when the figure plus its "
         "expanded uncertainty U (k = 2) is within the tolerance, <b>FAIL</b> when the figure minus U is beyond it, "
         "<b>NOT PROVEN</b> between. A budget that lacks a contribution says so; its U is then a lower bound.</p>";
}

}  // namespace ncpost::comp
