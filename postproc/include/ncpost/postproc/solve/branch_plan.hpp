// SPDX-License-Identifier: Apache-2.0
#pragma once
// Branch planning over a run of feed motions (PostOptions::branch_plan): which inverse solution
// (branch, and turn of a rotary axis whose limits span more than a turn) each CL point takes.
//
// The greedy choice takes, point by point, the solution nearest the previous commands; when the
// limits later end that branch, the post must change the solution mid-path (retract along the
// tool axis, reorient, re-engage). Planned, the choice looks at the whole run (dynamic
// programming, Viterbi): among all sequences of candidates it takes the one with the fewest forced
// changes, then the least rotary travel (sum over the axes of |Δangle|, rad). A pure function over
// candidate lists: the caller says which steps are forced changes (the post: the step swings the
// rotary axes clearly further than the unlimited machine would, `branch_changed` in post.cpp).
//
// Memory: the plan holds one back-pointer per candidate of the points it plans at once; runs
// longer than `window` points are planned window by window, each from the last choice of the
// window before (greedy at the window boundaries).
#include <cstddef>
#include <functional>
#include <vector>

#include "ncpost/kinematics/machine.hpp"

namespace ncpost {

/// The rotary angles (rad) of each candidate solution of each point, best (the solver's order) first.
using BranchCandidates = std::vector<std::vector<RotaryAngles>>;

/// True when moving from the rotary angles `from` (the point before, or the start) to `to` at point
/// `point` is a forced change of solution.
using ForcedChange = std::function<bool(std::size_t point, const RotaryAngles& from, const RotaryAngles& to)>;

struct BranchPlan {
  std::vector<std::size_t> choice;  ///< the candidate index of each point
  std::size_t changes = 0;          ///< forced changes along the plan
  double travel_rad = 0.0;          ///< rotary travel along the plan (sum over the axes)
};

/// The plan with the fewest forced changes, then the least travel, from `start_rad`; ties keep the
/// earlier candidate. Every point must have at least one candidate. `window` >= 1 points are
/// planned at once.
BranchPlan plan_branches(const RotaryAngles& start_rad, const BranchCandidates& candidates, const ForcedChange& forced,
                         std::size_t window);

/// The greedy choice (nearest the previous, ties keep the earlier candidate), for comparison.
BranchPlan greedy_branches(const RotaryAngles& start_rad, const BranchCandidates& candidates,
                           const ForcedChange& forced);

}  // namespace ncpost
