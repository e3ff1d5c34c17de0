// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/diagnose_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "ncpost/compensation/identify_report.hpp"
#include "report_text.hpp"

namespace ncpost::comp {
namespace {

using report::base_name;
using report::escape;

/// Size of an added effect in report units.
std::string size_text(const AddedEffect& e) {
  if (e.candidate.kind == CandidateKind::drift)
    return fmt::format("{:.3f} ± {:.3f} µm over the data", 1e3 * e.size, 1e3 * e.size_sigma);
  if (e.size_is_angle) return fmt::format("{:.3f} ± {:.3f} µrad", 1e6 * e.size, 1e6 * e.size_sigma);
  return fmt::format("{:.3f} ± {:.3f} µm", 1e3 * e.size, 1e3 * e.size_sigma);
}

std::string what_size(const AddedEffect& e) {
  switch (e.candidate.kind) {
    case CandidateKind::component:
      return e.candidate.effect.find(":h") != std::string::npos ? "amplitude" : "over the measured travel";
    case CandidateKind::reversal:
      return "play";
    case CandidateKind::drift:
      return "largest";
    default:
      return "size";
  }
}

/// The largest harmonic of each file/value/axis line, as text.
std::string spectrum_text(const ResidualSignature& s, const std::string& file, int value, char axis) {
  for (const auto& l : s.spectrum)
    if (l.file == file && l.value == value && l.axis == axis) {
      std::string t;
      for (int k = 0; k < 4; ++k) t += fmt::format(" h{} {:.2f}", k + 1, l.amplitude_um[static_cast<std::size_t>(k)]);
      return t;
    }
  return {};
}

/// Where the tool-tip figures hold (issue 25 item 4): the measured region, the figures within it,
/// and what rests on the model's form beyond it.
std::string region_claim(const ToolTipComparison& tt) {
  if (tt.measured_region.empty())
    return "The region the data cover was not computed: the figures rest on the model's form.";
  std::string s = fmt::format(
      "The data cover {}; within that region the machine deviates by up to {:.2f} µm and the final "
      "model's uncertainty is 1σ up to {:.2f} µm (rms {:.2f}). Beyond it (the working-space figures "
      "above) they rest on the model's form (location errors constant along the axes), which no "
      "measurement there confirms.",
      tt.measured_region, tt.measured_uncompensated_max_um, tt.measured_sigma_max_um, tt.measured_sigma_rms_um);
  if (!tt.single_position_axes.empty())
    s += fmt::format(
        " {} measured at one position only: terms that change with {} are not measured, and no figure "
        "holds for other positions of {} but by the model's assumption.",
        tt.single_position_axes, tt.single_position_axes, tt.single_position_axes);
  return s;
}

struct Series {
  std::vector<double> x, y;
};

std::string scatter_svg(const std::string& title, const std::string& x_label, const Series& before,
                        const Series& after) {
  const double w = 360, h = 200, l = 44, r = 10, t = 22, b = 30;
  double x0 = 1e300, x1 = -1e300, ys = 0.5;
  for (const Series* s : {&before, &after})
    for (std::size_t i = 0; i < s->x.size(); ++i) {
      x0 = std::min(x0, s->x[i]);
      x1 = std::max(x1, s->x[i]);
      ys = std::max(ys, std::abs(s->y[i]));
    }
  if (!(x1 > x0)) x1 = x0 + 1.0;
  auto px = [&](double x) { return l + (w - l - r) * (x - x0) / (x1 - x0); };
  auto py = [&](double y) { return t + (h - t - b) * (0.5 - 0.5 * y / ys); };
  std::string svg =
      fmt::format(R"(<svg xmlns="http://www.w3.org/2000/svg" width="{}" height="{}" viewBox="0 0 {} {}">)", w, h, w, h);
  svg += fmt::format(R"(<text x="{}" y="14" font-size="11">{}</text>)", l, escape(title));
  svg += fmt::format(R"(<rect x="{}" y="{}" width="{}" height="{}" fill="none" stroke="#ccc"/>)", l, t, w - l - r,
                     h - t - b);
  svg += fmt::format(R"(<line x1="{}" y1="{:.1f}" x2="{}" y2="{:.1f}" stroke="#999"/>)", l, py(0), w - r, py(0));
  svg += fmt::format(R"(<text x="2" y="{:.1f}" font-size="9" fill="#666">{:+.2g} µm</text>)", py(ys) + 8, ys);
  svg += fmt::format(R"(<text x="2" y="{:.1f}" font-size="9" fill="#666">{:+.2g}</text>)", py(-ys), -ys);
  svg += fmt::format(R"(<text x="{}" y="{}" font-size="9" fill="#666">{:.4g}</text>)", l, h - 16, x0);
  svg += fmt::format(R"(<text x="{}" y="{}" font-size="9" fill="#666" text-anchor="end">{:.4g}</text>)", w - r, h - 16,
                     x1);
  svg += fmt::format(R"(<text x="{}" y="{}" font-size="10" text-anchor="middle">{}</text>)", (l + w - r) / 2, h - 4,
                     escape(x_label));
  auto dots = [&](const Series& s, const char* colour) {
    std::string d;
    for (std::size_t i = 0; i < s.x.size(); ++i) d += fmt::format("M{:.1f},{:.1f}h1.2 ", px(s.x[i]), py(s.y[i]));
    return fmt::format(R"(<path d="{}" stroke="{}" stroke-width="1.6" fill="none"/>)", d, colour);
  };
  svg += dots(before, "#aaa") + dots(after, "#1f5fbf");
  return svg + "</svg>";
}

/// The residual's signature, basic model -> final model, one line per file, value and axis.
std::string signature_text(const Machine& m, const std::vector<MeasurementSet>& sets, const DiagnoseResult& d) {
  std::string o = "  residual signature (basic -> final):\n";
  for (const auto& s : sets)
    for (int v = 0; v < s.values_per_row(); ++v) {
      for (int k = 0; k < m.rotary_count(); ++k) {
        const char a = m.rotary(k).letter;
        const std::string b = spectrum_text(d.before, s.file, v, a), f = spectrum_text(d.after, s.file, v, a);
        if (!b.empty())
          o += fmt::format("    {} {} vs {} (µm):{}  ->{}\n", base_name(s.file), value_name(s, v), a, b, f);
      }
      for (std::size_t i = 0; i < d.before.reversal.size(); ++i) {
        const auto& b = d.before.reversal[i];
        if (b.file != s.file || b.value != v) continue;
        const auto& f = d.after.reversal[i];
        if (std::abs(b.correlation) > 0.2 || std::abs(f.correlation) > 0.2)
          o += fmt::format(
              "    {} {} vs direction of {}: correlation {:.2f} -> {:.2f}, falling − rising {:.2f} -> {:.2f} µm\n",
              base_name(s.file), value_name(s, v), b.axis, b.correlation, f.correlation, b.falling_minus_rising_um,
              f.falling_minus_rising_um);
      }
      for (std::size_t i = 0; i < d.before.time.size(); ++i) {
        const auto& b = d.before.time[i];
        if (b.file != s.file || b.value != v) continue;
        const auto& f = d.after.time[i];
        o += fmt::format("    {} {} vs time: correlation {:.2f} -> {:.2f}, slope {:.2f} -> {:.2f} µm/h\n",
                         base_name(s.file), value_name(s, v), b.correlation, f.correlation, b.slope_um_per_h,
                         f.slope_um_per_h);
      }
    }
  return o;
}

}  // namespace

/// What the final model leaves that nothing explains (diagnose_structure.hpp), with the proposed measurement.
std::string unexplained_text(const DiagnoseResult& d) {
  if (d.unexplained.empty()) return "  left: nothing against any rotary axis beyond the noise\n";
  std::string o = "  UNEXPLAINED (no candidate explains it; not attributed to any effect):\n";
  if (!d.not_attributed.empty()) {
    std::string l;
    for (const auto& n : d.not_attributed) l += (l.empty() ? "" : ", ") + n;
    o += "    fitted on the way but not attributed (structure remained with them): " + l + "\n";
  }
  for (const auto& u : d.unexplained)
    o += fmt::format("    {} {} against {}: {} (F = {:.3g}, p = {:.2g}, {} groups)\n", base_name(u.file), u.value,
                     u.axis, u.shape, u.f_statistic, u.p_value, u.groups);
  o += "    to resolve it: " + d.unexplained.front().proposal + "\n";
  return o;
}

std::string text_diagnose_report(const Machine& m, const std::vector<MeasurementSet>& sets, const DiagnoseResult& d,
                                 const ToolTipComparison& tt) {
  std::string o = "residual analysis (issue 6; --no-diagnose skips it)\n";
  o += fmt::format(
      "  basic model: rms {:.3f} µm, max {:.3f} µm; noise level from the data (successive differences): {:.3f} µm\n",
      d.basic.rms_after_um, d.basic.max_after_um, d.noise_um);
  if (d.added.empty()) o += "  no effect added\n";
  for (std::size_t i = 0; i < d.added.size(); ++i) {
    const AddedEffect& e = d.added[i];
    o += fmt::format(
        "  {}. added {:<16} {} {}; rms {:.3f} -> {:.3f} µm, max {:.3f} -> {:.3f} µm (F = {:.4g}, p = {:.2g}, {} "
        "candidates{})\n",
        i + 1, e.candidate.effect, what_size(e), size_text(e), e.rms_before_um, e.rms_after_um, e.max_before_um,
        e.max_after_um, e.f_statistic, e.p_value, e.tested,
        e.candidate.measurement_only ? "; measuring only, not posted" : "");
    if (!e.equivalent.empty()) {
      std::string list;
      for (const auto& q : e.equivalent) list += (list.empty() ? "" : ", ") + q;
      o += "       the data cannot tell it from " + list + " (same signature; named by catalogue order)\n";
    }
    if (!e.correlated.empty() || e.separation_sine < 0.05) o += "       " + e.separation + "\n";
    for (std::size_t p = 0; p < e.values.size(); ++p) {
      const std::string& n = e.values.names()[p];
      const ReportValue v = report_value(m, n, e.values.values()[p]);
      const auto u = e.uncertainty.get(n);
      o += u ? fmt::format("       {:<20} {:>10.3f} ± {:.3f} {}\n", n, v.value, report_value(m, n, *u).value, v.unit)
             : fmt::format("       {:<20} {:>10.3f} (held) {}\n", n, v.value, v.unit);
    }
  }
  o += "  stopped: " + d.stop_reason + "\n";
  for (const auto& r : d.last_rejected)
    o += fmt::format("    {} not added: {} (rms would be {:.3f} µm)\n", r.effect, r.reason, r.rms_after_um);
  o += unexplained_text(d);
  o += "  residual (µm):           basic rms / max         final rms / max\n";
  for (std::size_t i = 0; i < d.basic.files.size() && i < d.final_fit.files.size(); ++i) {
    const auto& b = d.basic.files[i];
    const auto& f = d.final_fit.files[i];
    o += fmt::format("    {:<22} {:>8.3f} / {:<8.3f}      {:>8.3f} / {:<8.3f}\n", base_name(b.file), b.rms_after_um,
                     b.max_after_um, f.rms_after_um, f.max_after_um);
  }
  o += fmt::format("    {:<22} {:>8.3f} / {:<8.3f}      {:>8.3f} / {:<8.3f}\n", "all", d.basic.rms_after_um,
                   d.basic.max_after_um, d.final_fit.rms_after_um, d.final_fit.max_after_um);
  o += fmt::format(
      "  predicted tool-tip error over the working space ({} poses): uncompensated max {:.2f} µm (rms {:.2f});\n"
      "    left after compensating with the basic model max {:.2f} µm (rms {:.2f}); with the final model its\n"
      "    uncertainty, 1σ up to {:.2f} µm (rms {:.2f})\n",
      tt.poses, tt.uncompensated_max_um, tt.uncompensated_rms_um, tt.basic_left_max_um, tt.basic_left_rms_um,
      tt.final_sigma_max_um, tt.final_sigma_rms_um);
  o += "    " + region_claim(tt) + "\n";
  o += signature_text(m, sets, d);
  return o;
}

namespace {

/// "effect (≡ a, b)": the effect and those the data cannot tell from it.
std::string effect_name(const AddedEffect& e) {
  if (e.equivalent.empty()) return escape(e.candidate.effect);
  std::string l;
  for (const auto& q : e.equivalent) l += (l.empty() ? "" : ", ") + q;
  return escape(e.candidate.effect) + " (≡ " + l + ")";
}

/// The effects added, one row each.
std::string html_effects(const DiagnoseResult& d) {
  std::string h =
      "<table><tr><th class=n>effect</th><th class=n>size</th><th>rms before µm</th><th>rms after µm</th><th>max "
      "before µm</th>"
      "<th>max after µm</th><th>F</th><th>p</th><th class=n>posted</th></tr>";
  for (const auto& e : d.added)
    h += fmt::format(
        "<tr><td class=n>{}</td><td class=n>{} {}</td><td>{:.3f}</td><td>{:.3f}</td><td>{:.3f}</td><td>{:.3f}</td>"
        "<td>{:.4g}</td><td>{:.2g}</td><td class=n>{}</td></tr>",
        effect_name(e), what_size(e), size_text(e), e.rms_before_um, e.rms_after_um, e.max_before_um, e.max_after_um,
        e.f_statistic, e.p_value, e.candidate.measurement_only ? "no (measuring only)" : "yes");
  h += "</table>";
  return h;
}

/// The candidates the last step rejected, and the structure no candidate explains.
std::string html_left_over(const DiagnoseResult& d) {
  std::string h;
  if (!d.last_rejected.empty()) {
    h += "<p>Not added in the last step:</p><ul>";
    for (const auto& r : d.last_rejected) h += "<li>" + escape(r.effect + ": " + r.reason) + "</li>";
    h += "</ul>";
  }
  if (!d.unexplained.empty()) {
    h += "<h2>Unexplained</h2><p>Structure the final model leaves that no candidate explains (not attributed to any "
         "effect):</p><ul>";
    for (const auto& u : d.unexplained)
      h += "<li>" +
           escape(fmt::format("{} {} against {}: {} (F = {:.3g}, p = {:.2g})", base_name(u.file), u.value, u.axis,
                              u.shape, u.f_statistic, u.p_value)) +
           "</li>";
    h += "</ul><p>To resolve it: " + escape(d.unexplained.front().proposal) + ".</p>";
  }
  return h;
}

/// The residual of each file, basic and final model; then the predicted tool-tip error.
std::string html_residuals_and_tool_tip(const DiagnoseResult& d, const ToolTipComparison& tt) {
  std::string h =
      "<h2>Residual per file</h2><table><tr><th class=n>file</th><th>basic rms µm</th><th>basic max µm</th><th>final "
      "rms µm</th><th>final max µm</th></tr>";
  for (std::size_t i = 0; i < d.basic.files.size() && i < d.final_fit.files.size(); ++i)
    h += fmt::format("<tr><td class=n>{}</td><td>{:.3f}</td><td>{:.3f}</td><td>{:.3f}</td><td>{:.3f}</td></tr>",
                     escape(base_name(d.basic.files[i].file)), d.basic.files[i].rms_after_um,
                     d.basic.files[i].max_after_um, d.final_fit.files[i].rms_after_um,
                     d.final_fit.files[i].max_after_um);
  h += "</table>";
  h += fmt::format(
      "<h2>Predicted tool-tip error</h2><p>Over {} poses of the working space: the machine as identified deviates "
      "from the nominal by up to {:.2f} µm (rms {:.2f}); compensating with the basic model alone would leave "
      "{:.2f} µm (rms {:.2f}); compensating with the final model leaves its uncertainty, 1σ up to {:.2f} µm (rms "
      "{:.2f}).</p>",
      tt.poses, tt.uncompensated_max_um, tt.uncompensated_rms_um, tt.basic_left_max_um, tt.basic_left_rms_um,
      tt.final_sigma_max_um, tt.final_sigma_rms_um);
  h += "<p>" + escape(region_claim(tt)) + "</p>";
  return h;
}

/// The abscissae a set's residual is plotted against: each rotary axis it turns through 9 or more
/// angles (label, axis index), then time (index -1).
std::vector<std::pair<std::string, int>> plot_abscissae(const Machine& m, const MeasurementSet& s) {
  std::vector<std::pair<std::string, int>> xs;
  for (int k = 0; k < m.rotary_count(); ++k) {
    std::set<long long> distinct;
    for (const auto& row : s.rows) distinct.insert(std::llround(row.command[3 + k] * 1e6));
    if (distinct.size() >= 9) xs.push_back({std::string(1, m.rotary(k).letter) + " (deg)", 3 + k});
  }
  xs.push_back({"t (s)", -1});
  return xs;
}

/// The residual of every set against angle and time, basic and final model.
std::string html_residual_plots(const Machine& m, const std::vector<MeasurementSet>& sets, const DiagnoseResult& d) {
  std::string h =
      "<h2>Residual against angle and time</h2><p><span style=\"color:#999\">basic model</span>, "
      "<span style=\"color:#1f5fbf\">final model</span>; sphere sets show dx, dy and dz together.</p><div class=plots>";
  Eigen::Index at = 0;
  for (const auto& s : sets) {
    const int nv = s.values_per_row();
    for (const auto& [label, axis] : plot_abscissae(m, s)) {
      Series before, after;
      for (std::size_t k = 0; k < s.rows.size(); ++k)
        for (int v = 0; v < nv; ++v) {
          const double x = axis < 0 ? s.rows[k].time_s : rad_to_deg(s.rows[k].command[axis]);
          const Eigen::Index i = at + static_cast<Eigen::Index>(k) * nv + v;
          before.x.push_back(x);
          before.y.push_back(1e3 * d.residual_before_mm[i]);
          after.x.push_back(x);
          after.y.push_back(1e3 * d.residual_after_mm[i]);
        }
      h += "<div class=plot>" + scatter_svg(base_name(s.file), label, before, after) + "</div>";
    }
    at += static_cast<Eigen::Index>(s.rows.size()) * nv;
  }
  h += "</div>";
  return h;
}

}  // namespace

std::string html_diagnose_report(const Machine& m, const std::vector<MeasurementSet>& sets, const DiagnoseResult& d,
                                 const ToolTipComparison& tt, const IdentifyReportInputs& inputs) {
  std::string page = html_report(m, sets, d.final_fit, inputs);
  std::string h = "<h1>Residual analysis</h1>";
  h += fmt::format(
      "<p>Basic model: rms {:.3f} µm, max {:.3f} µm; final model: rms {:.3f} µm, max {:.3f} µm. Noise level "
      "estimated from the data: {:.3f} µm. Stopped: {}.</p>",
      d.basic.rms_after_um, d.basic.max_after_um, d.final_fit.rms_after_um, d.final_fit.max_after_um, d.noise_um,
      escape(d.stop_reason));
  h += html_effects(d);
  h += html_left_over(d);
  h += html_residuals_and_tool_tip(d, tt);
  h += "<h2>Residual signature</h2><p>Harmonic amplitudes against each rotary angle that turns most of a turn, "
       "correlation with the direction each axis last moved and with time; basic model → final model.</p><pre>" +
       escape(signature_text(m, sets, d)) + "</pre>";
  h += html_residual_plots(m, sets, d);
  const auto end = page.rfind("</body>");
  if (end == std::string::npos) return page + h;
  return page.substr(0, end) + h + page.substr(end);
}

}  // namespace ncpost::comp
