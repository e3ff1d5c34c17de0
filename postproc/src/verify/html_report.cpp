// SPDX-License-Identifier: Apache-2.0
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>

#include "ncpost/postproc/verify/preview_html.hpp"
#include "ncpost/postproc/verify/preview_svg.hpp"
#include "ncpost/version.hpp"

namespace ncpost::preview {
namespace {

/// What the preview adds to the shared page style: source lines in monospace.
std::string style() { return "<style>td.src{text-align:left;font-family:monospace;white-space:pre}</style>\n"; }

std::string totals(const HtmlReport& r) {
  const PreviewSummary& s = *r.summary;
  std::string t = "<table>\n";
  auto row = [&](const std::string& k, const std::string& v) {
    t += fmt::format("<tr><th>{}</th><td>{}</td></tr>\n", k, v);
  };
  row("CL motions / previewed blocks", fmt::format("{} / {}", r.stats.motions, s.blocks()));
  row("largest nonlinear error", fmt::format("{:.4f} mm", s.max_error_mm()));
  row("mean nonlinear error", fmt::format("{:.4f} mm", s.mean_error_mm()));
  row("largest orientation error", fmt::format("{:.4f}&deg;", rad_to_deg(s.max_orientation_rad())));
  row("harmonic model vs exact, largest difference", fmt::format("{:.4f} mm", s.max_harmonic_residual_mm()));
  for (double tol : {0.001, 0.005, 0.01, 0.05, 0.1})
    row(fmt::format("blocks over {} &micro;m", tol * 1000), fmt::format("{}", s.blocks_over(tol)));
  return t + "</table>\n";
}

std::string series_chart(const PreviewSummary& s) {
  svg::Series exact{"exact largest error", "#1f5fa8", {}, {}, false};
  svg::Series harmonic{"harmonic model Emax", "#d0702a", {}, {}, true};
  for (const auto& b : s.series()) {
    const double x = 0.5 * static_cast<double>(b.first_block + b.last_block);
    exact.x.push_back(x);
    exact.y.push_back(b.max_error_mm);
    harmonic.x.push_back(x);
    harmonic.y.push_back(b.max_harmonic_mm);
  }
  svg::ChartFrame f;
  f.title = "Nonlinear error per block along the program";
  f.x_label = "block";
  f.y_label = "error (mm)";
  return svg::line_chart(f, {exact, harmonic});
}

std::string histogram_chart(const PreviewSummary& s) {
  const auto& h = s.histogram();
  std::size_t first = h.size(), last = 0;
  for (std::size_t i = 0; i < h.size(); ++i)
    if (h[i] > 0) {
      first = std::min(first, i);
      last = i;
    }
  if (first > last) {
    first = 0;
    last = 0;
  }
  std::vector<double> heights;
  std::vector<std::string> labels, colours;
  for (std::size_t i = first; i <= last; ++i) {
    heights.push_back(static_cast<double>(h[i]));
    const double lo = PreviewSummary::bin_lower_mm(static_cast<int>(i));
    labels.push_back(i == 0 ? "<1e-6" : fmt::format("{:.2g}", lo));
    // the colours of the path plot: log scale over 3 decades below the largest error
    const double vmin = s.max_error_mm() * 1e-3;
    colours.push_back(svg::colour(lo > vmin && vmin > 0 ? std::log10(lo / vmin) / 3.0 : 0.0));
  }
  svg::ChartFrame f;
  f.height = 260;
  f.title = "Histogram of the block errors (log bins, 4 per decade)";
  f.x_label = "largest error of the block, lower bin edge (mm)";
  f.y_label = "blocks";
  return svg::bar_chart(f, heights, labels, colours, heights.size() > 20 ? 2 : 1);
}

std::string path_chart(const PreviewSummary& s) {
  std::vector<svg::PathSegment> segments;
  for (const auto& p : s.path())
    segments.push_back({p.start_mm.x(), p.start_mm.y(), p.end_mm.x(), p.end_mm.y(), p.max_error_mm});
  svg::ChartFrame f;
  f.height = 620;
  f.title = "Tool path (XY of the workpiece frame W) coloured by the block error (log scale)";
  f.x_label = "X (mm) →, Y (mm) ↑";
  return svg::path_plot(f, segments, s.max_error_mm(), "mm", 3);
}

std::string worst_table(const HtmlReport& r) {
  std::string t =
      "<table>\n<tr><th>#</th><th>block</th><th>CL line</th><th>error (mm)</th><th>at t</th>"
      "<th>harmonic Emax (mm)</th><th>orientation (&deg;)</th><th>source</th></tr>\n";
  const auto& worst = r.summary->worst();
  for (std::size_t i = 0; i < worst.size(); ++i) {
    const BlockRow& w = worst[i];
    t += fmt::format(
        "<tr><td>{}</td><td>{}</td><td>{}</td><td>{:.4f}</td><td>{:.3f}</td><td>{:.4f}</td><td>{:.4f}</td>"
        "<td class=\"src\">{}</td></tr>\n",
        i + 1, w.block, w.line, w.exact.max_error_mm, w.exact.at_t, w.harmonic_mm,
        rad_to_deg(w.exact.max_orientation_rad),
        svg::escape(i < r.worst_source_lines.size() ? r.worst_source_lines[i] : std::string()));
  }
  return t + "</table>\n";
}

std::string worst_curve_chart(const HtmlReport& r) {
  if (r.summary->worst().empty() || r.worst_curve_mm.size() < 2) return "<p class=\"note\">no block to show</p>\n";
  const BlockRow& w = r.summary->worst().front();
  svg::Series exact{"exact |e(t)|", "#1f5fa8", {}, {}, false};
  svg::Series midpoint{"harmonic, midpoint fit", "#d0702a", {}, {}, true};
  svg::Series peak{"harmonic, peak fit", "#2a9d4a", {}, {}, true};
  const std::size_t n = r.worst_curve_mm.size() - 1;
  for (std::size_t k = 0; k <= n; ++k) {
    const double t = static_cast<double>(k) / static_cast<double>(n);
    exact.x.push_back(t);
    exact.y.push_back(r.worst_curve_mm[k]);
    midpoint.x.push_back(t);
    midpoint.y.push_back(w.harmonic_mm * std::sin(kPi * t));
    peak.x.push_back(t);
    peak.y.push_back(w.exact.max_error_mm * std::sin(kPi * t));
  }
  svg::ChartFrame f;
  f.title = fmt::format("Block {} (CL line {}): exact error and the harmonic model Emax·sin(πt)", w.block, w.line);
  f.x_label = "t along the block (linear in axis space)";
  f.y_label = "error (mm)";
  return svg::line_chart(f, {exact, midpoint, peak});
}

}  // namespace

std::string render_html(const HtmlReport& r) {
  report::Provenance p;
  p.title = "Nonlinear error preview: " + r.input_name;
  p.machine = r.machine_name;
  p.model = r.model_name;
  p.inputs = r.inputs;
  std::string h = report::page_start(p) + style();
  h += "<p class=\"note\">The control interpolates every axis linearly between block ends (no RTCP): the tool tip "
       "leaves the straight CL segment in between. For each block: the exact largest distance of the executed tip "
       "from the segment (bracketed maximisation), and the harmonic model of seed 001, L(t) = Emax&middot;sin(&pi;t), "
       "with Emax from the deviation at mid-block.</p>\n";
  h += totals(r);
  h += "<h2>Error along the program</h2>\n" + series_chart(*r.summary);
  h += "<h2>Distribution</h2>\n" + histogram_chart(*r.summary);
  h += "<h2>Where on the part</h2>\n" + path_chart(*r.summary);
  h += "<h2>Worst blocks</h2>\n" + worst_table(r);
  h += "<h2>Harmonic model against the exact curve (worst block)</h2>\n" + worst_curve_chart(r);
  if (!r.stats.notices.empty()) {
    h += "<h2>Notices</h2>\n<ul class=\"note\">\n";
    std::size_t shown = 0;
    for (const auto& n : r.stats.notices) {
      if (++shown > 50) {
        h += fmt::format("<li>… {} more</li>\n", r.stats.notices.size() - 50);
        break;
      }
      h += "<li>" + svg::escape(n) + "</li>\n";
    }
    h += "</ul>\n";
  }
  return h + report::page_end();
}

std::vector<std::string> source_lines(const std::string& path, const std::vector<int>& lines) {
  std::map<int, std::string> wanted;
  for (int l : lines) wanted[l];
  std::ifstream in(path, std::ios::binary);
  std::string text;
  int n = 0;
  while (!wanted.empty() && std::getline(in, text)) {
    ++n;
    auto it = wanted.find(n);
    if (it != wanted.end()) {
      if (!text.empty() && text.back() == '\r') text.pop_back();
      it->second = text.substr(0, 200);
    }
    if (n > wanted.rbegin()->first) break;
  }
  std::vector<std::string> out;
  for (int l : lines) out.push_back(wanted[l]);
  return out;
}

}  // namespace ncpost::preview
