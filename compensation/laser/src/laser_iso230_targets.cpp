// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/laser_iso230_targets.hpp"

#include <fmt/format.h>

#include "ncpost/report/html_page.hpp"

namespace ncpost::comp {

std::vector<Iso230TargetRow> iso230_2_target_rows(const Iso230Figures& g) {
  std::vector<Iso230TargetRow> rows;
  for (const Iso230Target& t : g.targets) {
    Iso230TargetRow r;
    r.target_mm = t.target_mm;
    r.runs_up = t.runs_up;
    r.runs_down = t.runs_down;
    r.mean_up_um = t.mean_up_um;
    r.mean_down_um = t.mean_down_um;
    r.two_s_up_um = 2.0 * t.s_up_um;
    r.two_s_down_um = 2.0 * t.s_down_um;
    r.reversal_um = t.reversal_um();
    r.mean_bidirectional_um = t.mean_bidirectional_um();
    r.repeat_up_um = 4.0 * t.s_up_um;
    r.repeat_down_um = 4.0 * t.s_down_um;
    r.repeat_um = t.repeatability_um();
    rows.push_back(r);
  }
  return rows;
}

std::string iso230_2_target_table_html(const Iso230Figures& g) {
  std::string h = fmt::format(
      "<table class=\"targets\"><tr><th class=n colspan=\"12\">{}: axis {}, ISO 230-2 per target (µm)</th></tr>"
      "<tr><th>target mm</th><th>runs ↑/↓</th><th>x̄↑</th><th>x̄↓</th><th>2s↑</th><th>2s↓</th><th>B<sub>i</sub></th>"
      "<th>x̄<sub>i</sub></th><th>R↑<sub>i</sub></th><th>R↓<sub>i</sub></th><th>R<sub>i</sub></th></tr>",
      report::escape(report::base_name(g.file)), g.axis);
  for (const Iso230TargetRow& r : iso230_2_target_rows(g))
    h += fmt::format(
        "<tr><td>{:.3f}</td><td>{}/{}</td><td>{:+.3f}</td><td>{:+.3f}</td><td>{:.3f}</td><td>{:.3f}</td>"
        "<td>{:+.3f}</td><td>{:+.3f}</td><td>{:.3f}</td><td>{:.3f}</td><td>{:.3f}</td></tr>",
        r.target_mm, r.runs_up, r.runs_down, r.mean_up_um, r.mean_down_um, r.two_s_up_um, r.two_s_down_um,
        r.reversal_um, r.mean_bidirectional_um, r.repeat_up_um, r.repeat_down_um, r.repeat_um);
  return h + "</table>";
}

}  // namespace ncpost::comp
