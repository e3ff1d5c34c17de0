// SPDX-License-Identifier: Apache-2.0
#pragma once
// Inverse-time feed (G93): the one rule by which the post times a block and the G-code reader
// reads a source block's time (README, docs/cli.md "Feeds").
//
// A feed F (mm/min) is the speed of the tool tip along its path in the workpiece W. A block whose
// tip moves runs for (length of the tip path in W) / F minutes: the length of the path the
// machine executes (its axes interpolated linearly from one block end to the other), not the
// chord. A block whose tip stands still (a pure reorientation) runs its largest rotary travel at
// F read as deg/min. No other cap: a machine whose rotary axes cannot follow slows the block
// itself (its control's rate limits), the program does not.
#include <functional>

#include "ncpost/kinematics/pose.hpp"

namespace ncpost {

/// Below this tip travel (mm) between the CL points a block is a pure reorientation.
inline constexpr double kStillTipMm = 1e-6;

/// The block's time (min) under the rule above. `tip_path_mm`: length of the executed tip path
/// in W; `tip_moves`: the CL tip points differ (kStillTipMm); `rotary_travel_deg`: the largest
/// rotary step. 0 for a block that moves nothing.
double inverse_time_minutes(double tip_path_mm, bool tip_moves, double rotary_travel_deg, double feed_mm_min);

/// The feed (mm/min, or deg/min for a pure reorientation) that gives a block `minutes`: the
/// inverse of inverse_time_minutes (0 for a block that moves nothing).
double feed_for_minutes(double tip_path_mm, bool tip_moves, double rotary_travel_deg, double minutes);

/// The length (mm) of the curve tip_at(t), t in [0, 1], from a polyline refined where the curve
/// bows: each half is split again until splitting changes its length by less than 1e-7 mm (at least
/// 4, at most 2^12 pieces), each piece's length extrapolated from its chord and its two halves
/// (halves + (halves - chord) / 3, Richardson: exact to the fourth order of the step). `tip_at` is the tool tip (W) at
/// the commands interpolated linearly.
double tip_path_length_mm(const std::function<Vec3d(double t)>& tip_at);
/// The same with the ends tip_at(0) = `start_mm` and tip_at(1) = `end_mm` given.
double tip_path_length_mm(const std::function<Vec3d(double t)>& tip_at, const Vec3d& start_mm, const Vec3d& end_mm);

}  // namespace ncpost
