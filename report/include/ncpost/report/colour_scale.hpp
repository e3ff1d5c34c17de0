// SPDX-License-Identifier: Apache-2.0
#pragma once
// The colour scale of every map in the reports and its colour bar. The scale runs from 0 to a
// maximum in the unit of the map (µm); a map whose values are all zero is drawn with the colour
// of zero on a bar that still starts at 0 (never stretched to saturate the largest colour).
#include <string>
#include <vector>

namespace ncpost::report {

/// "#rrggbb" for a fraction in [0, 1] (dark blue → teal → yellow-green → orange → red).
std::string colour(double fraction);
/// The same colour as three 0..255 components.
void colour_rgb(double fraction, int rgb[3]);

/// About `count` round tick values covering [lo, hi].
std::vector<double> nice_ticks(double lo, double hi, int count);
/// A tick label: 3 significant digits, no exponent between 1e-3 and 1e4.
std::string format_tick(double value);

/// Linear scale from 0 to `top` (top > 0: the largest value, rounded up to a round tick).
struct ColourScale {
  double top = 1.0;
  std::string unit = "µm";
  bool all_zero = false;  ///< every value was 0: the map shows zero, the bar says so
  double fraction(double value) const;
};
/// The scale of values whose largest magnitude is `largest` (0 or less: all zero, top 1 unit).
ColourScale colour_scale_for(double largest, const std::string& unit);

/// A vertical colour bar (SVG, width ~90 px) with ticks in the scale's unit.
std::string colour_bar_svg(const ColourScale& scale, double height_px, const std::string& title);

/// Signed maps: blue (−1) → white (0) → red (+1), as "#rrggbb".
std::string diverging_colour(double fraction);

/// Below this largest |value| (µm) a map has no effect: it is drawn as zero (white), never
/// stretched to saturate its colours with rounding noise.
constexpr double kNoEffectUm = 1e-3;

/// A horizontal diverging colour bar (SVG, `width` px) from −span to +span in `unit`; with
/// `no_effect` it says so and labels ±kNoEffectUm.
std::string diverging_bar_svg(double span, const std::string& unit, double width, bool no_effect);

}  // namespace ncpost::report
