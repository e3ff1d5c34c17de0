// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/solve/play_subdivision.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace ncpost {
namespace {

/// Stretches per input block before giving up (each one ends at a turn of an axis with reversal).
constexpr int kMaxStretches = 64;

/// Where an axis stands counts as moved beyond this (the IK's own tolerances: mm, rad).
double still_within(int axis) {
  return axis < 3 ? ActualSolver::kPostTipToleranceMm : ActualSolver::kPostAxisToleranceRad;
}

/// A move of an axis shows which way it goes beyond this: one step of the NC words, at least the
/// IK's tolerance (mm, rad).
double direction_shown_beyond(int axis, const WordSteps& steps) {
  return std::max(still_within(axis), axis < 3 ? steps.linear_mm : steps.rotary_rad);
}

/// The commands with every axis with reversal whose first move (standing at `stands`, going where
/// the first node that moves it beyond `direction_shown_beyond` puts it) starts on the other side
/// of its play than `command` stands: that axis's command moved to the edge of the band the move
/// runs on. nullopt when no axis needs it.
std::optional<AxisPosition> take_up_before(const ActualSolver& actual, const AxisPosition& command,
                                           const AxisPosition& stands, const std::vector<nonlinear::BlockNode>& nodes,
                                           const WordSteps& steps) {
  const comp::MachineModel& model = actual.model();
  AxisPosition q = command;
  bool any = false;
  const int n = static_cast<int>(model.machine().axes.size());
  for (int a = 0; a < n; ++a) {
    const int p = model.layout().reversal_of(a);
    if (p < 0) continue;
    const double shown = direction_shown_beyond(a, steps);
    double move = 0.0;
    for (const auto& node : nodes) {
      move = actual.stands_after(node.q, stands)[a] - stands[a];
      if (std::abs(move) > shown) break;
    }
    if (std::abs(move) <= shown) continue;
    const double band = model.values()[static_cast<std::size_t>(p)];
    const double lo = std::min(0.0, band), hi = std::max(0.0, band);
    const double edge = stands[a] - (move > 0.0 ? lo : hi);  // rising: actual = command + lo
    if (std::abs(edge - command[a]) > 1e-12) {
      q[a] = edge;
      any = true;
    }
  }
  if (!any) return std::nullopt;
  return q;
}

/// Largest difference between two positions of the axes with reversal, in units of still_within.
double turned_by(const comp::MachineModel& model, const AxisPosition& a, const AxisPosition& b) {
  double worst = 0.0;
  const int n = static_cast<int>(model.machine().axes.size());
  for (int i = 0; i < n; ++i)
    if (model.layout().reversal_of(i) >= 0) worst = std::max(worst, std::abs(a[i] - b[i]) / still_within(i));
  return worst;
}

bool same_commands(const AxisPosition& a, const AxisPosition& b) {
  return (a.linear_mm - b.linear_mm).cwiseAbs().maxCoeff() <= 1e-12 &&
         max_abs_step(a.rotary_rad, b.rotary_rad) <= 1e-12;
}

/// The commands the stretch from `cur` ends at: `to.q` where the actual machine reaches `to.cl`
/// with it (the axes standing at `stands`), else solved there; nullopt with `failure`.
std::optional<AxisPosition> stretch_end(const ActualSolver& actual, SolverData& data, const SolvedPoint& cur,
                                        const SolvedPoint& to, const std::optional<AxisPosition>& stands,
                                        std::string& failure) {
  if (actual.reaches(to.cl, to.q, stands)) return to.q;
  const IkOutcome o = actual.solve_standing(to.cl, cur.q, data, nullptr, stands);
  if (!o.ok()) {
    failure = o.failure.message;
    return std::nullopt;
  }
  return *o.position;
}

/// The way each axis starts: points along the stretch from `cur` to `to` (its end `end`), solved
/// with the axes standing at `stands`, for take_up_before.
std::vector<nonlinear::BlockNode> start_probes(const ActualSolver& actual, SolverData& data, const SolvedPoint& cur,
                                               const SolvedPoint& to, const AxisPosition& end,
                                               const AxisPosition& stands) {
  std::vector<nonlinear::BlockNode> probes;
  for (double t : {1.0 / 256, 1.0 / 64, 1.0 / 16, 0.25, 0.5}) {
    const ClPoint p = nonlinear::cl_at(cur.cl, to.cl, t);
    const IkOutcome o = actual.solve_standing(p, cur.q, data, nullptr, stands);
    if (o.ok()) probes.push_back({t, p, *o.position});
  }
  probes.push_back({1.0, to.cl, end});
  return probes;
}

/// How many of the nodes, replayed in sequence through the dead band from `stands`, stand where
/// the stretch's model (every node from `stands`) puts them.
std::size_t nodes_in_sequence(const ActualSolver& actual, const std::vector<nonlinear::BlockNode>& nodes,
                              const AxisPosition& stands) {
  AxisPosition in_sequence = stands;
  std::size_t k = 0;
  for (; k < nodes.size(); ++k) {
    const AxisPosition next = actual.stands_after(nodes[k].q, in_sequence);
    if (turned_by(actual.model(), next, actual.stands_after(nodes[k].q, stands)) > 1.0) break;
    in_sequence = next;
  }
  return k;
}

}  // namespace

std::vector<SolvedPoint> subdivide_with_play(const Machine& machine, const Setup& setup, const ActualSolver& actual,
                                             SolverData& data, const SolvedPoint& from, const SolvedPoint& to,
                                             const nonlinear::CompensationOptions& options, const WordSteps& steps,
                                             std::string& failure) {
  std::vector<SolvedPoint> out;
  std::optional<AxisPosition> stands = data.stands;
  SolvedPoint cur{from.cl, from.q};
  bool taken_up = false;  // at most one take-up per stretch start
  for (int stretch = 0; stretch < kMaxStretches; ++stretch) {
    const std::optional<AxisPosition> end = stretch_end(actual, data, cur, to, stands, failure);
    if (!end) return {};
    if (stands && !taken_up) {
      // the way each axis starts, from points along the stretch: take up the play before it
      const std::vector<nonlinear::BlockNode> probes = start_probes(actual, data, cur, to, *end, *stands);
      taken_up = true;
      if (auto q = take_up_before(actual, cur.q, *stands, probes, steps)) {
        cur = {cur.cl, *q};
        out.push_back(cur);
        continue;  // the stretch again from the taken-up commands
      }
    }
    auto ik = [&](const ClPoint& cl, const AxisPosition& previous) {
      return actual.solve_standing(cl, previous, data, nullptr, stands);
    };
    const nonlinear::ClBlock block{cur.cl, to.cl, cur.q, *end};
    const nonlinear::SplitBlock split =
        nonlinear::compensate_block(machine, setup, block, actual.errors_from(stands), ik, options);
    if (!split.ok()) {
      failure = split.failure;
      return {};
    }
    if (!stands) {  // no history: offsets 0 throughout, one stretch
      for (const auto& node : split.nodes) out.push_back({node.cl, node.q});
      return out;
    }
    // replay the nodes in sequence through the dead band
    std::size_t k = nodes_in_sequence(actual, split.nodes, *stands);
    if (k == split.nodes.size()) {
      for (const auto& node : split.nodes) out.push_back({node.cl, node.q});
      if (!same_commands(*end, to.q)) out.push_back({to.cl, to.q});  // the held end, inside the play
      return out;
    }
    k = std::max<std::size_t>(k, 1);  // the first node follows the stretch's model by construction
    for (std::size_t i = 0; i < k; ++i) out.push_back({split.nodes[i].cl, split.nodes[i].q});
    cur = {split.nodes[k - 1].cl, split.nodes[k - 1].q};
    AxisPosition in_sequence = *stands;
    for (std::size_t i = 0; i < k; ++i) in_sequence = actual.stands_after(split.nodes[i].q, in_sequence);
    stands = in_sequence;
    taken_up = false;
  }
  failure = fmt::format("an axis with reversal turns back more than {} times inside one block", kMaxStretches);
  return {};
}

}  // namespace ncpost
