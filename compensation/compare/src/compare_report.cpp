// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/compare_report.hpp"

#include <fmt/format.h>

#include "ncpost/compensation/uncertainty_report.hpp"
#include "ncpost/report/html_page.hpp"
#include "ncpost/report/xy_chart.hpp"

namespace ncpost::comp {
namespace {

using report::escape;

std::string value_text(const FigureTrend& t, std::size_t k) {
  if (!t.value[k]) return "—";
  if (!(t.expanded[k] > 0)) return fmt::format("{:.3f} (no U)", *t.value[k]);
  return fmt::format("{:.3f} ± {:.3f}", *t.value[k], t.expanded[k]);
}

std::string session_label(const Comparison& c, std::size_t k) {
  const std::string name = report::base_name(c.sessions[k].file);
  return c.sessions[k].date.empty() ? name : name + " (" + c.sessions[k].date + ")";
}

std::string change_text(const FigureTrend& t) {
  if (t.first < 0 || t.first == t.last) return "";
  if (!(t.change_U > 0)) return fmt::format("{:+.3f}: {}", t.change, t.outcome);
  return fmt::format("{:+.3f} ± {:.3f}: {}", t.change, t.change_U, t.outcome);
}

/// One figure over the sessions: value ± U against the day (or the session number), the tolerance dashed.
std::string trend_plot(const Comparison& c, const FigureTrend& t) {
  report::XySeries s{t.name, "#1f5fbf", {}, {}, {}, {}, false, true};
  for (std::size_t k = 0; k < t.value.size(); ++k) {
    if (!t.value[k]) continue;
    s.x.push_back(c.day[k]);
    s.y.push_back(*t.value[k]);
    s.lo.push_back(*t.value[k] - t.expanded[k]);
    s.hi.push_back(*t.value[k] + t.expanded[k]);
  }
  std::vector<report::XySeries> series{s};
  if (t.tolerance && s.x.size() >= 2)
    series.push_back(
        {"tolerance", "#d0402b", {s.x.front(), s.x.back()}, {*t.tolerance, *t.tolerance}, {}, {}, true, false});
  report::XyFrame f;
  f.title = fmt::format("{} ({}) ± U, k = 2", t.name, t.unit);
  f.x_label = c.dated ? "days since the first session" : "session (undated)";
  f.y_label = t.unit;
  f.width = 420;
  f.height = 240;
  return report::xy_chart(f, series);
}

}  // namespace

std::string compare_text(const Comparison& c) {
  std::string o =
      fmt::format("comparison of {} sessions of one test: {}\n", c.sessions.size(), c.sessions.front().test);
  for (std::size_t k = 0; k < c.sessions.size(); ++k)
    o += fmt::format("  session {}: {}{}\n", k + 1, c.sessions[k].file,
                     c.sessions[k].date.empty() ? std::string(" (no date)") : ", " + c.sessions[k].date);
  o += "figure (unit): value ± U (k = 2) per session [verdict]; change first -> last ± U\n";
  for (const FigureTrend& t : c.figures) {
    o += fmt::format("  {} ({}):", t.name, t.unit);
    for (std::size_t k = 0; k < t.value.size(); ++k)
      o += " " + value_text(t, k) + (t.verdict[k] ? fmt::format(" [{}]", to_string(*t.verdict[k])) : std::string()) +
           ";";
    o += " " + change_text(t) + "\n";
  }
  return o;
}

std::string compare_html(const Comparison& c, const std::string& machine_name, const std::string& machine_file) {
  report::Provenance p;
  p.title = "Before and after: " + machine_name;
  p.machine = machine_name + " (" + machine_file + ")";
  p.model = "none applied: each session's figures as measured (or as identified, for a model)";
  p.inputs.push_back({"machine file", machine_file});
  for (std::size_t k = 0; k < c.sessions.size(); ++k)
    p.inputs.push_back({fmt::format("session {}", k + 1), c.sessions[k].file});
  p.extra.push_back({"test", escape(c.sessions.front().test)});
  std::string h = report::page_start(p) + decision_rule_note_html() +
                  "<p class=\"note\">The change from the first session to the last is proven when it exceeds its "
                  "expanded uncertainty U<sub>Δ</sub> = √(U<sub>first</sub>² + U<sub>last</sub>²); better means closer "
                  "to 0.</p><h2>Figures</h2><table><tr><th class=n>figure</th>";
  for (std::size_t k = 0; k < c.sessions.size(); ++k) h += "<th>" + escape(session_label(c, k)) + "</th>";
  h += "<th>tolerance</th><th class=n>change first → last</th></tr>";
  for (const FigureTrend& t : c.figures) {
    h += fmt::format("<tr><td class=n>{} ({})</td>", escape(t.name), escape(t.unit));
    for (std::size_t k = 0; k < t.value.size(); ++k)
      h += t.verdict[k] ? fmt::format("<td class=\"{}\">{} {}</td>", css_class(*t.verdict[k]), escape(value_text(t, k)),
                                      to_string(*t.verdict[k]))
                        : "<td>" + escape(value_text(t, k)) + "</td>";
    h += "<td>" + (t.tolerance ? fmt::format("{:g}", *t.tolerance) : std::string("—")) + "</td><td class=n>" +
         escape(change_text(t)) + "</td></tr>";
  }
  h += "</table><h2>Trend</h2>";
  if (!c.dated)
    h +=
        "<p class=\"note\">Not every session gives a <code># date:</code>: the trend runs over the session number.</p>";
  h += "<div class=\"plots\">";
  for (const FigureTrend& t : c.figures) h += "<div class=\"plot\">" + trend_plot(c, t) + "</div>";
  return h + "</div>" + report::page_end();
}

}  // namespace ncpost::comp
