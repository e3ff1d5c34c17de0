// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/solve/branch_plan.hpp"

#include <cassert>
#include <limits>

namespace ncpost {
namespace {

/// Cost of a partial plan, compared lexicographically: forced changes first, then travel.
struct Cost {
  std::size_t changes = 0;
  double travel_rad = 0.0;
  bool operator<(const Cost& o) const {
    return changes != o.changes ? changes < o.changes : travel_rad < o.travel_rad - 1e-12;
  }
};

double travel(const RotaryAngles& from, const RotaryAngles& to) { return (to - from).cwiseAbs().sum(); }

/// Viterbi over the points [begin, end) from `start`; appends the choices to `plan`.
void plan_window(const RotaryAngles& start, const BranchCandidates& candidates, const ForcedChange& forced,
                 std::size_t begin, std::size_t end, BranchPlan& plan) {
  std::vector<std::vector<std::size_t>> back(end - begin);
  std::vector<Cost> cost, next;
  for (const RotaryAngles& c : candidates[begin]) {
    Cost k;
    k.changes = forced(begin, start, c) ? 1 : 0;
    k.travel_rad = travel(start, c);
    cost.push_back(k);
  }
  back[0].assign(candidates[begin].size(), 0);
  for (std::size_t i = begin + 1; i < end; ++i) {
    const auto& from = candidates[i - 1];
    const auto& to = candidates[i];
    next.assign(to.size(), Cost{std::numeric_limits<std::size_t>::max(), 0.0});
    back[i - begin].assign(to.size(), 0);
    // (from the outer loop: the caller's test sees the same `from` in a row; ties keep the earlier a)
    for (std::size_t a = 0; a < from.size(); ++a) {
      for (std::size_t b = 0; b < to.size(); ++b) {
        Cost k = cost[a];
        k.changes += forced(i, from[a], to[b]) ? 1 : 0;
        k.travel_rad += travel(from[a], to[b]);
        if (k < next[b]) {
          next[b] = k;
          back[i - begin][b] = a;
        }
      }
    }
    cost.swap(next);
  }
  std::size_t best = 0;
  for (std::size_t b = 1; b < cost.size(); ++b)
    if (cost[b] < cost[best]) best = b;
  std::vector<std::size_t> choice(end - begin);
  for (std::size_t i = end - begin; i-- > 0;) {
    choice[i] = best;
    best = back[i][best];
  }
  plan.choice.insert(plan.choice.end(), choice.begin(), choice.end());
}

/// Changes and travel of the choices in `plan` from `start`.
void account(const RotaryAngles& start, const BranchCandidates& candidates, const ForcedChange& forced,
             BranchPlan& plan) {
  RotaryAngles at = start;
  plan.changes = 0;
  plan.travel_rad = 0.0;
  for (std::size_t i = 0; i < plan.choice.size(); ++i) {
    const RotaryAngles& c = candidates[i][plan.choice[i]];
    plan.changes += forced(i, at, c) ? 1 : 0;
    plan.travel_rad += travel(at, c);
    at = c;
  }
}

}  // namespace

BranchPlan plan_branches(const RotaryAngles& start_rad, const BranchCandidates& candidates, const ForcedChange& forced,
                         std::size_t window) {
  assert(window >= 1);
  BranchPlan plan;
  RotaryAngles start = start_rad;
  for (std::size_t begin = 0; begin < candidates.size(); begin += window) {
    const std::size_t end = std::min(candidates.size(), begin + window);
    plan_window(start, candidates, forced, begin, end, plan);
    start = candidates[end - 1][plan.choice.back()];
  }
  account(start_rad, candidates, forced, plan);
  return plan;
}

BranchPlan greedy_branches(const RotaryAngles& start_rad, const BranchCandidates& candidates,
                           const ForcedChange& forced) {
  BranchPlan plan;
  RotaryAngles at = start_rad;
  for (const auto& list : candidates) {
    assert(!list.empty());
    std::size_t best = 0;
    for (std::size_t b = 1; b < list.size(); ++b)
      if (travel(at, list[b]) < travel(at, list[best]) - 1e-12) best = b;
    plan.choice.push_back(best);
    at = list[best];
  }
  account(start_rad, candidates, forced, plan);
  return plan;
}

}  // namespace ncpost
