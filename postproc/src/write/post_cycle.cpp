// SPDX-License-Identifier: Apache-2.0
#include "write/post_cycle.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ncpost/postproc/write/fixed_format.hpp"

namespace ncpost::detail {

HolePlanes hole_planes(const cl::Cycle& c, const ClPoint& hole) {
  const Vec3d& u = hole.axis;
  HolePlanes p;
  p.r_plane = {hole.tip_mm + c.rapid_to_mm * u, u};
  p.bottom = {hole.tip_mm - c.depth_mm * u, u};
  p.retract_to_r = !c.retract_mm || std::abs(*c.retract_mm - c.rapid_to_mm) < 1e-6;
  p.retract = p.retract_to_r ? p.r_plane : ClPoint{hole.tip_mm + *c.retract_mm * u, u};
  return p;
}

std::vector<HoleStep> expand_hole(const cl::Cycle& c, const HolePlanes& p, double feed_mm_min, bool spindle_ccw) {
  using K = cl::Cycle::Kind;
  std::vector<HoleStep> s;
  const Vec3d u = p.r_plane.axis;
  const double total = (p.r_plane.tip_mm - p.bottom.tip_mm).dot(u);  // R plane to bottom
  auto below_r = [&](double d) { return ClPoint{p.r_plane.tip_mm - d * u, u}; };
  auto rapid = [&](const ClPoint& to) { s.push_back({HoleStep::Kind::rapid, to, 0.0, 0.0, {}}); };
  auto feed = [&](const ClPoint& to) { s.push_back({HoleStep::Kind::feed, to, feed_mm_min, 0.0, {}}); };
  auto block = [&](HoleStep::Turn t) { s.push_back({HoleStep::Kind::spindle, {}, 0.0, 0.0, t}); };
  auto dwell = [&]() {
    if (c.dwell_s > 0.0) s.push_back({HoleStep::Kind::dwell, {}, 0.0, c.dwell_s, {}});
  };
  rapid(p.r_plane);
  if (c.kind == K::deep || c.kind == K::chip_break) {
    double reached = 0.0;
    double peck = c.first_peck_mm;
    while (reached < total - 1e-9) {
      const double next = std::min(total, reached + peck);
      feed(below_r(next));
      reached = next;
      peck = c.peck_mm;
      if (reached >= total - 1e-9) break;
      if (c.kind == K::deep) {
        rapid(p.r_plane);  // out of the hole: the chips come with the drill
        rapid(below_r(std::max(0.0, reached - kPeckResumeClearanceMm)));
      } else {
        rapid(below_r(std::max(0.0, reached - kChipBreakRetractMm)));  // break the chip
      }
    }
  } else {
    feed(p.bottom);
  }
  dwell();
  using Turn = HoleStep::Turn;
  const Turn forward = spindle_ccw ? Turn::counter_clockwise : Turn::clockwise;
  const Turn reverse = spindle_ccw ? Turn::clockwise : Turn::counter_clockwise;
  switch (c.kind) {
    case K::tap:
      block(reverse);  // the thread is followed out with the spindle reversed
      feed(p.r_plane);
      block(forward);
      break;
    case K::bore:
      feed(p.r_plane);
      break;
    case K::bore_drag:
      block(Turn::stop);
      rapid(p.r_plane);
      block(forward);
      break;
    default:
      break;
  }
  rapid(p.retract);
  return s;
}

std::optional<NcCycle> native_hole(const cl::Cycle& c, const CycleWords& w, const Vec3d& r_plane, const Vec3d& bottom,
                                   bool retract_to_r, double feed_mm_min, double rpm, int linear_decimals,
                                   std::string& notice) {
  using K = cl::Cycle::Kind;
  const std::string& code = w.word(c);
  if (code.empty()) return std::nullopt;
  NcCycle n;
  n.code = code;
  n.retract_to_r = retract_to_r;
  n.bottom_mm = {bottom.x(), bottom.y(), bottom.z()};
  n.r_plane_mm = r_plane.z();
  n.feed_mm_min = feed_mm_min;
  if (c.kind == K::tap)
    for (const std::string& b : w.tap_before) n.before.push_back(with_value(b, "{rpm}", fmt::format("{:.0f}", rpm)));
  fmt::memory_buffer words;
  auto word = [&](char letter, double v, int decimals) {
    words.push_back(' ');
    words.push_back(letter);
    append_fixed(words, v, decimals);
  };
  if (c.kind == K::deep || c.kind == K::chip_break) {
    if (std::abs(c.first_peck_mm - c.peck_mm) < 1e-9) {
      word('Q', c.peck_mm, linear_decimals);
    } else if (w.first_peck_ijk && c.first_peck_mm > c.peck_mm && c.kind == K::deep) {
      // first peck I, each next one J less, never less than K: I, then K, K, ...
      word('I', c.first_peck_mm, linear_decimals);
      word('J', c.first_peck_mm - c.peck_mm, linear_decimals);
      word('K', c.peck_mm, linear_decimals);
    } else {
      const double q = std::min(c.first_peck_mm, c.peck_mm);
      word('Q', q, linear_decimals);
      notice = fmt::format(
          "first peck {:.4g} mm then {:.4g} mm: {} has one peck depth, pecks of {:.4g} mm written "
          "(never deeper than the CL data asks)",
          c.first_peck_mm, c.peck_mm, code, q);
    }
  }
  if (c.dwell_s > 0.0) {
    if (w.dwell_in_ms)
      word('P', std::round(c.dwell_s * 1000.0), 0);
    else
      word('P', c.dwell_s, 3);
  }
  n.words = fmt::to_string(words);
  return n;
}

}  // namespace ncpost::detail
