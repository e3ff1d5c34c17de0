// SPDX-License-Identifier: Apache-2.0
#pragma once
// CYCL DEF 200 DRILLING and 207 RIGID TAPPING (TNC user manual, "Cycles: drilling") as a cl::Cycle: its Q parameters,
// written on the `~` continuation lines (`Q200=+2 ;SET-UP CLEARANCE ~`).
//   Q200 set-up clearance above the surface (> 0), Q201 depth below it (< 0), Q206 plunging feed
//   (mm/min), Q202 plunging depth (the hole in one plunge when >= the depth, else pecks with a
//   full retract to the set-up clearance), Q210 dwell at the top (0 only), Q203 the surface
//   coordinate (absolute, along the tool axis Z), Q204 2nd set-up clearance (the tool returns to
//   the higher of Q200 and Q204), Q211 dwell at the depth (s, one plunge only), Q395 depth
//   reference (0: the tool tip, only).
// The hole's CL point is its top (X Y of the call, Z = Q203): cl::Cycle distances from there.
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "ncpost/postproc/read/cl_record.hpp"

namespace ncpost::klartext {

/// One `Qn = value` continuation line: the number and the value, or the text when not a number.
struct QAssignment {
  int number = -1;
  std::optional<double> value;
  std::string text;  ///< the value as written
};
/// nullopt when the line is no `Qn=` line.
std::optional<QAssignment> q_assignment(std::string_view line);

struct DrillingCycle {
  cl::Cycle cycle;          ///< distances from the hole's top
  double surface_mm = 0.0;  ///< Q203
  double return_mm = 0.0;   ///< where the tool stands after a hole, above the surface: max(Q200, Q204)
  /// 206 (floating tap holder): its tapping feed Q206 (mm/min); the pitch is Q206 / the speed at the
  /// call, the thread's hand the spindle's direction there
  std::optional<double> tap_feed_mm_min;
  /// 209 with chip removal: the depths below the surface (mm, > 0, the last the thread's) of its taps, each from
  /// the set-up clearance and back to it; empty: one tap
  std::vector<double> infeed_depths_mm;
};

/// CYCL DEF 200 from its parameters, or why not (a sentence naming the parameter).
std::variant<DrillingCycle, std::string> drilling_200(const std::map<int, double>& q, cl::Location where);

/// CYCL DEF 207 RIGID TAPPING (the TNC's tapping without a floating holder): Q200 set-up
/// clearance, Q201 depth of the thread (< 0), Q239 pitch (mm; > 0 right-hand, the spindle M3 in,
/// < 0 left-hand, M4), Q203 surface, Q204 2nd set-up clearance, Q336 the spindle's orientation
/// angle (where the spindle stops: no motion). The tool goes at FMAX to the set-up clearance,
/// taps to the depth at the feed of pitch x speed, reverses the spindle, comes back to the set-up
/// clearance at the same feed, and goes at FMAX to the 2nd set-up clearance (cl::Cycle::Kind::tap).
std::variant<DrillingCycle, std::string> tapping_207(const std::map<int, double>& q, cl::Location where);

/// CYCL DEF 206 TAPPING NEW (with a floating tap holder): Q200 set-up clearance, Q201 depth of the
/// thread (< 0), Q206 the tapping feed (mm/min: speed x pitch), Q211 dwell at the bottom (s), Q203
/// surface, Q204 2nd set-up clearance. The tool goes at FMAX to the set-up clearance, taps to the
/// depth at Q206, dwells Q211, reverses the spindle, comes back to the set-up clearance at Q206 and
/// goes at FMAX to the 2nd set-up clearance; the thread's hand is the spindle's direction (M3
/// right, M4 left). A cl::Cycle tap whose pitch is set at the call (DrillingCycle::tap_feed_mm_min).
std::variant<DrillingCycle, std::string> tapping_206(const std::map<int, double>& q, cl::Location where);

/// CYCL DEF 209 TAPPING WITH CHIP BREAKING (rigid, as 207): Q200 set-up clearance, Q201 depth of the thread
/// (< 0), Q239 pitch (+ right-hand, - left-hand), Q203 surface, Q204 2nd set-up clearance, Q257 infeed depth for
/// chip breaking (0: none, one tap), Q256 retraction for chip breaking (a factor of the pitch; 0: out to the set-up
/// clearance), Q336 the spindle's orientation angle (where it stops: no motion), Q403 the speed factor of the
/// retraction. The TNC taps Q257 deeper each time, reverses the spindle and retracts (Q256 = 0: to the set-up
/// clearance), reverses it again and taps on, until the depth; then back to the set-up clearance and at FMAX to the
/// 2nd. Read: Q256 = 0 (each infeed a tap from the set-up clearance and back: `infeed_depths_mm`) or no chip
/// breaking, with Q403 = 1. Refused, naming the parameter: Q256 other than 0 (a partial retraction inside the hole,
/// which no output tapping cycle makes) and Q403 other than 1 (the output's taps come out at the tapping feed).
std::variant<DrillingCycle, std::string> tapping_209(const std::map<int, double>& q, cl::Location where);

}  // namespace ncpost::klartext
