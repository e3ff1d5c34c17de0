// SPDX-License-Identifier: Apache-2.0
// The sphere-probing section of the identification report: the measured positions and the
// dispersion of each component before (nominal model) and after identification, in µm.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "identify_report_sections.hpp"
#include "ncpost/report/html_page.hpp"

namespace ncpost::comp::sections {
namespace {

using report::escape;

struct Dispersion {
  double mean = 0, sd = 0, range = 0;
};

Dispersion dispersion(const std::vector<double>& v) {
  Dispersion d;
  if (v.empty()) return d;
  double lo = INFINITY, hi = -INFINITY;
  for (double x : v) d.mean += x, lo = std::min(lo, x), hi = std::max(hi, x);
  d.mean /= static_cast<double>(v.size());
  for (double x : v) d.sd += (x - d.mean) * (x - d.mean);
  d.sd = v.size() > 1 ? std::sqrt(d.sd / static_cast<double>(v.size() - 1)) : 0.0;
  d.range = hi - lo;
  return d;
}

constexpr std::size_t kRowsShown = 120;

}  // namespace

std::string sphere_section(const Machine& m, const MeasurementSet& s, const std::vector<double>& fitted,
                           const std::vector<double>& nominal) {
  const std::size_t n = s.rows.size();
  if (n == 0 || fitted.size() < 3 * n || nominal.size() < 3 * n) return "";
  std::vector<double> measured[3], before[3], after[3];
  for (std::size_t k = 0; k < n; ++k)
    for (int c = 0; c < 3; ++c) {
      const double v = 1e3 * s.rows[k].value[c];
      measured[c].push_back(v);
      before[c].push_back(v - 1e3 * nominal[3 * k + static_cast<std::size_t>(c)]);
      after[c].push_back(v - 1e3 * fitted[3 * k + static_cast<std::size_t>(c)]);
    }
  const std::string name = report::base_name(s.file);
  std::string h = fmt::format(
      "<h3>{}</h3><p class=\"note\">Sphere centre at home {:.3f}, {:.3f}, {:.3f} mm; {} probed "
      "positions. dx, dy, dz: the sphere centre measured relative to its nominal place (µm); "
      "residual: measured − predicted by the model.</p>",
      escape(name), s.sphere_mm.x(), s.sphere_mm.y(), s.sphere_mm.z(), n);
  h += "<table><tr><th class=n>dispersion per axis (µm)</th><th>mean</th><th>s</th><th>range</th><th>residual s, "
       "nominal "
       "model</th><th>range</th><th>residual s, identified</th><th>range</th></tr>";
  for (int c = 0; c < 3; ++c) {
    const Dispersion dm = dispersion(measured[c]), db = dispersion(before[c]), da = dispersion(after[c]);
    h += fmt::format(
        "<tr><td class=n>d{}</td><td>{:+.2f}</td><td>{:.2f}</td><td>{:.2f}</td><td>{:.2f}</td><td>{:.2f}</td>"
        "<td>{:.3f}</td><td>{:.3f}</td></tr>",
        "xyz"[c], dm.mean, dm.sd, dm.range, db.sd, db.range, da.sd, da.range);
  }
  h += "</table><table><tr><th>line</th>";
  for (const auto& a : m.axes) h += fmt::format("<th>{} ({})</th>", a.letter, a.is_rotary() ? "°" : "mm");
  h += "<th>dx µm</th><th>dy µm</th><th>dz µm</th><th>residual dx</th><th>dy</th><th>dz</th></tr>";
  for (std::size_t k = 0; k < n && k < kRowsShown; ++k) {
    h += fmt::format("<tr><td>{}</td>", s.rows[k].line);
    for (int a = 0; a < static_cast<int>(m.axes.size()); ++a)
      h += a < 3 ? fmt::format("<td>{:.3f}</td>", s.rows[k].command[a])
                 : fmt::format("<td>{:.3f}</td>", s.rows[k].command[a] * 180.0 / 3.141592653589793);
    h += fmt::format(
        "<td>{:+.2f}</td><td>{:+.2f}</td><td>{:+.2f}</td><td>{:+.3f}</td><td>{:+.3f}</td><td>{:+.3f}</td></tr>",
        measured[0][k], measured[1][k], measured[2][k], after[0][k], after[1][k], after[2][k]);
  }
  h += "</table>";
  if (n > kRowsShown) h += fmt::format("<p class=\"note\">First {} of {} positions shown.</p>", kRowsShown, n);
  return h;
}

}  // namespace ncpost::comp::sections
