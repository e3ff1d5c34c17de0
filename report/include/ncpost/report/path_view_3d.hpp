// SPDX-License-Identifier: Apache-2.0
#pragma once
// A 3D view of tool paths in the HTML page itself: WebGL in an inline script (no network, no
// external JS), one canvas per path, coloured by a value on a shared colour scale with its colour
// bar; drag with the mouse to turn all views together, wheel to zoom. After the first drawing
// each canvas carries data-drawn-pixels (the coloured pixels it shows), so that a test reading
// the DOM can tell a drawn view from an empty one.
#include <string>
#include <vector>

#include "ncpost/report/colour_scale.hpp"

namespace ncpost::report {

struct PathPoint3 {
  double x = 0, y = 0, z = 0;  ///< mm
};

struct PathView3d {
  std::string id;     ///< the canvas id (letters, digits, '-')
  std::string title;  ///< shown above the canvas
  std::vector<PathPoint3> points;
  std::vector<double> values;  ///< at each point: the value of the segment that ends there (the scale's unit)
};

/// The canvases, the colour bar (of `scale`, titled `bar_title`) and the script.
std::string path_view_3d(const std::vector<PathView3d>& views, const ColourScale& scale, const std::string& bar_title);

}  // namespace ncpost::report
