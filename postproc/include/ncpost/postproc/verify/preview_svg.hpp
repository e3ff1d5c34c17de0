// SPDX-License-Identifier: Apache-2.0
#pragma once
// Inline SVG charts for the self-contained HTML reports (no scripts, no network): a line chart,
// a bar chart, an XY path coloured by a value, and the colour scale they share. Sizes in CSS px.
// escape, colour and nice_ticks are those of the reports layer (ncpost/report/), named here for
// the preview's charts.
#include <string>
#include <vector>

namespace ncpost::preview::svg {

/// Text escaped for HTML/SVG content and attributes.
std::string escape(const std::string& text);

/// "#rrggbb" for a fraction in [0, 1] of the colour scale (dark blue → teal → yellow-green → orange → red).
std::string colour(double fraction);

/// About `count` round tick values covering [lo, hi].
std::vector<double> nice_ticks(double lo, double hi, int count);

struct Series {
  std::string label;
  std::string colour;
  std::vector<double> x, y;
  bool dashed = false;
};

struct ChartFrame {
  int width = 1000, height = 280;
  std::string title, x_label, y_label;
};

/// Lines over a common x; y from 0 (or the data's minimum if negative) to the largest value.
std::string line_chart(const ChartFrame& frame, const std::vector<Series>& series);

/// Bars with a text label under each (every `label_every`-th shown); y linear from 0.
std::string bar_chart(const ChartFrame& frame, const std::vector<double>& heights,
                      const std::vector<std::string>& labels, const std::vector<std::string>& colours,
                      int label_every = 1);

struct PathSegment {
  double x0, y0, x1, y1;
  double value;  ///< coloured on [0, value_max]
};

/// Segments in an equal-aspect XY frame, coloured by value, with a colour bar labelled in `unit`;
/// `log_decades` > 0: logarithmic colours over that many decades below value_max.
std::string path_plot(const ChartFrame& frame, const std::vector<PathSegment>& segments, double value_max,
                      const std::string& unit, int log_decades = 0);

}  // namespace ncpost::preview::svg
