// SPDX-License-Identifier: Apache-2.0
// One motion block of the post (poster.hpp): its words (machine axes, the tip under RTCP or a
// tilted plane's X Y Z), the commands the control executes for the rounded words, its feed (per
// minute or inverse time, inverse_time.hpp) and rapids in two (PostOptions::order_rapids).
#include <fmt/format.h>

#include "ncpost/compensation/nonlinear_block.hpp"
#include "ncpost/postproc/solve/inverse_time.hpp"
#include "post/poster.hpp"

namespace ncpost::detail {

void Poster::emit(const SolvedPoint& from, const SolvedPoint& to, int line, bool rapid) {
  NcMotion m = motion_words(to, rapid);
  // the control executes the rounded values (in a tilted plane: through the plane's words)
  const AxisPosition executed = executed_commands(to, m);
  set_feed(m, from, to, executed, line, rapid);
  bool split = false;
  std::optional<ReadBackBlock> first_block, block;  // read back (--verify)
  WrittenState in_force = read_back_ ? writer_.in_force() : WrittenState{};
  if (rapid && options_.order_rapids && last_values_) {
    split = write_retract_or_approach(from, to, m);
    if (split && read_back_) {
      first_block = read_written(in_force, from.cl, to.cl, line);
      in_force = writer_.in_force();
    }
  }
  last_values_ = m.values;
  const bool written = writer_.motion(m);
  if (written && split) ++summary_.rapid_splits;
  if (!written && !split) return;  // the control is already there
  // (a split rapid that keeps Z is written whole by its first block: the machine is at `to` all the same)
  if (written && read_back_) block = read_written(in_force, from.cl, to.cl, line);
  if (read_back_) check_written(from, to, line, rapid, m, first_block, block);
  if (written && options_.on_block && have_position_)
    options_.on_block(WrittenBlock{line, rapid, from.cl, to.cl, last_executed_, executed});
  hooks_.advance(executed, data_);
  last_executed_ = executed;
}

/// The words of the block to `to` (mm, deg): X Y Z of a tilted plane or the tip under RTCP, then
/// the solver's command words (CommandWords).
NcMotion Poster::motion_words(const SolvedPoint& to, bool rapid) const {
  NcMotion m;
  m.rapid = rapid;
  if (plane_) {
    const Vec3d in_plane = plane_->words.to_plane(to.cl.tip_mm + home_offset_);
    for (int i = 0; i < 3; ++i) m.values[static_cast<std::size_t>(i)] = in_plane[i];
  } else if (options_.rtcp) {
    const Vec3d tip_mm = hooks_.programmed_tip(to.cl, to.q);
    for (int i = 0; i < 3; ++i) m.values[static_cast<std::size_t>(i)] = tip_mm[i];
  }
  for (int i = (options_.rtcp || plane_) ? 3 : 0; i < words_.count; ++i) {  // the words of the solver (CommandWords)
    const auto u = static_cast<std::size_t>(i);
    m.values[u] = words_.angle[u] ? rad_to_deg(to.q[i]) : to.q[i];
  }
  return m;
}

/// The commands the control executes for the words of `m` as rounded (in a tilted plane: through
/// the plane's words).
AxisPosition Poster::executed_commands(const SolvedPoint& to, const NcMotion& m) const {
  AxisPosition executed = to.q;
  if (plane_) {
    executed = plane_executed(Vec3d(m.values[0], m.values[1], m.values[2]));
  } else {
    for (int i = 0; i < words_.count; ++i)
      executed[i] = words_.angle[static_cast<std::size_t>(i)] ? deg_to_rad(writer_.rounded(i, rad_to_deg(to.q[i])))
                                                              : writer_.rounded(i, to.q[i]);
  }
  return executed;
}

/// The feed of the block: per minute, or inverse time where a rotary axis turns (or always, by
/// PostOptions::feed_mode) by the rule of inverse_time.hpp.
void Poster::set_feed(NcMotion& m, const SolvedPoint& from, const SolvedPoint& to, const AxisPosition& executed,
                      int line, bool rapid) const {
  const double feed = records_.feed_mm_min(options_.default_feed_mm_min);
  const double rotary_travel_deg =
      words_.rotary_count > 0 ? rad_to_deg(max_abs_step(to.q.rotary_rad, from.q.rotary_rad)) : 0.0;
  // (in a tilted plane the control turned the rotary axes before: the block moves X Y Z only)
  const bool simultaneous = !plane_ && words_.rotary_count > 0 && rotary_travel_deg > 1e-9;
  const bool inverse = !options_.rtcp && options_.feed_mode != PostOptions::FeedMode::per_minute &&
                       (options_.feed_mode == PostOptions::FeedMode::inverse_time || simultaneous);
  if (inverse && !rapid && writer_.dialect().motion.inverse_time.empty())
    // an inverse-time number written as a plain feed would run at the wrong feed
    throw Infeasible(fmt::format(
        "{}:{}: this move turns a rotary axis while the tool cuts, and the {} dialect has no inverse-time feed "
        "(G93) for it ([motion] inverse_time is empty in {}): post with --rtcp (the control's tool-tip control "
        "keeps the feed)",
        input_, line, writer_.dialect().name, writer_.dialect().file));
  if (inverse) {
    // the block's time by the rule of inverse_time.hpp: the executed tip path over the feed
    const bool tip_moves = (to.cl.tip_mm - from.cl.tip_mm).norm() > kStillTipMm;
    const double path_mm = tip_moves && !rapid ? executed_tip_path_mm(last_executed_, executed) : 0.0;
    const double minutes = inverse_time_minutes(path_mm, tip_moves, rotary_travel_deg, feed);
    m.feed_mode = NcMotion::FeedMode::inverse_time;
    m.feed = minutes > 0.0 ? 1.0 / minutes : 99999.0;
  } else {
    m.feed = feed;
  }
}

/// The model the program's times are computed on: the post's (under --verify-on, not the
/// verifying machine's, so that the program does not depend on it).
const KinematicModel& Poster::feed_solver() const { return options_.feed_solver ? *options_.feed_solver : solver_; }

/// The first block of a rapid in two (PostOptions::order_rapids): going up, the tool leaves
/// along its axis at `from` until it is level with the target; going down, it travels to the
/// point on the axis line of `to` level with where it is, then (the caller's block) descends
/// along that line. Level: Z of the program frame. With the tool along +Z of the program frame
/// this is Z first up / Z last down. Not split (one straight block, as the CL data give it) where
/// the tool axis is within 60 deg of horizontal in the program frame or the point on the line
/// is beyond a linear axis's limits. True when the block was written.
bool Poster::write_retract_or_approach(const SolvedPoint& from, const SolvedPoint& to, const NcMotion& m) {
  const PerAxis<double>& last = *last_values_;
  const bool up = m.values[2] > last[2];
  const SolvedPoint& still = up ? from : to;
  const Vec3d d = tool_axis_in_program(still.cl, still.q.rotary_rad);
  if (!(d.z() >= 0.5)) return false;
  const Vec3d at_still = up ? Vec3d(last[0], last[1], last[2]) : Vec3d(m.values[0], m.values[1], m.values[2]);
  const double level = up ? m.values[2] : last[2];
  const Vec3d on_line = at_still + ((level - at_still.z()) / d.z()) * d;
  NcMotion first = m;
  if (up) first.values = last;  // the rotary axes turn in the second block
  for (int i = 0; i < 3; ++i) {
    first.values[static_cast<std::size_t>(i)] = on_line[i];
    const Axis& axis = machine_.axes[static_cast<std::size_t>(i)];
    if (!plane_ && !options_.rtcp && axis.limits && !axis.limits->contains(on_line[i])) return false;
  }
  return writer_.motion(first);  // nothing is written if no word changes
}

/// The direction, in the program frame's X Y Z words, in which the tool tip moves along the tool
/// axis of `cl` (unit length in W) with the rotary axes at `rotary_rad`: +Z in a tilted plane,
/// the CL axis under RTCP (the words are the tip in W), else the linear axes' direction.
Vec3d Poster::tool_axis_in_program(const ClPoint& cl, const RotaryAngles& rotary_rad) const {
  if (plane_) return Vec3d::UnitZ();
  if (options_.rtcp) return cl.axis.normalized();
  const Vec3d tip = solver_.with_rotary(cl, rotary_rad, data_).linear_mm;
  const Vec3d above =
      solver_.with_rotary(ClPoint{cl.tip_mm + cl.axis.normalized(), cl.axis}, rotary_rad, data_).linear_mm;
  return above - tip;
}

/// The length (mm) of the tool tip's path in W while the axes run linearly from `q0` to `q1`.
/// The ends are the tips at q0 and q1 themselves; a model whose execute() has no state gives the
/// same tip at the same commands, so the start of a block is the end of the block before it.
double Poster::executed_tip_path_mm(const AxisPosition& q0, const AxisPosition& q1) const {
  const KinematicModel& feeds = feed_solver();
  auto tip_at = [&](const AxisPosition& q) { return feeds.execute(q, data_).tip_mm; };
  const bool stateless = feeds.stateless_execute();
  const Vec3d start_mm = stateless && last_feed_tip_ && last_feed_tip_->q == q0 ? last_feed_tip_->tip_mm : tip_at(q0);
  const Vec3d end_mm = tip_at(q1);
  if (stateless) last_feed_tip_ = FeedTip{q1, end_mm};
  return tip_path_length_mm([&](double t) { return tip_at(nonlinear::lerp(q0, q1, t)); }, start_mm, end_mm);
}

}  // namespace ncpost::detail
