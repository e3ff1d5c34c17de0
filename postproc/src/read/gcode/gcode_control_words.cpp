// SPDX-License-Identifier: Apache-2.0
// Control-specific G codes (see gcode_control_words.hpp).
#include "ncpost/postproc/read/gcode/gcode_control_words.hpp"

#include <cmath>
#include <fmt/format.h>

namespace ncpost::gcode {
namespace {

bool is_switch(std::optional<double> v, double on) { return v && (*v == on || *v == 0.0); }

std::string number(double v) { return fmt::format("{}", v); }

/// A mode word that changes nothing the reader reads where it stands alone (dropped, with `dropped`
/// as the notice, "" none) and is refused beside axis or arc words.
struct ModeWord {
  int code10;
  const char* dropped;
  const char* with_geometry;
};

constexpr const char* kCancelWithAxes = "a cancel word (G15, G50.1, G69) with axis words is not supported";

// the cancel words of modes the reader refuses when they are switched on (scaling G51, rotation
// G68, polar coordinates G16, mirror image G51.1): in a safe-start line they change nothing
constexpr ModeWord kModeWords[] = {
    {500, "", "G50 with axis words (a lathe's coordinate setting) is not supported"},
    {690, "", kCancelWithAxes},
    {150, "", kCancelWithAxes},
    {501, "", kCancelWithAxes},
    // G97: spindle speed in rpm (constant surface speed G96 off), what S always is here
    {970, "", "G97 with axis words is not supported"},
    // Haas G187 P1..3 E<corner rounding>: the smoothness of the control's path
    {1870,
     "G187 (Haas smoothness and corner rounding) is a control mode word, not a motion: dropped (the posted program "
     "runs with its control's own setting)",
     "G187 with axis words is not supported"},
    // Haas G103 P<n>: limit block look-ahead
    {1030, "G103 (Haas block look-ahead limit) is a control mode word, not a motion: dropped",
     "G103 with axis words is not supported"},
};

/// G10 L..: the offsets the reader takes (work and tool offsets) pass; any other kind is refused.
ControlWord g10(std::optional<double> l) {
  // an L beyond any G10 form is no kind (and must not overflow the int cast)
  const int kind = l && std::abs(*l) < 1000.0 ? static_cast<int>(*l) : -1;
  if (kind == 2 || kind == 20) return {ControlWordAction::none, {}};  // work offsets (gcode_modal.cpp)
  if (kind == 1 || (kind >= 10 && kind <= 13))
    return {ControlWordAction::none, {}};  // tool offsets, as the dialect reads them (gcode_tool_offsets.hpp)
  return {ControlWordAction::refuse,
          "G10 (writing offsets or parameters from within the program) is not supported: remove it and give the "
          "part's position with --workpiece-origin"};
}

}  // namespace

ControlWord classify_control_word(int code10, bool axis_words, bool arc_words, std::optional<double> p,
                                  std::optional<double> q, std::optional<double> l) {
  const bool geometry = axis_words || arc_words;
  for (const ModeWord& m : kModeWords)
    if (m.code10 == code10)
      return geometry ? ControlWord{ControlWordAction::refuse, m.with_geometry}
                      : ControlWord{ControlWordAction::drop, m.dropped};
  switch (code10) {
    case 51:  // Fanuc G05.1 Q1/Q0; LinuxCNC G5.1 is a quadratic B-spline (I J with X Y)
      if (!geometry && is_switch(q, 1.0))
        return {ControlWordAction::drop,
                fmt::format("G05.1 Q{} (Fanuc AI contour control: look-ahead) is a control mode word, not a motion: "
                            "dropped (the posted program runs with its control's own look-ahead setting)",
                            number(*q))};
      return {ControlWordAction::refuse,
              "G5.1 with axis words (a quadratic B-spline) is not supported: post the CL data, or have the CAM "
              "system write the spline as G1/G2/G3 blocks"};
    case 50:  // Fanuc G05 P10000/P0; LinuxCNC G5 is a cubic spline (I J P Q with X Y)
      if (!geometry && !q && is_switch(p, 10000.0))
        return {ControlWordAction::drop,
                fmt::format("G05 P{} (Fanuc high-speed high-precision contour control) is a control mode word, not "
                            "a motion: dropped",
                            number(*p))};
      return {ControlWordAction::refuse,
              "G5 with axis words (a cubic spline) is not supported: post the CL data, or have the CAM system write "
              "the spline as G1/G2/G3 blocks"};
    case 80:  // Fanuc G08 P1/P0; LinuxCNC G8 is lathe radius mode
      if (!geometry && is_switch(p, 1.0))
        return {ControlWordAction::drop,
                fmt::format("G08 P{} (Fanuc advanced preview control: look-ahead) is a control mode word, not a "
                            "motion: dropped",
                            number(*p))};
      return {ControlWordAction::none, {}};
    case 700:
      if (p || q) return {ControlWordAction::refuse, "G70 with P/Q (a lathe finishing cycle) is not supported"};
      return {ControlWordAction::length_inch,
              "G70 (Sinumerik): lengths are read in inch; feeds stay in the control's basic unit (mm unless --units "
              "inch); use G700 if the feeds are in inch too"};
    case 710:
      if (p || q) return {ControlWordAction::refuse, "G71 with P/Q (a lathe roughing cycle) is not supported"};
      return {ControlWordAction::length_mm,
              "G71 (Sinumerik): lengths are read in mm; feeds stay in the control's basic unit (mm unless --units "
              "inch)"};
    case 7000:
      return {ControlWordAction::units_inch, {}};
    case 7100:
      return {ControlWordAction::units_mm, {}};
    case 100:
      return g10(l);
    case 960:  // G96: constant surface speed (S in m/min or ft/min)
      return {ControlWordAction::refuse,
              "G96 (constant surface speed: S in m/min or ft/min) is not supported: program the speed in rpm (G97)"};
    default:
      return {ControlWordAction::none, {}};
  }
}

}  // namespace ncpost::gcode
