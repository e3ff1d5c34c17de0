// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/write/cycle_words.hpp"

#include <fmt/format.h>

namespace ncpost {

const std::string& CycleWords::word(const cl::Cycle& c) const {
  using K = cl::Cycle::Kind;
  static const std::string none;
  switch (c.kind) {
    case K::drill:
      return c.dwell_s > 0.0 ? drill_dwell : drill;
    case K::deep:
      return c.dwell_s > 0.0 ? none : deep;
    case K::chip_break:
      return c.dwell_s > 0.0 ? none : chip_break;
    case K::tap:
      return c.dwell_s > 0.0 ? none : c.left_hand ? tap_left : tap;
    case K::bore:
      return c.dwell_s > 0.0 ? bore_dwell : bore;
    case K::bore_drag:
      return c.dwell_s > 0.0 ? none : bore_drag;
    case K::off:
      break;
  }
  return none;
}

std::optional<CycleWords> cycle_words(const Dialect& d) { return d.cycles; }

std::vector<std::string> dwell_blocks(const Dialect& d, double seconds) {
  const std::string ms = fmt::format("{:.0f}", seconds * 1000.0);
  const std::string s = fmt::format("{:.3f}", seconds);
  std::vector<std::string> out;
  for (const std::string& b : d.dwell) out.push_back(with_value(with_value(b, "{ms}", ms), "{s}", s));
  return out;
}

std::optional<CompWords> comp_words(const Dialect& d) { return d.compensation; }

}  // namespace ncpost
