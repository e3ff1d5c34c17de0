// SPDX-License-Identifier: Apache-2.0
// CYCL DEF 200 as a cl::Cycle (klartext_drilling.hpp).
#include "read/klartext/klartext_drilling.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

namespace ncpost::klartext {

std::optional<QAssignment> q_assignment(std::string_view line) {
  std::size_t p = 0;
  const auto blanks = [&] {
    while (p < line.size() && (line[p] == ' ' || line[p] == '\t')) ++p;
  };
  blanks();
  if (p >= line.size() || (line[p] != 'Q' && line[p] != 'q')) return std::nullopt;
  ++p;
  const std::size_t digits = p;
  while (p < line.size() && std::isdigit(static_cast<unsigned char>(line[p]))) ++p;
  if (p == digits) return std::nullopt;
  QAssignment a;
  a.number = std::stoi(std::string(line.substr(digits, p - digits)));
  blanks();
  if (p >= line.size() || line[p] != '=') return std::nullopt;
  ++p;
  blanks();
  std::size_t end = p;
  while (end < line.size() && line[end] != ' ' && line[end] != '\t' && line[end] != ';' && line[end] != '~') ++end;
  a.text = std::string(line.substr(p, end - p));
  std::string number = a.text;
  if (!number.empty() && number.front() == '+') number.erase(0, 1);
  double v = 0.0;
  const auto r = std::from_chars(number.data(), number.data() + number.size(), v);
  if (!number.empty() && r.ec == std::errc{} && r.ptr == number.data() + number.size()) a.value = v;
  return a;
}

std::variant<DrillingCycle, std::string> drilling_200(const std::map<int, double>& q, cl::Location where) {
  const auto get = [&q](int n) -> std::optional<double> {
    const auto it = q.find(n);
    return it == q.end() ? std::nullopt : std::optional<double>(it->second);
  };
  for (int n : {200, 201, 206, 202, 203, 204})
    if (!get(n)) return fmt::format("CYCL DEF 200 without Q{} (expected Q200 Q201 Q206 Q202 Q210 Q203 Q204 Q211)", n);
  const double clearance = *get(200), depth = *get(201), feed = *get(206), peck = *get(202);
  if (!(clearance > 0.0)) return fmt::format("CYCL DEF 200: Q200={} (the set-up clearance must be > 0)", clearance);
  if (!(depth < 0.0)) return fmt::format("CYCL DEF 200: Q201={} (the depth must be < 0, below the surface)", depth);
  if (!(feed > 0.0)) return fmt::format("CYCL DEF 200: Q206={} (the plunging feed must be > 0 mm/min)", feed);
  if (!(peck > 0.0)) return fmt::format("CYCL DEF 200: Q202={} (the plunging depth must be > 0)", peck);
  if (get(210).value_or(0.0) != 0.0)
    return fmt::format("CYCL DEF 200: Q210={} (a dwell at the top between pecks) is not read; program Q210=0",
                       *get(210));
  if (get(395).value_or(0.0) != 0.0)
    return "CYCL DEF 200: Q395=1 (the depth to the tool's full diameter) is not read; program Q395=0 (the tip)";
  const double dwell = get(211).value_or(0.0);
  if (dwell < 0.0 || dwell > cl::kMaxDwellSeconds) return fmt::format("CYCL DEF 200: Q211={} s is no dwell", dwell);
  DrillingCycle d;
  cl::Cycle& c = d.cycle;
  c.where = where;
  c.kind_word = "CYCL DEF 200";
  c.text = "CYCL DEF 200 DRILLING";
  c.depth_mm = -depth;
  c.rapid_to_mm = clearance;
  const double second = *get(204);
  if (second > clearance) c.retract_mm = second;
  c.feed = feed;
  if (peck + 1e-9 >= c.depth_mm) {
    c.kind = cl::Cycle::Kind::drill;
    c.dwell_s = dwell;
  } else {
    if (dwell > 0.0)
      return fmt::format(
          "CYCL DEF 200: Q211={} s (a dwell at the depth) with pecks (Q202={} < the depth {}) is not "
          "read; program Q211=0 or one plunge",
          dwell, peck, -depth);
    c.kind = cl::Cycle::Kind::deep;
    c.peck_mm = c.first_peck_mm = peck;
  }
  d.surface_mm = *get(203);
  d.return_mm = std::max(clearance, second);
  return d;
}

namespace {

/// The tap (cl::Cycle::Kind::tap) of CYCL DEF `number` with the parameters both tapping cycles share
/// (Q200 set-up clearance, Q201 depth, Q203 surface, Q204 2nd set-up clearance), or why not.
std::variant<DrillingCycle, std::string> tap_of(int number, const char* text, const std::map<int, double>& q,
                                                cl::Location where) {
  const double clearance = q.at(200), depth = q.at(201), second = q.at(204);
  if (!(clearance > 0.0))
    return fmt::format("CYCL DEF {}: Q200={} (the set-up clearance must be > 0)", number, clearance);
  if (!(depth < 0.0)) return fmt::format("CYCL DEF {}: Q201={} (the thread's depth must be < 0)", number, depth);
  DrillingCycle d;
  cl::Cycle& c = d.cycle;
  c.where = where;
  c.kind = cl::Cycle::Kind::tap;
  c.kind_word = fmt::format("CYCL DEF {}", number);
  c.text = text;
  c.depth_mm = -depth;
  c.rapid_to_mm = clearance;
  if (second > clearance) c.retract_mm = second;
  d.surface_mm = q.at(203);
  d.return_mm = std::max(clearance, second);
  return d;
}

}  // namespace

std::variant<DrillingCycle, std::string> tapping_207(const std::map<int, double>& q, cl::Location where) {
  for (int n : {200, 201, 239, 203, 204})
    if (!q.count(n)) return fmt::format("CYCL DEF 207 without Q{} (expected Q200 Q201 Q239 Q203 Q204)", n);
  const double pitch = q.at(239);
  if (pitch == 0.0 || std::abs(pitch) > 100.0)
    return fmt::format("CYCL DEF 207: Q239={} (the pitch in mm: + right-hand, - left-hand)", pitch);
  auto d = tap_of(207, "CYCL DEF 207 RIGID TAPPING", q, where);
  if (DrillingCycle* tap = std::get_if<DrillingCycle>(&d)) {
    tap->cycle.pitch_mm = std::abs(pitch);
    tap->cycle.left_hand = pitch < 0.0;
  }
  return d;
}

std::variant<DrillingCycle, std::string> tapping_206(const std::map<int, double>& q, cl::Location where) {
  for (int n : {200, 201, 206, 203, 204})
    if (!q.count(n)) return fmt::format("CYCL DEF 206 without Q{} (expected Q200 Q201 Q206 Q211 Q203 Q204)", n);
  const double feed = q.at(206);
  const double dwell = q.count(211) ? q.at(211) : 0.0;
  if (!(feed > 0.0) || std::isinf(feed))
    return fmt::format("CYCL DEF 206: Q206={} (the tapping feed, speed x pitch, must be a feed > 0)", feed);
  if (dwell < 0.0 || dwell > cl::kMaxDwellSeconds) return fmt::format("CYCL DEF 206: Q211={} s is no dwell", dwell);
  auto d = tap_of(206, "CYCL DEF 206 TAPPING", q, where);
  if (DrillingCycle* tap = std::get_if<DrillingCycle>(&d)) {
    tap->cycle.dwell_s = dwell;
    tap->tap_feed_mm_min = feed;
  }
  return d;
}

std::variant<DrillingCycle, std::string> tapping_209(const std::map<int, double>& q, cl::Location where) {
  for (int n : {200, 201, 239, 203, 204, 257, 256})
    if (!q.count(n))
      return fmt::format("CYCL DEF 209 without Q{} (expected Q200 Q201 Q239 Q203 Q204 Q257 Q256 Q336 Q403)", n);
  const double pitch = q.at(239), infeed = q.at(257), back = q.at(256);
  const double speed_factor = q.count(403) ? q.at(403) : 1.0;
  if (pitch == 0.0 || std::abs(pitch) > 100.0)
    return fmt::format("CYCL DEF 209: Q239={} (the pitch in mm: + right-hand, - left-hand)", pitch);
  if (!(infeed >= 0.0) || std::isinf(infeed))
    return fmt::format("CYCL DEF 209: Q257={} (the infeed depth for chip breaking must be >= 0)", infeed);
  if (speed_factor != 1.0)
    return fmt::format(
        "CYCL DEF 209: Q403={:g} (the retraction at {:g} times the spindle speed) is not read: the "
        "output's taps come out at the tapping feed; program Q403=1",
        speed_factor, speed_factor);
  auto d = tap_of(209, "CYCL DEF 209 TAPPING W/ CHIP BRKG", q, where);
  DrillingCycle* tap = std::get_if<DrillingCycle>(&d);
  if (!tap) return d;
  tap->cycle.pitch_mm = std::abs(pitch);
  tap->cycle.left_hand = pitch < 0.0;
  const double depth = tap->cycle.depth_mm;
  if (infeed == 0.0 || infeed >= depth) return d;  // no chip breaking: one tap
  if (back != 0.0)
    return fmt::format(
        "CYCL DEF 209: Q256={:g} (chip breaking inside the hole: back by Q256 x the pitch, {:g} mm, after each "
        "infeed of Q257={:g}) is not read: the output's tapping cycles leave the thread only at the set-up "
        "clearance; Q256=0 (out to the set-up clearance after each infeed) is read",
        back, std::abs(back * pitch), infeed);
  constexpr int kMostInfeeds = 1000;
  if (depth / infeed > kMostInfeeds)
    return fmt::format("CYCL DEF 209: Q257={:g} makes more than {} infeeds to the depth {:g}", infeed, kMostInfeeds,
                       depth);
  for (int k = 1; k * infeed < depth - 1e-9; ++k) tap->infeed_depths_mm.push_back(k * infeed);
  tap->infeed_depths_mm.push_back(depth);
  return d;
}

}  // namespace ncpost::klartext
