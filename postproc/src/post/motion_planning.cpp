// SPDX-License-Identifier: Apache-2.0
// Branch planning of the post (PostOptions::branch_choice, branch_plan.hpp): a run of feed motions
// is read ahead, solved greedily, and where the axis limits force changes of solution on that path
// the plan with the fewest is queued with the records (poster.hpp).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ncpost/postproc/solve/branch_plan.hpp"
#include "post/poster.hpp"

namespace ncpost::detail {
namespace {

/// A feed motion whose solution the post chooses (not a rapid, no programmed angles).
bool plannable(const cl::Motion& m) { return !m.rapid && !m.from && !m.rotary_rad; }
/// A rapid (or FROM) whose solution the post chooses: it may open a run (any solution is free there).
bool free_start(const cl::Motion& m) { return (m.rapid || m.from) && !m.rotary_rad; }

/// Records that may stand between the feed motions of one run (they move nothing).
bool passes(const cl::Record& r) {
  return std::holds_alternative<cl::Feed>(r) || std::holds_alternative<cl::Spindle>(r) ||
         std::holds_alternative<cl::Coolant>(r) || std::holds_alternative<cl::Comment>(r) ||
         std::holds_alternative<cl::Unsupported>(r) || std::holds_alternative<cl::Dwell>(r) ||
         std::holds_alternative<cl::Stop>(r);
}

const cl::Motion& motion_of(const AheadItem& item) { return std::get<cl::Motion>(*item.record); }

/// The CL point of the k-th motion of a run.
const ClPoint& point_of(const std::deque<AheadItem>& items, const std::vector<std::size_t>& motions, std::size_t k) {
  return motion_of(items[motions[k]]).point;
}

}  // namespace

/// True when `item` (read from the input, not planned yet) opens a run of feed motions to plan:
/// a two-rotary serial machine whose solver depends on nothing the post's progress changes.
bool Poster::starts_run(const AheadItem& item) const {
  if (options_.branch_choice != PostOptions::BranchChoice::lookahead || !words_.branches_chosen ||
      words_.rotary_count != 2 || !solver_.concurrent() || item.error || !item.record)
    return false;
  const auto* m = std::get_if<cl::Motion>(&*item.record);
  return m && (plannable(*m) || free_start(*m)) && cycle_.kind == cl::Cycle::Kind::off && !pending_circle_;
}

/// True while the feed motions of a run longer than one window go on: such a run is posted
/// greedily as a whole (a plan that starts mid-run is not attempted).
bool Poster::continues_unplanned_run(const AheadItem& item) {
  if (!unplanned_run_) return false;
  const auto* m = item.record ? std::get_if<cl::Motion>(&*item.record) : nullptr;
  if ((m && plannable(*m)) || (item.record && !m && passes(*item.record))) return true;
  unplanned_run_ = false;
  return false;
}

/// The continuity test of the post: moving the rotary axes from `from` to `to` for the tool axis
/// `axis_W` travels clearly further than the machine without limits would (another branch).
bool Poster::forced_change(const Vec3d& axis_W, const RotaryAngles& from, const RotaryAngles& to) const {
  const double chosen = (to - from).cwiseAbs().sum();
  if (chosen <= options_.branch_change_rad) return false;  // the free travel is >= 0
  const auto free = unlimited_rotary_travel(machine_, axis_W, from);
  if (!free) return false;
  return chosen > *free + options_.branch_change_rad;
}

/// Reads the run that `first` (a feed motion, or a rapid that leads to feed motions) opens: up to
/// kPlanWindow motions, and the record that ends it (a rapid that ends it opens the next run),
/// chooses the solution of each motion, and queues the records with the choice.
void Poster::plan_run(AheadItem first, const Fetch& fetch) {
  std::deque<AheadItem>& items = pending_;  // (empty: a run opens once all before it is posted)
  std::vector<std::size_t> motions{0};
  items.push_back(std::move(first));
  while (motions.size() < kPlanWindow && items.size() < 4 * kPlanWindow) {
    AheadItem item = fetch();
    bool stop = item.error || !item.record;
    bool motion = false;
    if (!stop) {
      if (const auto* m = std::get_if<cl::Motion>(&*item.record))
        (plannable(*m) ? motion : stop) = true;
      else
        stop = !passes(*item.record);
    }
    if (stop && !item.error && item.record && starts_run(item)) {
      carry_ = std::move(item);  // a rapid: it opens the next run
      break;
    }
    items.push_back(std::move(item));
    if (motion) motions.push_back(items.size() - 1);
    if (stop) break;
  }
  plan_motions(items, motions, motions.size() == kPlanWindow);
}

/// The greedy solutions of the motions (kept as solved ahead: the post uses them as it goes);
/// where the limits force changes of solution on that path, the plan with the fewest.
/// `window_full`: the run goes on after these motions.
void Poster::plan_motions(std::deque<AheadItem>& items, std::vector<std::size_t> motions, bool window_full) {
  std::vector<AxisPosition> greedy;  // the commands each motion is solved from, then its own
  const std::size_t greedy_changes = solve_greedily(items, motions, greedy);
  if (window_full) {  // the run goes on beyond the window: posted greedily as a whole
    unplanned_run_ = true;
    if (greedy_changes > 0)
      summary_.notices.push_back(fmt::format(
          "{}:{}: a run of more than {} feed motions is not planned ahead (--branch-plan lookahead): its solutions "
          "are chosen motion by motion",
          input_, motion_of(items[motions.front()]).where.line, kPlanWindow));
    return;
  }
  if (greedy_changes == 0) return;  // nothing to improve: the greedy program
  const std::optional<std::size_t> changes = plan_fewest_changes(items, motions, greedy, greedy_changes);
  if (!changes) return;
  const int first_line = motion_of(items[motions.front()]).where.line;
  const int last_line = motion_of(items[motions.back()]).where.line;
  summary_.notices.push_back(fmt::format(
      "{}:{}: the rotary solutions of lines {} to {} are planned ahead: the axis limits force {} change{} of "
      "solution there instead of {} (--branch-plan greedy){}",
      input_, first_line, first_line, last_line, *changes, *changes == 1 ? "" : "s", greedy_changes, ""));
  ++summary_.planned_runs;
}

/// Solves the motions of a run one after the other, each from the solution before it (kept in the
/// items as solved ahead); the motions end before the first that has no solution. `greedy` gets
/// the commands each motion is solved from. Returns the forced changes of solution on that path.
std::size_t Poster::solve_greedily(std::deque<AheadItem>& items, std::vector<std::size_t>& motions,
                                   std::vector<AxisPosition>& greedy) {
  // a rapid first: any solution is free there (the post tests no change of solution on rapids)
  const bool rapid_first = !plannable(motion_of(items[motions[0]]));
  auto tested = [&](std::size_t k) { return k > 0 ? true : !rapid_first && have_position_; };
  AxisPosition q = previous_.q;
  std::size_t greedy_changes = 0;
  for (std::size_t k = 0; k < motions.size(); ++k) {
    AheadItem& item = items[motions[k]];
    const ClPoint& point = point_of(items, motions, k);
    if (!(item.solved && item.solved->fits(point, q))) {
      AheadSolve s{point, q, {}, {}};
      try {
        s.ik = solver_.solve_quiet(point, q, plan_data_, &s.figures);
      } catch (...) {
        s.ik = {};  // the post solves this motion itself and meets the failure there
      }
      item.solved.reset();
      if (s.ik.ok()) item.solved = std::move(s);
    }
    if (!item.solved || !item.solved->ik.ok()) {
      motions.resize(k);  // the post names the failure; the plan ends before it
      break;
    }
    const AxisPosition& next = *item.solved->ik.position;
    if (tested(k) && forced_change(point.axis, q.rotary_rad, next.rotary_rad)) ++greedy_changes;
    greedy.push_back(q);
    q = next;
  }
  return greedy_changes;
}

/// The plan with the fewest forced changes of solution over every branch (and whole turn) of each
/// motion; queued with the items when it has fewer than the greedy path (and a retract is allowed
/// where it still has one). Returns its changes when queued.
std::optional<std::size_t> Poster::plan_fewest_changes(std::deque<AheadItem>& items,
                                                       const std::vector<std::size_t>& motions,
                                                       const std::vector<AxisPosition>& greedy,
                                                       std::size_t greedy_changes) {
  const bool rapid_first = !plannable(motion_of(items[motions[0]]));
  auto tested = [&](std::size_t k) { return k > 0 ? true : !rapid_first && have_position_; };
  BranchCandidates candidates(motions.size());
  for (std::size_t k = 0; k < motions.size(); ++k) {
    std::vector<RotaryAngles>& list = candidates[k];
    list.push_back(items[motions[k]].solved->ik.position->rotary_rad);  // the greedy choice first
    std::vector<AxisPosition> branches;
    try {
      branches = solver_.branches(point_of(items, motions, k), greedy[k], plan_data_);
    } catch (...) {
      return std::nullopt;  // (a solver that fails here fails the post at this motion, or solves it greedily)
    }
    for (const AxisPosition& b : branches)
      for (const RotaryAngles& turned : turns(b.rotary_rad))
        if (std::none_of(list.begin(), list.end(),
                         [&](const RotaryAngles& c) { return max_abs_step(c, turned) < 1e-9; }))
          list.push_back(turned);
  }
  // the free travel from one candidate to the next point, computed once for all its candidates
  struct {
    std::size_t k = SIZE_MAX;
    RotaryAngles from;
    std::optional<double> free;
  } last;
  const ForcedChange forced = [&](std::size_t k, const RotaryAngles& from, const RotaryAngles& to) {
    if (!tested(k)) return false;
    const double chosen = (to - from).cwiseAbs().sum();
    if (chosen <= options_.branch_change_rad) return false;
    if (last.k != k || last.from != from)
      last = {k, from, unlimited_rotary_travel(machine_, point_of(items, motions, k).axis, from)};
    return last.free && chosen > *last.free + options_.branch_change_rad;
  };
  const BranchPlan plan = plan_branches(previous_.q.rotary_rad, candidates, forced, kPlanWindow);
  // (no retract allowed: the post fails at the first change either way, the greedy one names it)
  if (plan.changes >= greedy_changes || (plan.changes > 0 && options_.retract_mm <= 0.0)) return std::nullopt;
  for (std::size_t k = 0; k < motions.size(); ++k) items[motions[k]].planned_rotary_rad = candidates[k][plan.choice[k]];
  return plan.changes;
}

/// The rotary angles `rotary_rad` and their whole turns within the limits (at most two turns
/// either way; an axis without limits: one turn either way).
std::vector<RotaryAngles> Poster::turns(const RotaryAngles& rotary_rad) const {
  std::vector<RotaryAngles> out{rotary_rad};
  for (int k = 0; k < machine_.rotary_count(); ++k) {
    const Axis& axis = machine_.rotary(k);
    std::vector<RotaryAngles> grown;
    for (const RotaryAngles& partial : out)
      for (int t : {0, -1, 1, -2, 2}) {
        const double v = rotary_rad[k] + 2.0 * kPi * t;
        if (axis.limits ? !axis.limits->contains(v) : std::abs(t) > 1) continue;
        grown.push_back(partial);
        grown.back()[k] = v;
      }
    out = std::move(grown);
  }
  return out;
}

}  // namespace ncpost::detail
