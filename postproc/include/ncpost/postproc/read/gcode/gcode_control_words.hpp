// SPDX-License-Identifier: Apache-2.0
#pragma once
// G codes whose meaning depends on the control that wrote the program, and that the modal
// interpreter does not handle as motion or a modal group of its own:
//   - look-ahead / contour-control mode words with no geometry: Fanuc G05.1 Q1|Q0 (AI contour
//     control), G05 P10000|P0 (high-speed high-precision), G08 P1|P0 (advanced preview): dropped
//     with a notice (the posted program's control keeps its own setting);
//   - Sinumerik G70/G71 (lengths in inch/mm, feeds stay in the control's basic unit) and
//     G700/G710 (lengths and feeds in inch/mm);
//   - G10 forms other than L2/L20 (work offsets) and L1, L10-L13 (tool offsets, read as the dialect
//     says: gcode_tool_offsets.hpp): refused with what to do;
//   - the cancel words of refused modes (G15, G50, G50.1, G69) and G97 (rpm, constant surface
//     speed G96 off) without geometry: nothing to do; G96 itself is refused;
//     Haas G187 P E (smoothness; its E is read only there) and G103 P (look-ahead): dropped.
// The same numbers mean other things on other controls (LinuxCNC G5/G5.1 splines, G7/G8 lathe
// modes): those are recognised by their words (I J P Q with axis words) and refused as such.
#include <optional>
#include <string>

namespace ncpost::gcode {

enum class ControlWordAction {
  none,         ///< not one of these words: the interpreter's own table applies
  drop,         ///< a mode word without geometry: drop it, with `notice`
  length_inch,  ///< G70: lengths in inch (feeds unchanged)
  length_mm,    ///< G71: lengths in mm (feeds unchanged)
  units_inch,   ///< G700: lengths and feeds in inch
  units_mm,     ///< G710: lengths and feeds in mm
  refuse,       ///< not supported: `message` says why and what to do
};

struct ControlWord {
  ControlWordAction action = ControlWordAction::none;
  std::string text;  ///< the notice (drop, units) or the error message (refuse)
};

/// What the words of one block say about G code `code10` (G05.1 -> 51). `axis_words`: the block
/// has X Y Z A B C words; `arc_words`: I J K R; P and Q as given (nullopt: absent); L likewise.
ControlWord classify_control_word(int code10, bool axis_words, bool arc_words, std::optional<double> p,
                                  std::optional<double> q, std::optional<double> l);

}  // namespace ncpost::gcode
