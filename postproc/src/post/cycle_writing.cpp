// SPDX-License-Identifier: Apache-2.0
// Drilling cycles in the post (poster.hpp): a hole of the active cycle as native cycle words
// (cycle_words.hpp) where it runs down −Z of the program frame, else explicit moves along the
// tool axis (post_cycle.hpp).
#include <fmt/format.h>

#include <cmath>

#include "ncpost/postproc/verify/verify_arc.hpp"
#include "ncpost/postproc/write/cycle_words.hpp"
#include "post/poster.hpp"
#include "write/post_cycle.hpp"

namespace ncpost::detail {

/// One hole of the active cycle: native (cycle_words.hpp) where the hole runs down −Z of the
/// program frame, else explicit moves along the tool axis (post_cycle.hpp).
void Poster::drill(const cl::Motion& m) {
  const HolePlanes p = hole_planes(cycle_, m.point);
  const double rpm = records_.spindle_rpm();
  const SourcePosition at{input_, m.where.line, m.where.column};
  double feed = records_.feed_mm_min(options_.default_feed_mm_min);
  if (cycle_.feed && cycle_.feed_per_rev && !(rpm > 0.0))
    throw InputError(at, "a cycle feed per revolution before any spindle speed (give SPINDL/rpm before the cycle)");
  if (cycle_.feed) feed = cycle_.feed_per_rev ? *cycle_.feed * rpm : *cycle_.feed;
  if (cycle_.kind == cl::Cycle::Kind::tap) {
    if (!(rpm > 0.0))
      throw InputError(at,
                       "a tapped hole before any spindle speed: the tapping feed (pitch x rpm) is unknown "
                       "(give SPINDL/rpm before the cycle)");
    feed = cycle_.pitch_mm * rpm;
  }
  if (native_hole(p, feed, m.where.line)) return;
  const RecordBlocks::Saved saved = records_.save();
  move_to(p.retract, m.where.line, true);
  for (const HoleStep& s : expand_hole(cycle_, p, feed, records_.spindle_ccw())) {
    using Kind = HoleStep::Kind;
    if (s.kind == Kind::rapid || s.kind == Kind::feed) {
      records_.set_feed(s.feed_mm_min > 0.0 ? s.feed_mm_min : feed);
      move_to(s.to, m.where.line, s.kind == Kind::rapid);
    } else if (s.kind == Kind::dwell) {
      for (const std::string& b : dwell_blocks(writer_.dialect(), s.dwell_s)) writer_.block(b);
    } else if (s.turn == HoleStep::Turn::stop) {
      writer_.spindle_stop();
    } else {
      writer_.spindle_turn(s.turn == HoleStep::Turn::counter_clockwise);
    }
  }
  records_.restore(saved);
}

bool Poster::native_hole(const HolePlanes& p, double feed, int line) {
  const auto words = cycle_words(writer_.dialect());
  if (!options_.native_cycles || !words) return false;
  const IkOutcome ik = solver_.solve(p.retract, previous_.q, data_);
  if (!ik.ok()) return false;  // the expansion names the failure
  const RotaryAngles rotary = ik.position->rotary_rad;
  const std::function<Vec3d(const ClPoint&)> frame = [&](const ClPoint& c) -> Vec3d {
    if (plane_) return plane_->words.to_plane(c.tip_mm + home_offset_);
    return options_.rtcp ? hooks_.programmed_tip(c, *ik.position) : solver_.with_rotary(c, rotary, data_).linear_mm;
  };
  const Vec3d xt = frame(p.retract), xr = frame(p.r_plane), xb = frame(p.bottom);
  // in a tilted plane its Z (rounded angles) is within ~1e-6 rad of the hole: the hole is native
  // where that leaves its top within half the words' resolution of the bottom's X Y
  const double across = plane_ ? 0.5 * std::pow(10.0, -writer_.dialect().linear_decimals) : 1e-7;
  auto on_axis = [&](const Vec3d& a) { return std::abs(a.x() - xb.x()) < across && std::abs(a.y() - xb.y()) < across; };
  if (!on_axis(xt) || !on_axis(xr) || !(xb.z() < xr.z()) || xt.z() < xr.z() - 1e-9) return false;
  std::string note;
  const auto nc = detail::native_hole(cycle_, *words, xr, xb, p.retract_to_r, feed, records_.spindle_rpm(),
                                      writer_.dialect().linear_decimals, note);
  if (!nc) return false;
  if (!note.empty() && noticed_cycle_line_ != cycle_.where.line) {
    notice(cycle_.where, note);
    noticed_cycle_line_ = cycle_.where.line;
  }
  const SolvedPoint at_retract{p.retract, *ik.position};
  const bool same_rotary = !have_position_ || max_abs_step(rotary, previous_.q.rotary_rad) < 1e-12;
  if (have_position_ && same_rotary && writer_.continues(*nc, p.retract_to_r ? xr.z() : xt.z())) {
    // the modal cycle travels there itself: the tool stands at the return level over the hole
    AxisPosition executed = at_retract.q;
    if (plane_)
      executed = plane_executed(xt);
    else
      for (int i = 0; i < 3; ++i) executed.linear_mm[i] = writer_.rounded(i, executed.linear_mm[i]);
    hooks_.advance(executed, data_);
    last_executed_ = executed;
    previous_ = at_retract;
    if (last_values_)
      for (int k = 0; k < 3; ++k) (*last_values_)[static_cast<std::size_t>(k)] = writer_.rounded(k, xt[k]);
  } else {
    writer_.end_cycle();
    move_to(p.retract, line, true);
  }
  writer_.cycle(*nc);
  last_rapid_.reset();  // the cycle leaves and enters its holes along Z itself
  last_was_feed_ = false;
  ++summary_.cycles_out;
  if (options_.verify && !options_.rtcp) verify_native_hole(p, rotary, frame, line);
  return true;
}

/// --verify of a native hole: the feed of the cycle block re-executed, R plane to the bottom (and
/// back for taps and bores).
void Poster::verify_native_hole(const HolePlanes& p, const RotaryAngles& rotary,
                                const std::function<Vec3d(const ClPoint&)>& frame, int line) {
  auto executed = [&](const ClPoint& c) {
    if (plane_) return plane_executed(frame(c));
    AxisPosition q = solver_.with_rotary(c, rotary, data_);
    for (int i = 0; i < 3; ++i) q.linear_mm[i] = writer_.rounded(i, q.linear_mm[i]);
    return q;
  };
  const double e =
      verify_block(solver_, data_, p.r_plane, executed(p.r_plane), p.bottom, executed(p.bottom), line, summary_.verify);
  if (options_.on_verified) options_.on_verified(line, e);
}

}  // namespace ncpost::detail
