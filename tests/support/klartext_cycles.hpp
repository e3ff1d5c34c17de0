// SPDX-License-Identifier: Apache-2.0
#pragma once
// The tool tip's path of the Heidenhain hole cycles 200, 201, 203, 206, 207, 208, 209, 240 and 241 for the tests'
// Klartext interpreter (klartext_interpreter.hpp), written from the cycle runs of the TNC 640 /
// iTNC 530 cycle programming manual as the tests read them, independently of the product:
//   200 DRILLING: FMAX to Q200 above the surface Q203, to Q201 at Q206, FMAX out (pecks of Q202
//       are not followed here: the ends of a hole are its planes);
//   203 UNIVERSAL DRILLING: FMAX to Q200; each plunge Q202 (less Q212 each time, not below Q205)
//       at Q206; after a plunge either a chip break (back Q256 at Q208, Q213 times in a row) or out
//       to Q200 at Q208 (Q208 = 0: Q206), FMAX back to Q200 above the depth reached; at the depth
//       out to Q200 at Q208; FMAX to Q204 when higher;
//   207 RIGID TAPPING: FMAX to Q200; to Q201 at pitch x speed; back to Q200 at the same feed;
//       FMAX to Q204 when higher; 206 TAPPING (floating holder) the same at the feed Q206;
//   209 TAPPING WITH CHIP BREAKING with Q256 = 0 (chip removal): FMAX to Q200; to Q257 below the surface
//       at pitch x speed, the spindle reversed and out to Q200 at the same feed (Q403 = 1), again to Q257
//       deeper, ... until Q201; out to Q200; FMAX to Q204 when higher; Q257 = 0 or beyond the depth: as 207
//       (Q256 other than 0, the partial retraction, throws: the tests do not follow it);
//   208 BORE MILLING: FMAX to Q200 over the centre; a half circle at Q200 from the centre onto the
//       circle of radius (Q335 - tool diameter) / 2 at angle 0; a helix of Q334 per turn down to
//       Q201; one more turn there; to the centre; FMAX to Q200, to Q204 when higher; climb (Q351
//       +1) with M3 counter-clockwise;
//   241 SINGLE-LIP DEEP HOLE: FMAX to Q200; at Q253 to Q200 above the deepened start Q379; at
//       Q206 to Q201; out to Q200 at Q208; FMAX to Q204 when higher;
//   201 REAMING: FMAX to Q200; at Q206 to Q201; (dwell Q211); at Q208 back to Q200; FMAX to Q204;
//   240 CENTERING (Q343=0, the depth Q201): FMAX to Q200; at Q206 to Q201; (dwell Q211); FMAX to
//       Q200; FMAX to Q204.
// Moves are relative to the hole's top (X Y of the call, Z = Q203), in the working plane X Y Z.
#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace ncpost::test {

/// One move of a cycle: a line to `to`, or an arc about `centre` through `sweep_rad` (> 0 ccw, the
/// Z of `to` reached in proportion), relative to the hole's top.
struct CycleMove {
  Eigen::Vector3d to = Eigen::Vector3d::Zero();
  bool cut = false;  ///< at a feed (else FMAX)
  bool arc = false;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double sweep_rad = 0.0;
};

/// The moves of cycle `n` with the Q parameters in force ("Q200" -> value), the spindle turning
/// clockwise (`m3`) and the tool's diameter (208).
inline std::vector<CycleMove> cycle_moves(int n, const std::map<std::string, double>& q, bool m3,
                                          double tool_diameter_mm) {
  const auto Q = [&](int k) { return q.at("Q" + std::to_string(k)); };
  const auto Qor = [&](int k, double d) {
    const auto it = q.find("Q" + std::to_string(k));
    return it == q.end() ? d : it->second;
  };
  std::vector<CycleMove> out;
  const auto line = [&](double x, double y, double z, bool cut) { out.push_back({{x, y, z}, cut, false, {}, 0.0}); };
  const double setup = Q(200), depth = Q(201), second = Q(204);
  line(0, 0, setup, false);
  if (n == 209 && Q(257) > 0 && Q(257) < -depth) {
    if (Q(256) != 0 || Qor(403, 1) != 1) throw std::runtime_error("the test interpreter: CYCL DEF 209 Q256 or Q403");
    for (double reached = -Q(257); reached > depth + 1e-9; reached -= Q(257)) {
      line(0, 0, reached, true);
      line(0, 0, setup, true);
    }
    line(0, 0, depth, true);
    line(0, 0, setup, true);
  } else if (n == 200 || n == 206 || n == 207 || n == 209 || n == 201 || n == 240) {
    line(0, 0, depth, true);
    line(0, 0, setup, n == 206 || n == 207 || n == 209 || n == 201);
  } else if (n == 203) {
    const bool breaking = Qor(213, 0) > 0;
    double reached = 0, plunge = Q(202);
    int since_out = 0;
    while (reached > depth + 1e-12) {
      reached = std::max(depth, reached - plunge);
      line(0, 0, reached, true);
      if (reached <= depth + 1e-12) break;
      if (breaking && since_out < Qor(213, 0)) {
        line(0, 0, reached + Qor(256, 0.2), true);
        ++since_out;
      } else {
        line(0, 0, setup, true);
        line(0, 0, reached + setup, false);
        since_out = 0;
      }
      if (Qor(212, 0) > 0) plunge = std::max(Qor(205, 0), plunge - Qor(212, 0));
    }
    line(0, 0, setup, true);
  } else if (n == 241) {
    if (Q(379) > 0) line(0, 0, setup - Q(379), true);
    line(0, 0, depth, true);
    line(0, 0, setup, true);
  } else if (n == 208) {
    const double r = (Q(335) - tool_diameter_mm) / 2;
    const double dir = (Qor(351, 1) > 0) == m3 ? 1.0 : -1.0;  // climb with M3: counter-clockwise
    out.push_back({{r, 0, setup}, true, true, {r / 2, 0, setup}, dir * M_PI});
    const double turns = (setup - depth) / Q(334);
    const double end_angle = dir * 2 * M_PI * turns;
    out.push_back({{r * std::cos(end_angle), r * std::sin(end_angle), depth}, true, true, {0, 0, 0}, end_angle});
    out.push_back({{r * std::cos(end_angle), r * std::sin(end_angle), depth}, true, true, {0, 0, 0}, dir * 2 * M_PI});
    line(0, 0, depth, true);
    line(0, 0, setup, false);
  } else {
    throw std::runtime_error("the test interpreter does not read CYCL DEF " + std::to_string(n));
  }
  if (second > setup) line(0, 0, second, false);
  return out;
}

}  // namespace ncpost::test
