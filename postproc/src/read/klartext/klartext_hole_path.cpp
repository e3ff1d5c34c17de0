// SPDX-License-Identifier: Apache-2.0
// CYCL DEF 201, 203, 208, 240 and 241 expanded into the tool tip's path (klartext_hole_path.hpp).
#include "read/klartext/klartext_hole_path.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ncpost/kinematics/pose.hpp"

namespace ncpost::klartext {
namespace {

/// More steps than this in one hole is a slip in the parameters (a 0.001 mm plunge in a deep hole).
constexpr std::size_t kMaxHoleSteps = 200000;
constexpr double kEpsMm = 1e-9;

using Q = std::map<int, double>;

std::optional<double> get(const Q& q, int n) {
  const auto it = q.find(n);
  return it == q.end() ? std::nullopt : std::optional<double>(it->second);
}

/// The first of `required` not in `q`, as the refusal, or "".
std::string missing(int cycle, const Q& q, std::initializer_list<int> required) {
  for (int n : required)
    if (!get(q, n)) return fmt::format("CYCL DEF {} without Q{}", cycle, n);
  return "";
}

std::string check_common(int cycle, const Q& q) {
  const double clearance = *get(q, 200), depth = *get(q, 201), second = *get(q, 204);
  if (!(clearance > 0.0))
    return fmt::format("CYCL DEF {}: Q200={} (the set-up clearance must be > 0)", cycle, clearance);
  if (!(depth < 0.0))
    return fmt::format("CYCL DEF {}: Q201={} (the depth must be < 0, below the surface)", cycle, depth);
  if (second < 0.0) return fmt::format("CYCL DEF {}: Q204={} (the 2nd set-up clearance must be >= 0)", cycle, second);
  for (int n : {206})
    if (const auto f = get(q, n); f && !(*f > 0.0))
      return fmt::format("CYCL DEF {}: Q{}={} (the feed must be > 0 mm/min)", cycle, n, *f);
  for (int n : {210, 211})
    if (const auto s = get(q, n); s && (*s < 0.0 || *s > cl::kMaxDwellSeconds))
      return fmt::format("CYCL DEF {}: Q{}={} s is no dwell", cycle, n, *s);
  if (get(q, 395).value_or(0.0) != 0.0)
    return fmt::format("CYCL DEF {}: Q395=1 (the depth to the tool's full diameter) is not read; program Q395=0",
                       cycle);
  return "";
}

std::string check_203(const Q& q) {
  if (auto m = missing(203, q, {200, 201, 206, 202, 203, 204}); !m.empty()) return m;
  const double peck = *get(q, 202), decrement = get(q, 212).value_or(0.0), least = get(q, 205).value_or(0.0);
  const double breaks = get(q, 213).value_or(0.0), back = get(q, 256).value_or(0.2);
  if (!(peck > 0.0)) return fmt::format("CYCL DEF 203: Q202={} (the plunging depth must be > 0)", peck);
  if (decrement < 0.0) return fmt::format("CYCL DEF 203: Q212={} (the decrement must be >= 0)", decrement);
  if (least < 0.0) return fmt::format("CYCL DEF 203: Q205={} (the minimum plunging depth must be >= 0)", least);
  if (decrement > 0.0 && !(least > 0.0))
    return "CYCL DEF 203: a decrement Q212 without a minimum plunging depth Q205 > 0 would shrink the pecks to "
           "nothing; program Q205";
  if (breaks < 0.0 || breaks != std::floor(breaks))
    return fmt::format("CYCL DEF 203: Q213={} (the number of chip breaks is a whole number >= 0)", breaks);
  const double smallest = decrement > 0.0 ? std::min(peck, least) : peck;
  if (breaks > 0.0 && !(back > 0.0 && back < smallest))
    return fmt::format("CYCL DEF 203: Q256={} (the chip-breaking retraction must be > 0 and less than the plunge)",
                       back);
  if (get(q, 208).value_or(0.0) < 0.0) return fmt::format("CYCL DEF 203: Q208={} (a feed >= 0)", *get(q, 208));
  return check_common(203, q);
}

std::string check_241(const Q& q) {
  if (auto m = missing(241, q, {200, 201, 206, 203, 204, 379, 253, 208, 426, 427, 428}); !m.empty()) return m;
  const double start = *get(q, 379), direction = *get(q, 426);
  if (start < 0.0 || start >= -*get(q, 201))
    return fmt::format("CYCL DEF 241: Q379={} (the deepened starting point lies between the surface and the depth)",
                       start);
  if (!(*get(q, 253) > 0.0))
    return fmt::format("CYCL DEF 241: Q253={} (the pre-positioning feed must be > 0)", *get(q, 253));
  if (*get(q, 208) < 0.0) return fmt::format("CYCL DEF 241: Q208={} (a feed >= 0)", *get(q, 208));
  if (direction != 3.0 && direction != 4.0 && direction != 5.0)
    return fmt::format("CYCL DEF 241: Q426={} (the spindle's direction in and out of the hole: 3, 4 or 5)", direction);
  if (*get(q, 427) < 0.0 || !(*get(q, 428) > 0.0))
    return fmt::format("CYCL DEF 241: Q427={} / Q428={} (spindle speeds: >= 0 in and out, > 0 drilling)", *get(q, 427),
                       *get(q, 428));
  if (get(q, 435).value_or(0.0) != 0.0)
    return fmt::format("CYCL DEF 241: Q435={} (a dwell depth) is not read; program Q435=0", *get(q, 435));
  return check_common(241, q);
}

std::string check_208(const Q& q) {
  if (auto m = missing(208, q, {200, 201, 206, 334, 203, 204, 335}); !m.empty()) return m;
  if (!(*get(q, 334) > 0.0)) return fmt::format("CYCL DEF 208: Q334={} (the helix's pitch must be > 0)", *get(q, 334));
  if (!(*get(q, 335) > 0.0))
    return fmt::format("CYCL DEF 208: Q335={} (the bore's diameter must be > 0)", *get(q, 335));
  if (const double s = get(q, 351).value_or(1.0); s != 1.0 && s != -1.0)
    return fmt::format("CYCL DEF 208: Q351={} (+1 climb, -1 up-cut milling)", s);
  if (get(q, 370))
    return "CYCL DEF 208: Q370 (the path overlap of the TNC 640's newer cycle) is not read; leave it out";
  return check_common(208, q);
}

std::string check_201(const Q& q) {
  if (auto m = missing(201, q, {200, 201, 206, 203, 204}); !m.empty()) return m;
  if (get(q, 208).value_or(0.0) < 0.0) return fmt::format("CYCL DEF 201: Q208={} (a feed >= 0)", *get(q, 208));
  return check_common(201, q);
}

std::string check_240(const Q& q) {
  if (auto m = missing(240, q, {200, 343, 206, 203, 204}); !m.empty()) return m;
  if (*get(q, 343) != 0.0)
    return fmt::format(
        "CYCL DEF 240: Q343={} (the depth from the countersinking diameter Q344) needs the tool's point angle "
        "(T-ANGLE of the TNC's tool table), which the post does not have; program Q343=0 and the depth Q201",
        *get(q, 343));
  if (auto m = missing(240, q, {201}); !m.empty()) return m;
  return check_common(240, q);
}

HoleStep step(HoleStep::Kind kind, double dx, double dy, double z, double feed = 0.0) {
  HoleStep s;
  s.kind = kind == HoleStep::Kind::feed && std::isinf(feed) ? HoleStep::Kind::rapid : kind;  // (Q208=MAX: FMAX)
  s.dx = dx;
  s.dy = dy;
  s.z = z;
  s.feed_mm_min = feed;
  return s;
}
HoleStep dwell(double seconds) {
  HoleStep s;
  s.kind = HoleStep::Kind::dwell;
  s.dwell_s = seconds;
  return s;
}
HoleStep spindle(cl::Spindle::Direction d, double rpm) {
  HoleStep s;
  s.kind = HoleStep::Kind::spindle;
  s.direction = d;
  s.rpm = rpm;
  return s;
}

/// The tool leaves the hole: to the set-up clearance (done), then to the 2nd where higher, at FMAX.
void to_second_clearance(const ExpandedCycle& c, std::vector<HoleStep>& out) {
  const double clearance = *get(c.q, 200), second = *get(c.q, 204);
  if (second > clearance) out.push_back(step(HoleStep::Kind::rapid, 0, 0, second));
}

/// 203: pecks of Q202 shrinking by Q212 down to Q205; after each, a chip break (back by Q256)
/// until Q213 of them, then a retraction at Q208 to the set-up clearance, the dwell Q210 there
/// and FMAX back to the set-up clearance above the last depth.
std::variant<std::vector<HoleStep>, std::string> steps_203(const ExpandedCycle& c) {
  const Q& q = c.q;
  const double s = *get(q, 200), depth = *get(q, 201), feed = *get(q, 206);
  const double out_feed = get(q, 208).value_or(0.0) > 0.0 ? *get(q, 208) : feed;
  const double decrement = get(q, 212).value_or(0.0), least = get(q, 205).value_or(0.0);
  const int breaks_before_retract = static_cast<int>(get(q, 213).value_or(0.0));
  const double back = get(q, 256).value_or(0.2), top_dwell = get(q, 210).value_or(0.0);
  std::vector<HoleStep> out{step(HoleStep::Kind::rapid, 0, 0, s)};
  double reached = 0.0, plunge = *get(q, 202);
  int breaks = 0;
  for (;;) {
    const double bottom = std::max(depth, reached - plunge);
    out.push_back(step(HoleStep::Kind::feed, 0, 0, bottom, feed));
    reached = bottom;
    if (bottom <= depth + kEpsMm) break;
    if (breaks < breaks_before_retract) {
      out.push_back(step(HoleStep::Kind::feed, 0, 0, bottom + back, out_feed));
      ++breaks;
    } else {
      out.push_back(step(HoleStep::Kind::feed, 0, 0, s, out_feed));
      if (top_dwell > 0.0) out.push_back(dwell(top_dwell));
      out.push_back(step(HoleStep::Kind::rapid, 0, 0, bottom + s));
      breaks = 0;
    }
    if (decrement > 0.0) plunge = std::max(plunge - decrement, least);
    if (out.size() > kMaxHoleSteps)
      return fmt::format("CYCL DEF 203: more than {} moves in one hole (Q202 / Q205 against the depth Q201={})",
                         kMaxHoleSteps, depth);
  }
  if (get(q, 211).value_or(0.0) > 0.0) out.push_back(dwell(*get(q, 211)));
  out.push_back(step(HoleStep::Kind::feed, 0, 0, s, out_feed));
  to_second_clearance(c, out);
  return out;
}

/// 201: FMAX to the set-up clearance, at Q206 to the depth, the dwell Q211, out at Q208 (0: Q206) to
/// the set-up clearance, FMAX to the 2nd. 240: the same but out at FMAX.
std::vector<HoleStep> steps_201_240(const ExpandedCycle& c) {
  const Q& q = c.q;
  const double s = *get(q, 200), feed = *get(q, 206);
  std::vector<HoleStep> out{step(HoleStep::Kind::rapid, 0, 0, s), step(HoleStep::Kind::feed, 0, 0, *get(q, 201), feed)};
  if (get(q, 211).value_or(0.0) > 0.0) out.push_back(dwell(*get(q, 211)));
  if (c.number == 240) {
    out.push_back(step(HoleStep::Kind::rapid, 0, 0, s));
  } else {
    const double out_feed = get(q, 208).value_or(0.0) > 0.0 ? *get(q, 208) : feed;
    out.push_back(step(HoleStep::Kind::feed, 0, 0, s, out_feed));
  }
  to_second_clearance(c, out);
  return out;
}

/// 241: FMAX to the set-up clearance; spindle Q426 at Q427; at Q253 to the set-up clearance above
/// the deepened starting point Q379; the drilling speed Q428 (the direction of the spindle before
/// the cycle); at Q206 to the depth; the dwell Q211; spindle Q426 at Q427; at Q208 (0: Q206) to
/// the set-up clearance; the spindle as before the cycle; FMAX to the 2nd set-up clearance.
std::variant<std::vector<HoleStep>, std::string> steps_241(const ExpandedCycle& c, const HoleContext& at) {
  const Q& q = c.q;
  if (at.spindle == cl::Spindle::Direction::off)
    return "CYCL DEF 241 called with the spindle stopped: the cycle drills in the direction of the spindle before "
           "it (program M3 or M4 before the call)";
  const double s = *get(q, 200), feed = *get(q, 206);
  const double out_feed = *get(q, 208) > 0.0 ? *get(q, 208) : feed;
  const int in_out = static_cast<int>(*get(q, 426));
  const auto in_out_spindle = spindle(in_out == 3   ? cl::Spindle::Direction::cw
                                      : in_out == 4 ? cl::Spindle::Direction::ccw
                                                    : cl::Spindle::Direction::off,
                                      in_out == 5 ? 0.0 : *get(q, 427));
  std::vector<HoleStep> out{step(HoleStep::Kind::rapid, 0, 0, s), in_out_spindle};
  if (*get(q, 379) > 0.0) out.push_back(step(HoleStep::Kind::feed, 0, 0, s - *get(q, 379), *get(q, 253)));
  out.push_back(spindle(at.spindle, *get(q, 428)));
  out.push_back(step(HoleStep::Kind::feed, 0, 0, *get(q, 201), feed));
  if (get(q, 211).value_or(0.0) > 0.0) out.push_back(dwell(*get(q, 211)));
  out.push_back(in_out_spindle);
  out.push_back(step(HoleStep::Kind::feed, 0, 0, s, out_feed));
  HoleStep restore;
  restore.kind = HoleStep::Kind::restore;
  out.push_back(restore);
  to_second_clearance(c, out);
  return out;
}

/// Arcs of at most half a turn about (0, 0) on radius r from polar angle `from` through `sweep`,
/// Z from `z0` to `z1` in proportion; the angle reached.
double helix(std::vector<HoleStep>& out, double r, double from, double sweep, double z0, double z1, double feed) {
  const long pieces = std::max(1L, static_cast<long>(std::ceil(std::abs(sweep) / kPi - 1e-9)));
  for (long i = 1; i <= pieces; ++i) {
    const double t = static_cast<double>(i) / static_cast<double>(pieces);
    const double a = from + sweep * t;
    HoleStep s = step(HoleStep::Kind::arc, r * std::cos(a), r * std::sin(a), z0 + (z1 - z0) * t, feed);
    s.sweep_rad = sweep / static_cast<double>(pieces);
    out.push_back(s);
  }
  return from + sweep;
}

/// 208: FMAX to the set-up clearance above the centre; a half circle at the clearance from the
/// centre to the circle of radius (Q335 - tool diameter) / 2 at polar angle 0 (tangent there); a
/// helix of pitch Q334 to the depth; a full circle at the depth; straight back to the centre;
/// FMAX to the set-up clearance and the 2nd. All at Q206; climb (Q351 +1) with M3 turns
/// counter-clockwise. A tool as wide as the bore drills straight down and comes out at FMAX.
std::variant<std::vector<HoleStep>, std::string> steps_208(const ExpandedCycle& c, const HoleContext& at) {
  const Q& q = c.q;
  if (!at.tool_diameter_mm)
    return fmt::format(
        "CYCL DEF 208 with the tool {}, whose diameter is not known: the helix's radius is the bore's "
        "less the tool's; give the diameter in --tool-table (name = {{ number = n, diameter = d }})",
        at.tool.empty() ? "(none called)" : at.tool);
  if (at.spindle == cl::Spindle::Direction::off)
    return "CYCL DEF 208 called with the spindle stopped: climb or up-cut (Q351) needs M3 or M4";
  const double s = *get(q, 200), depth = *get(q, 201), feed = *get(q, 206);
  const double r = 0.5 * (*get(q, 335) - *at.tool_diameter_mm);
  if (r < -kEpsMm)
    return fmt::format("CYCL DEF 208: the bore's diameter Q335={} is smaller than the tool's {} mm", *get(q, 335),
                       *at.tool_diameter_mm);
  std::vector<HoleStep> out{step(HoleStep::Kind::rapid, 0, 0, s)};
  if (r < 1e-3) {
    out.push_back(step(HoleStep::Kind::feed, 0, 0, depth, feed));
    out.push_back(step(HoleStep::Kind::rapid, 0, 0, s));
  } else {
    const bool climb = get(q, 351).value_or(1.0) > 0.0;
    const double sign = climb == (at.spindle == cl::Spindle::Direction::cw) ? 1.0 : -1.0;
    HoleStep in = step(HoleStep::Kind::arc, r, 0, s, feed);
    in.cx = 0.5 * r;
    in.sweep_rad = sign * kPi;
    out.push_back(in);
    const double turns = (s - depth) / *get(q, 334);
    if (turns * 2.0 > static_cast<double>(kMaxHoleSteps))
      return fmt::format("CYCL DEF 208: {:.0f} turns of the helix (Q334={})", turns, *get(q, 334));
    const double a = helix(out, r, 0.0, sign * 2.0 * kPi * turns, s, depth, feed);
    helix(out, r, a, sign * 2.0 * kPi, depth, depth, feed);
    out.push_back(step(HoleStep::Kind::feed, 0, 0, depth, feed));
    out.push_back(step(HoleStep::Kind::rapid, 0, 0, s));
  }
  to_second_clearance(c, out);
  return out;
}

}  // namespace

std::variant<ExpandedCycle, std::string> expanded_cycle(int number, const std::map<int, double>& q) {
  const std::string why = number == 203   ? check_203(q)
                          : number == 241 ? check_241(q)
                          : number == 208 ? check_208(q)
                          : number == 201 ? check_201(q)
                          : number == 240 ? check_240(q)
                                          : "not expanded";
  if (!why.empty()) return why;
  ExpandedCycle c;
  c.number = number;
  c.q = q;
  c.surface_mm = *get(q, 203);
  c.return_mm = std::max(*get(q, 200), *get(q, 204));
  if (number == 241 && (get(q, 429) || get(q, 430)))
    c.notes.push_back(
        fmt::format("CYCL DEF 241: Q429={:g} / Q430={:g} (the machine's M functions for the coolant in "
                    "and out of the hole) are noted, not posted: the coolant stays as programmed",
                    get(q, 429).value_or(0.0), get(q, 430).value_or(0.0)));
  if (number == 208 && get(q, 342))
    c.notes.push_back(
        fmt::format("CYCL DEF 208: Q342={:g} (the pre-drilled diameter, for the TNC's check of the "
                    "tool against the bore) is noted; it does not change the path",
                    *get(q, 342)));
  return c;
}

std::variant<std::vector<HoleStep>, std::string> hole_steps(const ExpandedCycle& c, const HoleContext& at_call) {
  switch (c.number) {
    case 203:
      return steps_203(c);
    case 241:
      return steps_241(c, at_call);
    case 201:
    case 240:
      return steps_201_240(c);
    default:
      return steps_208(c, at_call);
  }
}

}  // namespace ncpost::klartext
