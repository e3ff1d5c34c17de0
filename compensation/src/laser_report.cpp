// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/laser_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include "report_text.hpp"

namespace ncpost::comp {
namespace {

using report::escape;

double shown(const LaserFunction& f, double v) { return f.is_angle() ? v * 1e6 : v * 1e3; }
const char* unit(const LaserFunction& f) { return f.is_angle() ? "µrad" : "µm"; }

/// A small line plot of the table (and its polynomial) in µm / µrad.
std::string svg_plot(const LaserFunction& f) {
  const double w = 320, h = 150, pad = 30;
  const double x0 = f.nodes_mm.front(), x1 = f.nodes_mm.back();
  double lo = 0, hi = 0;
  for (double v : f.values) {
    lo = std::min(lo, shown(f, v));
    hi = std::max(hi, shown(f, v));
  }
  if (hi - lo < 1e-9) hi = lo + 1;
  auto X = [&](double x) { return pad + (x - x0) / std::max(1e-9, x1 - x0) * (w - 2 * pad); };
  auto Y = [&](double y) { return h - pad - (y - lo) / (hi - lo) * (h - 2 * pad); };
  std::string s = fmt::format(R"(<svg xmlns="http://www.w3.org/2000/svg" width="{}" height="{}" style="background:#fff;border:1px solid #ccc">)", w, h);
  s += fmt::format(R"(<line x1="{}" y1="{:.1f}" x2="{}" y2="{:.1f}" stroke="#999"/>)", pad, Y(0), w - pad, Y(0));
  std::string pts, poly;
  for (std::size_t i = 0; i < f.nodes_mm.size(); ++i) {
    pts += fmt::format("{:.1f},{:.1f} ", X(f.nodes_mm[i]), Y(shown(f, f.values[i])));
    s += fmt::format(R"(<circle cx="{:.1f}" cy="{:.1f}" r="2.5" fill="{}"/>)", X(f.nodes_mm[i]),
                     Y(shown(f, f.values[i])), f.seen[i] ? "#1f5fbf" : "#d0402b");
  }
  for (int k = 0; k <= 60; ++k) {
    const double x = x0 + (x1 - x0) * k / 60.0;
    const double v = f.polynomial[0] * x + f.polynomial[1] * x * x + f.polynomial[2] * x * x * x;
    poly += fmt::format("{:.1f},{:.1f} ", X(x), Y(shown(f, v)));
  }
  s += fmt::format(R"(<polyline points="{}" fill="none" stroke="#1f5fbf"/>)", pts);
  s += fmt::format(R"(<polyline points="{}" fill="none" stroke="#e09020" stroke-dasharray="4 3"/>)", poly);
  s += fmt::format(R"(<text x="4" y="14" font-size="11">{} ({} of {}), {} over {} … {} mm</text>)", f.name(), escape(f.kind()),
                   f.axis, unit(f), x0, x1);
  s += fmt::format(R"(<text x="4" y="{}" font-size="10">{:.2f}</text><text x="4" y="{}" font-size="10">{:.2f}</text>)",
                   pad, hi, h - pad + 10, lo);
  return s + "</svg>";
}

}  // namespace

std::string laser_text_report(const Machine& m, const LaserIdentifyResult& r) {
  std::string o = fmt::format("laser identification of {}: {} readings; {}\n", m.name, r.readings, r.message);
  if (!r.ok) return o;
  o += fmt::format("residual: machine without errors {:.2f} µm rms / {:.2f} max; fitted {:.2f} / {:.2f}; "
                   "model as written (ISO 230-1 reference) {:.2f} / {:.2f}\n",
                   r.rms_nominal_um, r.max_nominal_um, r.rms_fit_um, r.max_fit_um, r.rms_after_um, r.max_after_um);
  o += "\nISO 230-2 per positioning line (µm): A accuracy, R repeatability, B reversal (mean), E systematic, M mean\n";
  for (const auto& g : r.iso230)
    o += fmt::format("  {:<12} {}  A {:7.2f}  R {:6.2f}  B {:6.2f} ({:+6.2f})  E {:7.2f}  M {:7.2f}\n",
                     g.file.substr(g.file.find_last_of('/') + 1), g.axis, g.accuracy_A_um, g.repeatability_R_um, g.reversal_B_um, g.mean_reversal_um, g.systematic_E_um,
                     g.mean_bidirectional_M_um);
  o += "\nerror functions (tables at every target; ISO 230-1 reference; p1..p3 fitted through home)\n";
  for (const auto& f : r.functions) {
    double lo = 0, hi = 0, sig = 0;
    for (std::size_t i = 0; i < f.values.size(); ++i) {
      lo = std::min(lo, shown(f, f.values[i]));
      hi = std::max(hi, shown(f, f.values[i]));
      sig = std::max(sig, shown(f, f.sigma[i]));
    }
    o += fmt::format("  {} {:<18} {:>4}: {:8.2f} … {:8.2f} {} (±{:.2f}){}; p1..p3 {:.4g} {:.4g} {:.4g}, fit rms {:.2f}\n",
                     f.name(), f.kind(), f.axis, lo, hi, unit(f), sig,
                     f.fully_seen() ? "" : (f.partly_seen() ? " PARTLY UNSEEN" : " NOT SEEN"), f.polynomial[0],
                     f.polynomial[1], f.polynomial[2], shown(f, f.polynomial_rms));
    if (f.component >= 'X' && f.component != f.axis)
      o += fmt::format("      straightness {:.2f} µm about its least-squares line, slope {:.2f} µrad moved into squareness\n",
                       f.iso_straightness_um, f.iso_slope * 1e6);
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

std::string laser_html_report(const Machine& m, const LaserIdentifyResult& r) {
  std::string h = "<!DOCTYPE html><html><head><meta charset=\"utf-8\"><title>ncpost laser identification</title>"
                  "<style>body{font-family:sans-serif;margin:1em}pre{background:#f6f6f6;padding:.5em}"
                  "svg{margin:4px}</style></head><body>";
  h += fmt::format("<h1>Laser identification of {}</h1>", escape(m.name));
  h += "<pre>" + escape(laser_text_report(m, r)) + "</pre>";
  h += "<h2>Error functions</h2><p>blue: identified table (red dots: nodes not seen), orange dashed: fitted "
       "polynomial p1..p3</p>";
  for (const auto& f : r.functions) h += svg_plot(f);
  return h + "</body></html>\n";
}

}  // namespace ncpost::comp
