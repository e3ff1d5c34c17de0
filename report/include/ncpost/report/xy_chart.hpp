// SPDX-License-Identifier: Apache-2.0
#pragma once
// An x–y chart (SVG) with tick values on both axes, a zero line, and series drawn as lines with
// markers and optional error bars (lo … hi at each point) — the ISO 230-2 bidirectional plots
// (x̄↑, x̄↓ with ± 2s) and the laser error functions.
#include <string>
#include <vector>

namespace ncpost::report {

struct XySeries {
  std::string label, colour;
  std::vector<double> x, y;
  std::vector<double> lo, hi;  ///< error bars (same size as y), or empty
  bool dashed = false;
  bool markers = true;
};

struct XyFrame {
  std::string title, x_label, y_label;
  int width = 520, height = 300;
};

std::string xy_chart(const XyFrame& frame, const std::vector<XySeries>& series);

}  // namespace ncpost::report
