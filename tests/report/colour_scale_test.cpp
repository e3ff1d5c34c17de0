// SPDX-License-Identifier: Apache-2.0
// The colour scale of the maps: a map of zeros is drawn with the colour of zero on a bar that
// says so; a map with values runs from 0 to a round top at or above its largest value.
#include <catch2/catch.hpp>

#include "ncpost/report/colour_scale.hpp"

using namespace ncpost::report;

TEST_CASE("a zero-effect map is drawn as zero, not saturated", "[report][colour]") {
  const ColourScale zero = colour_scale_for(0.0, "µm");
  CHECK(zero.all_zero);
  CHECK(zero.fraction(0.0) == 0.0);
  CHECK(zero.fraction(1e-14) == 0.0);  // rounding noise stays at the colour of zero
  CHECK(colour(zero.fraction(1e-14)) == colour(0.0));
  const std::string bar = colour_bar_svg(zero, 300, "error");
  CHECK(bar.find(">all 0</text>") != std::string::npos);
  CHECK(bar.find(">0</text>") != std::string::npos);
  CHECK(diverging_colour(0.0) == "#ffffff");
  CHECK(diverging_bar_svg(1e-9, "µm", 200, true).find("no effect") != std::string::npos);
}

TEST_CASE("a map's scale runs from 0 to a round top", "[report][colour]") {
  const ColourScale s = colour_scale_for(1.8, "µm");
  CHECK_FALSE(s.all_zero);
  CHECK(s.top == Approx(2.0));
  CHECK(s.fraction(1.0) == Approx(0.5));
  CHECK(s.fraction(5.0) == 1.0);
  CHECK(colour(0.0) == "#1e328c");
  CHECK(colour(1.0) == "#c81e1e");
  const std::string bar = colour_bar_svg(s, 300, "contour error");
  for (const char* t : {">0</text>", ">0.5</text>", ">1</text>", ">1.5</text>", ">2</text>"}) {
    INFO(t);
    CHECK(bar.find(t) != std::string::npos);
  }
  CHECK(bar.find("contour error (µm)") != std::string::npos);
}
