// SPDX-License-Identifier: Apache-2.0
// The branch planner (branch_plan.hpp) on synthetic candidate lists: one rotary angle per
// candidate (the second stays 0), a step is a forced change when it turns more than 0.5 rad.
// Branch A falls from 1.3 to 0.4, branch B rises from 1.8 to 3.0; where a point lacks a branch the
// limits exclude it there.
#include <catch2/catch.hpp>

#include <algorithm>

#include "ncpost/postproc/solve/branch_plan.hpp"

using namespace ncpost;

namespace {

Eigen::Vector2d at(double a) { return Eigen::Vector2d(a, 0.0); }

const ForcedChange kJump = [](std::size_t, const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
  return (to - from).cwiseAbs().sum() > 0.5;
};

std::vector<double> angles(const BranchCandidates& c, const BranchPlan& p) {
  std::vector<double> out;
  for (std::size_t i = 0; i < p.choice.size(); ++i) out.push_back(c[i][p.choice[i]][0]);
  return out;
}

}  // namespace

TEST_CASE("branch plan: greedy changes twice where the look-ahead changes once") {
  // greedy: A (nearest the start 1.5) until B is the only one (change), B, then A only (change)
  const BranchCandidates c{{at(1.3), at(1.8)}, {at(0.9), at(2.2)}, {at(2.6)}, {at(0.5), at(3.0)}, {at(0.4)}};
  const BranchPlan greedy = greedy_branches(at(1.5), c, kJump);
  CHECK(greedy.changes == 2);
  CHECK(angles(c, greedy) == std::vector<double>{1.3, 0.9, 2.6, 3.0, 0.4});
  const BranchPlan plan = plan_branches(at(1.5), c, kJump, 100);
  CHECK(plan.changes == 1);
  // the one change where it costs the least travel: down to A at its point 4 (0.5), not at 5
  CHECK(angles(c, plan) == std::vector<double>{1.8, 2.2, 2.6, 0.5, 0.4});
  CHECK(plan.travel_rad == Approx(3.3));
}

TEST_CASE("branch plan: greedy changes once where the look-ahead needs no change") {
  const BranchCandidates c{{at(1.3), at(1.8)}, {at(0.9), at(2.2)}, {at(2.6)}, {at(0.5), at(3.0)}};
  CHECK(greedy_branches(at(1.5), c, kJump).changes == 1);
  const BranchPlan plan = plan_branches(at(1.5), c, kJump, 100);
  CHECK(plan.changes == 0);
  CHECK(angles(c, plan) == std::vector<double>{1.8, 2.2, 2.6, 3.0});
  CHECK(plan.travel_rad == Approx(1.5));
}

TEST_CASE("branch plan: without forced changes the plan is the greedy choice") {
  // both branches all along: A stays nearest the start; the plan keeps it (least travel)
  const BranchCandidates c{{at(1.3), at(1.8)}, {at(1.1), at(2.2)}, {at(0.9), at(2.6)}, {at(0.7), at(3.0)}};
  const BranchPlan greedy = greedy_branches(at(1.5), c, kJump);
  const BranchPlan plan = plan_branches(at(1.5), c, kJump, 100);
  CHECK(greedy.changes == 0);
  CHECK(plan.changes == 0);
  CHECK(plan.choice == greedy.choice);
  CHECK(plan.travel_rad == Approx(greedy.travel_rad));
  // the second candidate first in the lists: still the nearest (the order only breaks ties)
  const BranchCandidates swapped{{at(1.8), at(1.3)}, {at(2.2), at(1.1)}, {at(2.6), at(0.9)}, {at(3.0), at(0.7)}};
  CHECK(angles(swapped, plan_branches(at(1.5), swapped, kJump, 100)) == std::vector<double>{1.3, 1.1, 0.9, 0.7});
  // equal travel both ways: the earlier candidate
  const BranchCandidates tie{{at(1.0), at(2.0)}};
  CHECK(plan_branches(at(1.5), tie, kJump, 100).choice == std::vector<std::size_t>{0});
}

TEST_CASE("branch plan: a run longer than the window is planned window by window") {
  // windows of 2 points: the first window cannot see that A ends at point 3 (least travel: A)
  const BranchCandidates c{{at(1.3), at(1.8)}, {at(0.9), at(2.2)}, {at(2.6)}, {at(0.5), at(3.0)}};
  const BranchPlan windowed = plan_branches(at(1.5), c, kJump, 2);
  CHECK(windowed.changes == 1);
  CHECK(angles(c, windowed) == std::vector<double>{1.3, 0.9, 2.6, 3.0});
  // a window of 3 sees it
  CHECK(plan_branches(at(1.5), c, kJump, 3).changes == 0);
  // a window of 1 is the greedy choice
  CHECK(plan_branches(at(1.5), c, kJump, 1).choice == greedy_branches(at(1.5), c, kJump).choice);
}

TEST_CASE("branch plan: the forced test sees the point and both ends; the start counts") {
  // a change at the first point (from the start) counts; the callback is asked with the point index
  std::vector<std::size_t> asked;
  const ForcedChange spy = [&](std::size_t i, const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
    asked.push_back(i);
    return kJump(i, from, to);
  };
  const BranchCandidates c{{at(3.0)}, {at(3.1)}};
  const BranchPlan plan = plan_branches(at(0.0), c, spy, 100);
  CHECK(plan.changes == 1);
  CHECK(plan.travel_rad == Approx(3.1));
  CHECK(std::find(asked.begin(), asked.end(), 0) != asked.end());
  CHECK(std::find(asked.begin(), asked.end(), 1) != asked.end());
}
