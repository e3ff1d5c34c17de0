// SPDX-License-Identifier: Apache-2.0
#include "ncpost/report/colour_scale.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "ncpost/report/html_page.hpp"

namespace ncpost::report {

void colour_rgb(double fraction, int rgb[3]) {
  static constexpr std::array<std::array<double, 3>, 5> stops{
      {{30, 50, 140}, {20, 150, 160}, {150, 200, 60}, {245, 160, 30}, {200, 30, 30}}};
  const double f = std::clamp(std::isfinite(fraction) ? fraction : 0.0, 0.0, 1.0) * (stops.size() - 1);
  const std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(f), stops.size() - 2);
  const double w = f - static_cast<double>(i);
  for (int k = 0; k < 3; ++k) rgb[k] = static_cast<int>(std::lround(stops[i][k] * (1 - w) + stops[i + 1][k] * w));
}

std::string colour(double fraction) {
  int rgb[3];
  colour_rgb(fraction, rgb);
  return fmt::format("#{:02x}{:02x}{:02x}", rgb[0], rgb[1], rgb[2]);
}

std::vector<double> nice_ticks(double lo, double hi, int count) {
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return {lo};
  const double raw = (hi - lo) / std::max(count, 1);
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = mag;
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if (m * mag >= raw) {
      step = m * mag;
      break;
    }
  std::vector<double> ticks;
  for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + step * 1e-9; t += step)
    ticks.push_back(std::abs(t) < step * 1e-9 ? 0.0 : t);
  return ticks;
}

std::string format_tick(double v) {
  if (v == 0) return "0";
  const double a = std::abs(v);
  if (a >= 1e4 || a < 1e-3) return fmt::format("{:.1e}", v);
  if (a >= 100) return fmt::format("{:.0f}", v);
  return fmt::format("{:.3g}", v);
}

double ColourScale::fraction(double value) const {
  if (all_zero || !(top > 0)) return 0.0;
  return std::clamp(std::abs(value) / top, 0.0, 1.0);
}

ColourScale colour_scale_for(double largest, const std::string& unit) {
  ColourScale s;
  s.unit = unit;
  if (!(largest > 0) || !std::isfinite(largest)) {
    s.all_zero = true;
    s.top = 1.0;
    return s;
  }
  const std::vector<double> ticks = nice_ticks(0.0, largest, 5);
  const double step = ticks.size() >= 2 ? ticks[1] - ticks[0] : largest;
  s.top = std::max(largest, std::ceil(largest / step - 1e-9) * step);
  return s;
}

std::string colour_bar_svg(const ColourScale& s, double height, const std::string& title) {
  const double top = 24, bar_h = height - 40, x = 10, w = 16;
  std::string o = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"colour-bar\" width=\"96\" height=\"{0}\" viewBox=\"0 0 96 "
      "{0}\" "
      "font-family=\"sans-serif\" font-size=\"11\"><rect width=\"96\" height=\"{0}\" fill=\"#fff\"/>",
      height);
  o += fmt::format("<text x=\"2\" y=\"14\">{} ({})</text>", escape(title), escape(s.unit));
  const int n = 64;
  for (int i = 0; i < n; ++i)
    o += fmt::format("<rect x=\"{}\" y=\"{:.2f}\" width=\"{}\" height=\"{:.2f}\" fill=\"{}\"/>", x, top + bar_h * i / n,
                     w, bar_h / n + 0.6, colour(1.0 - (i + 0.5) / n));
  o += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#666\"/>", x, top, w,
                   bar_h);
  for (double t : nice_ticks(0.0, s.top, 5)) {
    const double y = top + bar_h * (1.0 - t / s.top);
    o += fmt::format(
        "<line x1=\"{}\" y1=\"{:.1f}\" x2=\"{}\" y2=\"{:.1f}\" stroke=\"#444\"/><text x=\"{}\" y=\"{:.1f}\">{}</text>",
        x + w, y, x + w + 4, y, x + w + 7, y + 4, format_tick(t));
  }
  if (s.all_zero) o += fmt::format("<text x=\"2\" y=\"{:.1f}\" fill=\"#c0241b\">all 0</text>", height - 4);
  return o + "</svg>";
}

std::string diverging_colour(double f) {
  f = std::clamp(std::isfinite(f) ? f : 0.0, -1.0, 1.0);
  const auto mix = [](double a, double b, double t) { return static_cast<int>(std::lround(a + (b - a) * t)); };
  int r, g, b;
  if (f < 0) {
    r = mix(255, 33, -f), g = mix(255, 102, -f), b = mix(255, 172, -f);
  } else {
    r = mix(255, 178, f), g = mix(255, 24, f), b = mix(255, 43, f);
  }
  return fmt::format("#{:02x}{:02x}{:02x}", r, g, b);
}

std::string diverging_bar_svg(double span, const std::string& unit, double width, bool no_effect) {
  const double x0 = 30, w = width - 60, y = 4, h = 10;
  std::string o = fmt::format(
      "<svg class=\"colour-bar\" width=\"{0}\" height=\"32\" viewBox=\"0 0 {0} 32\" "
      "font-family=\"sans-serif\" font-size=\"10\">",
      width);
  const int n = 40;
  for (int i = 0; i < n; ++i)
    o += fmt::format("<rect x=\"{:.2f}\" y=\"{}\" width=\"{:.2f}\" height=\"{}\" fill=\"{}\"/>", x0 + w * i / n, y,
                     w / n + 0.5, h, diverging_colour(-1.0 + 2.0 * (i + 0.5) / n));
  o += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#666\"/>", x0, y, w, h);
  const std::string s = no_effect ? format_tick(kNoEffectUm) : format_tick(span);
  o += fmt::format(
      "<text x=\"{}\" y=\"27\" text-anchor=\"middle\">−{}</text><text x=\"{}\" y=\"27\" "
      "text-anchor=\"middle\">0</text><text x=\"{}\" y=\"27\" text-anchor=\"middle\">+{} {}</text>",
      x0, s, x0 + w / 2, x0 + w, s, escape(unit));
  if (no_effect) o += fmt::format("<text x=\"{}\" y=\"27\" fill=\"#c0241b\">no effect</text>", x0 + w / 2 + 12);
  return o + "</svg>";
}

}  // namespace ncpost::report
