// SPDX-License-Identifier: Apache-2.0
// A CL motion to axis commands (poster.hpp): the solution (in a tilted plane, planned by the branch
// plan, solved ahead or here), the take-up of reversing axes, the retract where the limits force
// another solution, and the subdivision into blocks.
#include <fmt/format.h>

#include "ncpost/postproc/solve/unreachable.hpp"
#include "post/poster.hpp"

namespace ncpost::detail {
namespace {

/// Rotary angles (rad) in degrees for a message: "12.3450, -45.0000".
std::string degrees_list(const RotaryAngles& rotary_rad, int decimals) {
  std::string out;
  for (Eigen::Index k = 0; k < rotary_rad.size(); ++k)
    out += fmt::format("{}{:.{}f}", k ? ", " : "", rad_to_deg(rotary_rad[k]), decimals);
  return out;
}

}  // namespace

void Poster::move_to(const ClPoint& cl, int line, bool rapid, std::optional<RotaryAngles> rotary) {
  if (plane_ && (cl.axis - plane_->axis_W).norm() > 1e-9) close_plane();  // (a motion of a cycle or arc)
  if (plane_ && !rotary) hold_plane_rotary(cl, rotary);
  const SolvedPoint next = solve_motion(cl, line, rotary);
  before_motion(line, rapid);
  if (have_position_ && !rapid && options_.take_up_reversal && !options_.subdivide.takes_up_play())
    take_up_reversal(next, line);
  if (have_position_ && !rapid && !rotary && words_.branches_chosen && words_.rotary_count == 2 &&
      branch_changed(cl, next.q)) {
    if (options_.retract_mm <= 0.0)
      throw Infeasible(
          fmt::format("{}:{}: the axis limits force a change of solution (rotary {} -> {} deg) and "
                      "no retract is allowed",
                      input_, line, degrees_list(previous_.q.rotary_rad, 4), degrees_list(next.q.rotary_rad, 4)));
    retract_and_reorient(next, line);
  }
  write_motion(next, line, rapid);
  previous_ = next;
  have_position_ = true;
}

/// In a tilted plane the rotary axes stand still, where the point is within the limits there
/// (`rotary` becomes the plane's); else the plane ends and the motion is posted as without it
/// (limits, retract, message).
void Poster::hold_plane_rotary(const ClPoint& cl, std::optional<RotaryAngles>& rotary) {
  const IkOutcome ik = solver_.solve_quiet(cl, previous_.q, data_, nullptr);
  if (ik.ok() && max_abs_step(ik.position->rotary_rad, plane_->rotary_rad) < 1e-9)
    rotary = plane_->rotary_rad;
  else
    close_plane();
}

/// The commands for `cl`: at the given rotary angles, else the solution the branch plan chose,
/// the one solved ahead, or the one solved here nearest the previous commands.
SolvedPoint Poster::solve_motion(const ClPoint& cl, int line, const std::optional<RotaryAngles>& rotary) {
  SolvedPoint next{cl, {}};
  if (rotary) {
    next.q = solver_.with_rotary(cl, *rotary, data_);
    return next;
  }
  const bool ahead_fits = ahead_ && ahead_->fits(cl, previous_.q);
  IkOutcome ik;
  if (std::optional<IkOutcome> planned = planned_solution(cl, ahead_fits)) ik = std::move(*planned);
  planned_rotary_.reset();
  if (ik.ok()) {
  } else if (ahead_fits && ahead_) {  // solved on the read-ahead thread
    ik = ahead_->ik;
    data_.record(ahead_->figures);
    ahead_ = nullptr;
  } else {
    ik = solver_.solve(cl, previous_.q, data_);
  }
  if (!ik.ok())
    throw Infeasible(unreachable_message(input_, line, solver_, data_, cl, previous_.q, ik.failure.message));
  next.q = *ik.position;
  next.executed = ik.executed;
  return next;
}

/// The solution the branch plan chose: the one nearest its rotary angles (nullopt: the greedy one).
std::optional<IkOutcome> Poster::planned_solution(const ClPoint& cl, bool ahead_fits) {
  if (!planned_rotary_ || (ahead_fits && ahead_->ik.ok() && ahead_->ik.position->rotary_rad == *planned_rotary_))
    return std::nullopt;
  AxisPosition toward = previous_.q;
  toward.rotary_rad = *planned_rotary_;
  SolveFigures figures;
  IkOutcome planned = solver_.solve_quiet(cl, toward, data_, &figures);
  ahead_ = nullptr;
  // (the same branch and turn: solutions apart are >= branch_change_rad apart; under --model
  // the compensated angles may differ from the plan's in the last digits)
  if (!(planned.ok() && max_abs_step(planned.position->rotary_rad, *planned_rotary_) < 1e-6)) return std::nullopt;
  data_.record(figures);
  return planned;
}

/// RTCP on before the first motion (the tool in the spindle: 1), and the notice of a feed motion
/// before any feed.
void Poster::before_motion(int line, bool rapid) {
  if (options_.rtcp && !rtcp_on_) {  // motion before any tool change: the tool in the spindle (1)
    writer_.rtcp(true, tool_, length_register());
    rtcp_on_ = true;
  }
  if (!rapid && !records_.feed_given() && !default_feed_noticed_) {
    summary_.notices.push_back(fmt::format("{}:{}: feed motion before any FEDRAT: using {:.0f} mm/min", input_, line,
                                           options_.default_feed_mm_min));
    default_feed_noticed_ = true;
  }
}

/// An actual machine with reversal: take up the play of reversing axes first (tool still).
void Poster::take_up_reversal(const SolvedPoint& next, int line) {
  if (auto q = hooks_.take_up(previous_.q, next.q, data_)) {
    const SolvedPoint still{previous_.cl, *q};
    emit(previous_, still, line, false);
    previous_ = still;
  }
}

/// The blocks from the previous point to `next`: subdivided to the tolerance, else one.
void Poster::write_motion(const SolvedPoint& next, int line, bool rapid) {
  // (in a tilted plane the tool axis and the rotary axes are still: a straight line, nothing to bound)
  if (have_position_ && (!rapid || options_.subdivide_rapids) && options_.subdivide && !options_.rtcp && !plane_) {
    SolvedPoint from = previous_;
    std::vector<SolvedPoint> points;
    try {
      if (ahead_cut_ && ahead_cut_->fits(previous_, next)) {  // cut on the read-ahead thread (once)
        points = std::move(ahead_cut_->points);
        ahead_cut_ = nullptr;
      } else {
        points = options_.subdivide(previous_, next, data_);
      }
    } catch (const Infeasible& e) {
      throw Infeasible(fmt::format("{}:{}: {}", input_, line, e.what()));
    }
    for (const SolvedPoint& p : points) {
      emit(from, p, line, rapid);
      from = p;
    }
  } else {
    emit(previous_, next, line, rapid);
  }
}

/// True when `q` (solved for `cl`) is on another branch than the continuous one because of the limits.
bool Poster::branch_changed(const ClPoint& cl, const AxisPosition& q) const {
  return forced_change(cl.axis, previous_.q.rotary_rad, q.rotary_rad);
}

/// Retract along the tool axis from the previous point, reorient above `next` on its branch,
/// then the caller re-engages (feeds down to `next`).
void Poster::retract_and_reorient(const SolvedPoint& next, int line) {
  const double d = options_.retract_mm;
  const ClPoint up_here{previous_.cl.tip_mm + d * previous_.cl.axis, previous_.cl.axis};
  const ClPoint up_there{next.cl.tip_mm + d * next.cl.axis, next.cl.axis};
  const IkOutcome a = solver_.solve(up_here, previous_.q, data_);
  const IkOutcome b = solver_.solve(up_there, next.q, data_);
  if (!a.ok() || !b.ok())
    throw Infeasible(unreachable_message(
        input_, line, solver_, data_, !a.ok() ? up_here : up_there, !a.ok() ? previous_.q : next.q,
        fmt::format("the axis limits force a change of solution, and the retract point {} mm along the tool axis "
                    "is out of reach: {}",
                    d, !a.ok() ? a.failure.message : b.failure.message)));
  summary_.notices.push_back(fmt::format(
      "{}:{}: the axis limits force a change of solution (rotary {} -> {} deg): retract {} mm along the tool "
      "axis, reorient, re-engage",
      input_, line, degrees_list(previous_.q.rotary_rad, 3), degrees_list(next.q.rotary_rad, 3), d));
  ++summary_.retracts;
  writer_.comment("retract, reorient, re-engage (axis limits)");
  const SolvedPoint p1{up_here, *a.position}, p2{up_there, *b.position};
  emit(previous_, p1, line, false);
  emit(p1, p2, line, true);
  previous_ = p2;
}

}  // namespace ncpost::detail
