// SPDX-License-Identifier: Apache-2.0
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ncpost/postproc/verify/preview_svg.hpp"
#include "ncpost/report/colour_scale.hpp"
#include "ncpost/report/html_page.hpp"

namespace ncpost::preview::svg {
namespace {

struct Box {
  double left, top, width, height;
};

Box plot_box(const ChartFrame& f) { return {70.0, 34.0, f.width - 90.0, f.height - 78.0}; }

std::string open_svg(const ChartFrame& f) {
  std::string s = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" "
      "font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"{0}\" height=\"{1}\" fill=\"#ffffff\"/>\n",
      f.width, f.height);
  if (!f.title.empty())
    s += fmt::format("<text x=\"{}\" y=\"20\" font-size=\"15\" font-weight=\"bold\">{}</text>\n", 10, escape(f.title));
  return s;
}

std::string format_tick(double v) { return report::format_tick(v); }

std::string axes(const ChartFrame& f, const Box& b, double x0, double x1, double y0, double y1, bool x_ticks = true) {
  std::string s;
  s += fmt::format(
      "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" fill=\"none\" stroke=\"#888\"/>\n", b.left,
      b.top, b.width, b.height);
  for (double t : nice_ticks(y0, y1, 5)) {
    const double y = b.top + b.height * (1.0 - (t - y0) / (y1 - y0));
    s += fmt::format("<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"#e4e4e4\"/>\n", b.left, y,
                     b.left + b.width, y);
    s += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"end\">{}</text>\n", b.left - 5, y + 4,
                     format_tick(t));
  }
  if (x_ticks) {
    for (double t : nice_ticks(x0, x1, 8)) {
      const double x = b.left + b.width * (t - x0) / (x1 - x0);
      s += fmt::format("<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\" stroke=\"#888\"/>\n", x,
                       b.top + b.height, b.top + b.height + 4);
      s += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{}</text>\n", x, b.top + b.height + 17,
                       format_tick(t));
    }
  }
  s += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{}</text>\n", b.left + b.width / 2,
                   f.height - 8.0, escape(f.x_label));
  s += fmt::format("<text transform=\"translate(16,{:.1f}) rotate(-90)\" text-anchor=\"middle\">{}</text>\n",
                   b.top + b.height / 2, escape(f.y_label));
  return s;
}

}  // namespace

std::string escape(const std::string& text) { return report::escape(text); }

std::string colour(double fraction) { return report::colour(fraction); }

std::vector<double> nice_ticks(double lo, double hi, int count) { return report::nice_ticks(lo, hi, count); }

std::string line_chart(const ChartFrame& f, const std::vector<Series>& series) {
  const Box b = plot_box(f);
  double x0 = INFINITY, x1 = -INFINITY, y0 = 0.0, y1 = -INFINITY;
  for (const Series& s : series)
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      x0 = std::min(x0, s.x[i]);
      x1 = std::max(x1, s.x[i]);
      y0 = std::min(y0, s.y[i]);
      y1 = std::max(y1, s.y[i]);
    }
  if (!(x1 > x0)) {
    x0 = std::isfinite(x0) ? x0 - 0.5 : 0.0;
    x1 = x0 + 1.0;
  }
  if (!(y1 > y0)) y1 = y0 + 1.0;
  y1 += 0.05 * (y1 - y0);
  std::string s = open_svg(f) + axes(f, b, x0, x1, y0, y1);
  double legend_x = b.left + 10;
  for (const Series& line : series) {
    std::string points;
    for (std::size_t i = 0; i < line.x.size(); ++i)
      points += fmt::format("{:.2f},{:.2f} ", b.left + b.width * (line.x[i] - x0) / (x1 - x0),
                            b.top + b.height * (1.0 - (line.y[i] - y0) / (y1 - y0)));
    s += fmt::format("<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"1.6\"{} points=\"{}\"/>\n", line.colour,
                     line.dashed ? " stroke-dasharray=\"6,4\"" : "", points);
    s += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" stroke=\"{3}\" stroke-width=\"2\"{4}/>"
        "<text x=\"{5:.1f}\" y=\"{6:.1f}\">{7}</text>\n",
        legend_x, b.top + 12, legend_x + 24, line.colour, line.dashed ? " stroke-dasharray=\"6,4\"" : "", legend_x + 30,
        b.top + 16, escape(line.label));
    legend_x += 40 + 7.0 * static_cast<double>(line.label.size());
  }
  return s + "</svg>\n";
}

std::string bar_chart(const ChartFrame& f, const std::vector<double>& heights, const std::vector<std::string>& labels,
                      const std::vector<std::string>& colours, int label_every) {
  const Box b = plot_box(f);
  double y1 = 0.0;
  for (double h : heights) y1 = std::max(y1, h);
  if (y1 <= 0) y1 = 1.0;
  y1 *= 1.05;
  std::string s = open_svg(f) + axes(f, b, 0, 1, 0, y1, false);
  const double w = b.width / std::max<std::size_t>(heights.size(), 1);
  for (std::size_t i = 0; i < heights.size(); ++i) {
    const double h = b.height * heights[i] / y1;
    s += fmt::format("<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"{}\"/>\n",
                     b.left + w * i + 1, b.top + b.height - h, std::max(w - 2, 1.0), h,
                     i < colours.size() ? colours[i] : std::string("#4a7ab5"));
    if (i < labels.size() && label_every > 0 && i % static_cast<std::size_t>(label_every) == 0)
      s += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\" font-size=\"10\">{}</text>\n",
                       b.left + w * (i + 0.5), b.top + b.height + 15, escape(labels[i]));
  }
  return s + "</svg>\n";
}

namespace {

/// The plot's scale from the segments' bounds, equal aspect: the larger span fills its side.
struct PathScale {
  double span = 1.0;  ///< mm across
  double scale = 1.0;
  double cx = 0.0, cy = 0.0;
};

PathScale path_scale(const Box& b, const std::vector<PathSegment>& segments) {
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (const PathSegment& p : segments) {
    x0 = std::min({x0, p.x0, p.x1});
    x1 = std::max({x1, p.x0, p.x1});
    y0 = std::min({y0, p.y0, p.y1});
    y1 = std::max({y1, p.y0, p.y1});
  }
  if (!std::isfinite(x0)) {
    x0 = y0 = 0;
    x1 = y1 = 1;
  }
  PathScale ps;
  ps.span = std::max({x1 - x0, (y1 - y0) * b.width / b.height, 1e-9});
  ps.scale = b.width / ps.span;
  ps.cx = 0.5 * (x0 + x1), ps.cy = 0.5 * (y0 + y1);
  return ps;
}

/// The colour bar right of the box: 0 (or vmin) to vmax, linear or over log_decades decades.
std::string colour_bar(const Box& b, double vmax, double vmin, const std::string& unit, int log_decades) {
  std::string s;
  const double bar_x = b.left + b.width + 25;
  for (int i = 0; i < 50; ++i) {
    const double frac = 1.0 - i / 49.0;
    s += fmt::format("<rect x=\"{:.1f}\" y=\"{:.2f}\" width=\"14\" height=\"{:.2f}\" fill=\"{}\"/>\n", bar_x,
                     b.top + b.height * i / 50.0, b.height / 50.0 + 0.5, colour(frac));
  }
  s += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\">{} {}</text>\n", bar_x - 5, b.top - 6, format_tick(vmax),
                   escape(unit));
  if (log_decades > 0) {
    for (int d = 1; d < log_decades; ++d)
      s += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\">{}</text>\n", bar_x + 18,
                       b.top + b.height * d / log_decades + 4, format_tick(vmax * std::pow(10.0, -d)));
    s += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\">&#8804;{}</text>\n", bar_x + 18, b.top + b.height,
                     format_tick(vmin));
  } else {
    s += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\">0</text>\n", bar_x + 18, b.top + b.height);
  }
  return s;
}

}  // namespace

std::string path_plot(const ChartFrame& f, const std::vector<PathSegment>& segments, double value_max,
                      const std::string& unit, int log_decades) {
  Box b = plot_box(f);
  b.width -= 100;  // colour bar and its labels
  const PathScale ps = path_scale(b, segments);
  auto px = [&](double x) { return b.left + b.width / 2 + (x - ps.cx) * ps.scale; };
  auto py = [&](double y) { return b.top + b.height / 2 - (y - ps.cy) * ps.scale; };
  std::string s = open_svg(f);
  s += fmt::format(
      "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" fill=\"none\" stroke=\"#888\"/>\n", b.left,
      b.top, b.width, b.height);
  const double vmax = value_max > 0 ? value_max : 1.0;
  const double vmin = log_decades > 0 ? vmax * std::pow(10.0, -log_decades) : 0.0;
  auto fraction = [&](double v) {
    if (log_decades <= 0) return v / vmax;
    return v <= vmin ? 0.0 : std::log10(v / vmin) / log_decades;
  };
  // low values first so that the worst segments are drawn on top
  std::vector<std::size_t> order(segments.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t l, std::size_t r) { return segments[l].value < segments[r].value; });
  for (std::size_t i : order) {
    const PathSegment& p = segments[i];
    s += fmt::format(
        "<line x1=\"{:.2f}\" y1=\"{:.2f}\" x2=\"{:.2f}\" y2=\"{:.2f}\" stroke=\"{}\" stroke-width=\"1.8\" "
        "stroke-linecap=\"round\"/>\n",
        px(p.x0), py(p.y0), px(p.x1), py(p.y1), colour(fraction(p.value)));
  }
  s += colour_bar(b, vmax, vmin, unit, log_decades);
  s += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{}</text>\n", b.left + b.width / 2,
                   f.height - 8.0, escape(f.x_label));
  s += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{:.4g} mm across</text>\n",
                   b.left + b.width / 2, f.height - 24.0, ps.span);
  return s + "</svg>\n";
}

}  // namespace ncpost::preview::svg
