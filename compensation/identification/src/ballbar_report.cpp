// SPDX-License-Identifier: Apache-2.0
// The ballbar section of the identification report.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "identify_report_sections.hpp"
#include "ncpost/report/circularity.hpp"
#include "ncpost/report/html_page.hpp"
#include "ncpost/report/polar_plot.hpp"
#include "ncpost/compensation/uncertainty_report.hpp"

namespace ncpost::comp::sections {
namespace {

using report::escape;

constexpr double kDeg = 180.0 / 3.141592653589793;

struct TestAngle {
  std::string axis;           ///< the axis whose angle the plot shows ("C", or "XY" for a circle of two linear axes)
  std::vector<double> angle;  ///< rad, unwrapped along the test
  bool rotary = true;
  double radius_mm = 0.0;  ///< the circle's radius for a linear circle (feed in mm/min)
};

/// The angle of the test: the rotary axis that turns most, or, if none turns, the polar angle of
/// the two linear axes that move most (a circle test on a three-axis machine).
TestAngle test_angle(const Machine& m, const MeasurementSet& s) {
  TestAngle t;
  int best_axis = -1;
  double best = 1e-6;
  for (int a = 3; a < 3 + m.rotary_count(); ++a) {
    double lo = INFINITY, hi = -INFINITY;
    for (const auto& r : s.rows) lo = std::min(lo, r.command[a]), hi = std::max(hi, r.command[a]);
    if (hi - lo > best) best = hi - lo, best_axis = a;
  }
  if (best_axis >= 0) {
    t.axis = std::string(1, m.axes[static_cast<std::size_t>(best_axis)].letter);
    for (const auto& r : s.rows) t.angle.push_back(r.command[best_axis]);
    return t;
  }
  // linear circle: the two axes with the largest ranges
  double range[3];
  double mean[3] = {0, 0, 0};
  for (int a = 0; a < 3; ++a) {
    double lo = INFINITY, hi = -INFINITY;
    for (const auto& r : s.rows)
      lo = std::min(lo, r.command[a]), hi = std::max(hi, r.command[a]), mean[a] += r.command[a];
    range[a] = hi - lo;
    mean[a] /= std::max<std::size_t>(s.rows.size(), 1);
  }
  int u = 0, v = 1;
  if (range[2] > std::min(range[0], range[1])) (range[0] < range[1] ? u : v) = 2;
  if (u > v) std::swap(u, v);
  t.rotary = false;
  t.axis = fmt::format("{}{}", m.axes[static_cast<std::size_t>(u)].letter, m.axes[static_cast<std::size_t>(v)].letter);
  t.radius_mm = 0.25 * (range[u] + range[v]);
  double previous = 0.0, offset = 0.0;
  for (std::size_t k = 0; k < s.rows.size(); ++k) {
    double a = std::atan2(s.rows[k].command[v] - mean[v], s.rows[k].command[u] - mean[u]);
    if (k > 0) {
      while (a + offset - previous > 3.141592653589793) offset -= 2 * 3.141592653589793;
      while (a + offset - previous < -3.141592653589793) offset += 2 * 3.141592653589793;
    }
    previous = a + offset;
    t.angle.push_back(previous);
  }
  return t;
}

std::string axes_moved(const Machine& m, const MeasurementSet& s) {
  std::string out;
  for (int a = 0; a < static_cast<int>(m.axes.size()); ++a) {
    double lo = INFINITY, hi = -INFINITY;
    for (const auto& r : s.rows) lo = std::min(lo, r.command[a]), hi = std::max(hi, r.command[a]);
    if (hi - lo > (a < 3 ? 1e-3 : 1e-5))
      out += std::string(out.empty() ? "" : " ") + m.axes[static_cast<std::size_t>(a)].letter;
  }
  return out.empty() ? "none" : out;
}

/// "C 86.4°/min counter-clockwise" from the angle and the row times.
std::string feed_and_direction(const TestAngle& t, const MeasurementSet& s, int direction) {
  double turned = 0.0, time = 0.0;
  for (std::size_t k = 1; k < s.rows.size(); ++k) {
    const double da = std::abs(t.angle[k] - t.angle[k - 1]), dt = s.rows[k].time_s - s.rows[k - 1].time_s;
    if (da > 0 && dt > 0) turned += da, time += dt;
  }
  const char* dir = direction > 0 ? "counter-clockwise" : direction < 0 ? "clockwise" : "both directions";
  if (!(time > 0)) return fmt::format("{} {} (no times in the file: feed unknown)", t.axis, dir);
  const double rate = turned / time * 60.0;  // rad/min
  if (t.rotary) return fmt::format("{} {:.1f}°/min {}", t.axis, rate * kDeg, dir);
  return fmt::format("{} {:.0f} mm/min (radius {:.1f} mm) {}", t.axis, rate * t.radius_mm, t.radius_mm, dir);
}

std::string figures_row(const std::string& what, const report::CircularityFigures& f, const UncertaintyBudget& budget,
                        std::optional<double> tol) {
  if (!f.ok)
    return fmt::format("<tr><td class=n>{}</td><td class=n colspan=\"7\">{}</td></tr>", escape(what),
                       escape(f.message));
  return fmt::format(
      "<tr><td class=n>{}</td><td>{}</td><td>{:+.2f}</td><td>{:+.2f}</td><td>{}</td><td>{:+.2f}, {:+.2f}</td>"
      "<td>{:.0f}°</td>{}</tr>",
      escape(what), escape(value_with_U(f.G_um, budget)), f.F_max_um, f.F_min_um,
      f.H_um >= 0 ? fmt::format("{:.2f}", f.H_um) : "(one direction)", f.centre_x_um, f.centre_y_um, f.arc_deg,
      verdict_cell(f.G_um, budget, tol));
}

}  // namespace

BallbarFigures ballbar_figures(const Machine& m, const MeasurementSet& s) {
  BallbarFigures out;
  if (s.rows.size() < 8) return out;
  const TestAngle t = test_angle(m, s);
  std::vector<double> measured_um;
  for (const auto& r : s.rows) measured_um.push_back(1e3 * (r.value[0] - s.bar_length_mm));
  const report::CircularityByDirection f = report::iso230_4_by_direction(t.angle, measured_um);
  out.both = f.both;
  out.ccw = f.ccw;
  out.cw = f.cw;
  return out;
}

std::optional<double> two_file_hysteresis_um(const Machine& m, const MeasurementSet& a, const MeasurementSet& b) {
  if (&a == &b || a.type != MeasurementType::ballbar || b.type != MeasurementType::ballbar || a.rows.size() < 8 ||
      b.rows.size() < 8 || a.bar_length_mm != b.bar_length_mm || a.table_ball_mm != b.table_ball_mm ||
      a.tool_ball_mm != b.tool_ball_mm || axes_moved(m, a) != axes_moved(m, b))
    return std::nullopt;
  const BallbarFigures fa = ballbar_figures(m, a), fb = ballbar_figures(m, b);
  if (!fa.both.ok || !fb.both.ok || fa.both.direction == 0 || fa.both.direction != -fb.both.direction)
    return std::nullopt;
  const MeasurementSet& ccw = fa.both.direction > 0 ? a : b;
  const MeasurementSet& cw = fa.both.direction > 0 ? b : a;
  auto delta_l_um = [](const MeasurementSet& s) {
    std::vector<double> out;
    for (const auto& r : s.rows) out.push_back(1e3 * (r.value[0] - s.bar_length_mm));
    return out;
  };
  const double h = report::circular_hysteresis_um(test_angle(m, ccw).angle, delta_l_um(ccw), test_angle(m, cw).angle,
                                                  delta_l_um(cw));
  if (h < 0) return std::nullopt;
  return h;
}

const MeasurementSet* opposite_run(const Machine& m, const std::vector<MeasurementSet>& sets, std::size_t s) {
  for (const MeasurementSet& other : sets)
    if (two_file_hysteresis_um(m, sets[s], other)) return &other;
  return nullptr;
}

std::string ballbar_section(const Machine& m, const MeasurementSet& s, const std::vector<double>& fitted,
                            const std::vector<double>& nominal, std::optional<double> tol,
                            const std::vector<double>& repeat_G_um, const MeasurementSet* opposite) {
  if (s.rows.size() < 8 || fitted.size() < s.rows.size() || nominal.size() < s.rows.size()) return "";
  const TestAngle t = test_angle(m, s);
  std::vector<double> measured_um, fitted_um, nominal_um, residual_um;
  for (std::size_t k = 0; k < s.rows.size(); ++k) {
    measured_um.push_back(1e3 * (s.rows[k].value[0] - s.bar_length_mm));
    fitted_um.push_back(1e3 * (fitted[k] - s.bar_length_mm));
    nominal_um.push_back(1e3 * (nominal[k] - s.bar_length_mm));
    residual_um.push_back(measured_um.back() - fitted_um.back());
  }
  report::CircularityFigures before = report::iso230_4_circularity(t.angle, measured_um);
  const std::optional<double> paired_H = opposite ? two_file_hysteresis_um(m, s, *opposite) : std::nullopt;
  if (paired_H) before.H_um = *paired_H;  // with the other direction's file (ISO 230-4 H)
  const report::CircularityFigures after = report::iso230_4_circularity(t.angle, residual_um);
  const std::string name = report::base_name(s.file);
  const std::string subtitle = "axes moved: " + axes_moved(m, s) + "; " + feed_and_direction(t, s, before.direction);
  std::string h =
      fmt::format("<h3>{}</h3><p class=\"note\">Bar {:.3f} mm; table ball {:.3f}, {:.3f}, {:.3f} mm; {} rows; {}.</p>",
                  escape(name), s.bar_length_mm, s.table_ball_mm.x(), s.table_ball_mm.y(), s.table_ball_mm.z(),
                  s.rows.size(), escape(subtitle));
  report::PolarFrame f;
  f.title = name + ": ΔL = L − bar length";
  f.subtitle = subtitle;
  f.angle_axis = t.axis;
  h += "<div class=\"plots\"><div class=\"plot\">" +
       report::polar_plot(f, {{"nominal model", "#999999", t.angle, nominal_um, true},
                              {"identified model", "#d0402b", t.angle, fitted_um},
                              {"measured", "#1f5fbf", t.angle, measured_um}}) +
       "</div>";
  f.title = name + ": residual after identification (own scale)";
  h += "<div class=\"plot\">" +
       report::polar_plot(f, {{"measured − identified model", "#2a8a3a", t.angle, residual_um}}) + "</div></div>";
  const UncertaintyBudget budget = circularity_budget(s, repeat_G_um);
  h += "<table><tr><th class=n>ISO 230-4</th><th>circular deviation G ± U µm</th><th>radial deviation F max µm</th>"
       "<th>F min µm</th><th>circular hysteresis H µm</th><th>LSC centre offset µm</th><th>arc</th>";
  if (tol) h += fmt::format("<th>G ≤ {:g} µm</th>", *tol);
  h += "</tr>" + figures_row("measured (the machine as it is)", before, budget, tol);
  if (before.direction == 0) {  // ISO 230-4: G of each direction of travel
    const BallbarFigures by_direction = ballbar_figures(m, s);
    h += figures_row("measured, counter-clockwise run", by_direction.ccw, budget, tol) +
         figures_row("measured, clockwise run", by_direction.cw, budget, tol);
  }
  h += figures_row("residual after identification (left by the model)", after, budget, tol) + "</table>";
  if (paired_H)
    h += fmt::format(
        "<p class=\"note\">Circular hysteresis H {:.2f} µm: this {} run against the {} run of {} (the same "
        "test in the other direction).</p>",
        *paired_H, before.direction > 0 ? "counter-clockwise" : "clockwise",
        before.direction > 0 ? "clockwise" : "counter-clockwise", escape(report::base_name(opposite->file)));
  h += budget_table_html("G of " + name, budget);
  return h;
}

}  // namespace ncpost::comp::sections
