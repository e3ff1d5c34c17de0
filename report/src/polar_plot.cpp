// SPDX-License-Identifier: Apache-2.0
#include "ncpost/report/polar_plot.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ncpost/report/colour_scale.hpp"
#include "ncpost/report/html_page.hpp"

namespace ncpost::report {

std::string polar_plot(const PolarFrame& f, const std::vector<PolarTrace>& traces) {
  double span = f.scale_span;
  if (!(span > 0)) {
    for (const auto& t : traces)
      for (double v : t.value)
        if (std::isfinite(v)) span = std::max(span, std::abs(v));
    if (!(span > 0)) span = 1.0;
    const std::vector<double> ticks = nice_ticks(0.0, span, 2);
    const double step = ticks.size() >= 2 ? ticks[1] - ticks[0] : span;
    span = std::ceil(span / step - 1e-9) * step;
  }
  const double size = f.size, c = size / 2.0, cy = c + 34.0;
  const double outer = c - 40.0, r0 = outer / 2.0, gain = (outer - r0) / span;  // ±span about the base circle
  auto radius = [&](double v) { return std::max(2.0, r0 + gain * std::clamp(v, -1.2 * span, 1.2 * span)); };
  const double height = size + 70.0;
  std::string s = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"polar\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" "
      "font-family=\"sans-serif\" font-size=\"11\"><rect width=\"{0}\" height=\"{1}\" fill=\"#fff\"/>",
      size, height);
  s += fmt::format("<text x=\"6\" y=\"15\" font-size=\"13\" font-weight=\"bold\">{}</text>", escape(f.title));
  s += fmt::format("<text x=\"6\" y=\"30\" fill=\"#444\">{}</text>", escape(f.subtitle));
  // spokes every 30°, labelled with the axis and angle
  for (int d = 0; d < 360; d += 30) {
    const double a = d * 3.141592653589793 / 180.0;
    s += fmt::format("<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"#e2e2e2\"/>", c, cy,
                     c + outer * std::cos(a), cy - outer * std::sin(a));
    const double lx = c + (outer + 14) * std::cos(a), ly = cy - (outer + 14) * std::sin(a) + 4;
    s += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\" fill=\"#555\">{}{}°</text>", lx, ly,
                     d == 0 ? escape(f.angle_axis) + " " : "", d);
  }
  // rings: −span … +span; the base circle (0) drawn darker
  for (double t : nice_ticks(-span, span, 4)) {
    const double rr = r0 + gain * t;
    if (rr <= 1) continue;
    s += fmt::format(
        "<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"{:.1f}\" fill=\"none\" stroke=\"{}\" stroke-width=\"{}\"/>", c, cy, rr,
        t == 0 ? "#999" : "#d4d4d4", t == 0 ? 1.2 : 0.7);
    s += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" fill=\"#777\" font-size=\"10\">{}{}</text>", c + 3, cy - rr - 2,
                     t > 0 ? "+" : "", format_tick(t) + (t == span ? " " + escape(f.unit) : std::string()));
  }
  for (const auto& t : traces) {
    std::string d;
    for (std::size_t k = 0; k < t.angle_rad.size() && k < t.value.size(); ++k) {
      if (!std::isfinite(t.value[k])) continue;
      const double rr = radius(t.value[k]);
      d += fmt::format("{}{:.2f},{:.2f} ", d.empty() ? "M" : "L", c + rr * std::cos(t.angle_rad[k]),
                       cy - rr * std::sin(t.angle_rad[k]));
    }
    s += fmt::format("<path d=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"1.4\"{}/>", d, t.colour,
                     t.dashed ? " stroke-dasharray=\"5,3\"" : "");
  }
  double lx = 6;
  for (const auto& t : traces) {
    s += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" stroke=\"{3}\" stroke-width=\"2\"{4}/>"
        "<text x=\"{5:.1f}\" y=\"{6:.1f}\">{7}</text>",
        lx, height - 12, lx + 18, t.colour, t.dashed ? " stroke-dasharray=\"5,3\"" : "", lx + 22, height - 8,
        escape(t.label));
    lx += 34 + 6.2 * static_cast<double>(t.label.size());
  }
  s += fmt::format(
      "<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"end\" fill=\"#777\" font-size=\"10\">{} per ring</text>", size - 6,
      height - 24,
      format_tick(nice_ticks(-span, span, 4).size() >= 2 ? nice_ticks(-span, span, 4)[1] - nice_ticks(-span, span, 4)[0]
                                                         : span) +
          " " + escape(f.unit));
  return s + "</svg>";
}

}  // namespace ncpost::report
