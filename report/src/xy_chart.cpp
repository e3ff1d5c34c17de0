// SPDX-License-Identifier: Apache-2.0
#include "ncpost/report/xy_chart.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ncpost/report/colour_scale.hpp"
#include "ncpost/report/html_page.hpp"

namespace ncpost::report {

std::string xy_chart(const XyFrame& f, const std::vector<XySeries>& series) {
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (const auto& s : series)
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      x0 = std::min(x0, s.x[i]);
      x1 = std::max(x1, s.x[i]);
      const double lo = i < s.lo.size() ? s.lo[i] : s.y[i], hi = i < s.hi.size() ? s.hi[i] : s.y[i];
      y0 = std::min({y0, s.y[i], lo});
      y1 = std::max({y1, s.y[i], hi});
    }
  if (!std::isfinite(x0)) x0 = 0, x1 = 1;
  if (!std::isfinite(y0)) y0 = 0, y1 = 1;
  y0 = std::min(y0, 0.0);
  y1 = std::max(y1, 0.0);
  if (!(x1 > x0)) x0 -= 0.5, x1 += 0.5;
  if (!(y1 > y0)) y1 = y0 + 1.0;
  const double pad = 0.06 * (y1 - y0);
  y0 -= pad, y1 += pad;
  const double L = 62, T = 44, W = f.width - L - 14, H = f.height - T - 44;
  auto X = [&](double x) { return L + W * (x - x0) / (x1 - x0); };
  auto Y = [&](double y) { return T + H * (1.0 - (y - y0) / (y1 - y0)); };
  std::string s = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"xy\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" "
      "font-family=\"sans-serif\" font-size=\"11\"><rect width=\"{0}\" height=\"{1}\" fill=\"#fff\"/>",
      f.width, f.height);
  s += fmt::format("<text x=\"6\" y=\"15\" font-size=\"13\" font-weight=\"bold\">{}</text>", escape(f.title));
  s += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#888\"/>", L, T, W, H);
  for (double t : nice_ticks(y0, y1, 5)) {
    s += fmt::format("<line x1=\"{}\" y1=\"{:.1f}\" x2=\"{}\" y2=\"{:.1f}\" stroke=\"{}\"/>", L, Y(t), L + W, Y(t),
                     t == 0 ? "#999" : "#ececec");
    s += fmt::format("<text x=\"{}\" y=\"{:.1f}\" text-anchor=\"end\">{}</text>", L - 4, Y(t) + 4, format_tick(t));
  }
  for (double t : nice_ticks(x0, x1, 6)) {
    s += fmt::format("<line x1=\"{0:.1f}\" y1=\"{1}\" x2=\"{0:.1f}\" y2=\"{2}\" stroke=\"#888\"/>", X(t), T + H,
                     T + H + 4);
    s += fmt::format("<text x=\"{:.1f}\" y=\"{}\" text-anchor=\"middle\">{}</text>", X(t), T + H + 16, format_tick(t));
  }
  s += fmt::format("<text x=\"{:.1f}\" y=\"{}\" text-anchor=\"middle\">{}</text>", L + W / 2, f.height - 6,
                   escape(f.x_label));
  s += fmt::format("<text transform=\"translate(14,{:.1f}) rotate(-90)\" text-anchor=\"middle\">{}</text>", T + H / 2,
                   escape(f.y_label));
  double lx = L;
  for (const auto& line : series) {
    std::string pts;
    for (std::size_t i = 0; i < line.x.size() && i < line.y.size(); ++i) {
      pts += fmt::format("{:.1f},{:.1f} ", X(line.x[i]), Y(line.y[i]));
      if (i < line.lo.size() && i < line.hi.size())
        s += fmt::format(
            "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\" stroke=\"{3}\" stroke-width=\"1\"/>"
            "<line x1=\"{4:.1f}\" y1=\"{1:.1f}\" x2=\"{5:.1f}\" y2=\"{1:.1f}\" stroke=\"{3}\"/>"
            "<line x1=\"{4:.1f}\" y1=\"{2:.1f}\" x2=\"{5:.1f}\" y2=\"{2:.1f}\" stroke=\"{3}\"/>",
            X(line.x[i]), Y(line.lo[i]), Y(line.hi[i]), line.colour, X(line.x[i]) - 3, X(line.x[i]) + 3);
      if (line.markers)
        s += fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"2.4\" fill=\"{}\"/>", X(line.x[i]), Y(line.y[i]),
                         line.colour);
    }
    s += fmt::format("<polyline points=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"1.5\"{}/>", pts, line.colour,
                     line.dashed ? " stroke-dasharray=\"5,3\"" : "");
    s += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"32\" x2=\"{1:.1f}\" y2=\"32\" stroke=\"{2}\" stroke-width=\"2\"{3}/>"
        "<text x=\"{4:.1f}\" y=\"36\">{5}</text>",
        lx, lx + 16, line.colour, line.dashed ? " stroke-dasharray=\"5,3\"" : "", lx + 20, escape(line.label));
    lx += 30 + 6.0 * static_cast<double>(line.label.size());
  }
  return s + "</svg>";
}

}  // namespace ncpost::report
