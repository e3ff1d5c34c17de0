// SPDX-License-Identifier: Apache-2.0
#pragma once
// A polar plot (SVG) as a ballbar report draws it: the radial deviation (µm) against the angle,
// about a base circle, with rings labelled in µm, spokes labelled in degrees of the angle's axis
// (0° to the right, counter-clockwise positive), the axes that moved and the test's feed and
// direction under the title.
#include <string>
#include <vector>

namespace ncpost::report {

struct PolarTrace {
  std::string label, colour;
  std::vector<double> angle_rad, value;  ///< value in the plot's unit
  bool dashed = false;
};

struct PolarFrame {
  std::string title;
  std::string subtitle;    ///< e.g. "axes moved: Y Z A C; C 86.4°/min counter-clockwise"
  std::string angle_axis;  ///< e.g. "C": spokes read "C 30°"
  std::string unit = "µm";
  double scale_span = 0.0;  ///< ± range of the rings (0: from the data, rounded up)
  int size = 380;
};

std::string polar_plot(const PolarFrame& frame, const std::vector<PolarTrace>& traces);

}  // namespace ncpost::report
