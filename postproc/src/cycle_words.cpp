// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/cycle_words.hpp"

#include <fmt/format.h>

namespace ncpost {

const std::string& CycleWords::word(const cl::Cycle& c) const {
  using K = cl::Cycle::Kind;
  static const std::string none;
  switch (c.kind) {
    case K::drill: return c.dwell_s > 0.0 ? drill_dwell : drill;
    case K::deep: return c.dwell_s > 0.0 ? none : deep;
    case K::chip_break: return c.dwell_s > 0.0 ? none : chip_break;
    case K::tap: return c.dwell_s > 0.0 ? none : c.left_hand ? tap_left : tap;
    case K::bore: return c.dwell_s > 0.0 ? bore_dwell : bore;
    case K::bore_drag: return c.dwell_s > 0.0 ? none : bore_drag;
    case K::off: break;
  }
  return none;
}

std::optional<CycleWords> cycle_words(const Dialect& d) {
  CycleWords w;
  w.drill = "G81", w.drill_dwell = "G82", w.deep = "G83", w.chip_break = "G73", w.bore = "G85", w.bore_dwell = "G89",
  w.bore_drag = "G86";
  if (d.name == "fanuc") {
    w.tap = "G84", w.tap_left = "G74";
  } else if (d.name == "haas") {
    w.tap = "G84", w.tap_left = "G74";
    w.first_peck_ijk = true;
  } else if (d.name == "linuxcnc") {
    // LinuxCNC's G84 needs a floating holder and G74 does not exist: taps are expanded
    w.dwell_in_ms = false;
  } else {
    return std::nullopt;
  }
  return w;
}

std::vector<std::string> dwell_blocks(const Dialect& d, double seconds) {
  if (d.klartext) return {"CYCL DEF 9.0 DWELL TIME", fmt::format("CYCL DEF 9.1 DWELL{:.3f}", seconds)};
  if (d.name == "sinumerik") return {fmt::format("G4 F{:.3f}", seconds)};
  if (d.name == "linuxcnc") return {fmt::format("G4 P{:.3f}", seconds)};
  return {fmt::format("G4 P{:.0f}", seconds * 1000.0)};  // Fanuc, Haas: P in milliseconds
}

std::optional<CompWords> comp_words(const Dialect& d) {
  CompWords w;
  if (d.name == "fanuc" || d.name == "haas") return w;
  if (d.name == "linuxcnc") return w;  // G41 D<n> reads the tool table's radius of tool n
  if (d.name == "sinumerik") {
    w.register_letter.clear();  // G41/G42 with the D of the active tool (D1 after T)
    return w;
  }
  // Heidenhain Klartext carries RL/RR on the L blocks themselves: not written, CUTCOM is refused
  return std::nullopt;
}

}  // namespace ncpost
