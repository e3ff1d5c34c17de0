// SPDX-License-Identifier: Apache-2.0
// --verify inside the post (poster.hpp): each block as written is read back from the words in force
// before it (read_back.hpp) and executed on the machine; its motion word, feed word, the line of
// rapids into and out of the cut and its contour are checked against the CL data.
#include <fmt/format.h>

#include <cmath>

#include "ncpost/postproc/solve/inverse_time.hpp"
#include "ncpost/postproc/verify/verify_arc.hpp"
#include "post/poster.hpp"

namespace ncpost::detail {

/// The block just written, read back from the words in force before it (`in_force`).
ReadBackBlock Poster::read_written(const WrittenState& in_force, const ClPoint& from, const ClPoint& to, int line) {
  ReadBackBlock b;
  b.from = in_force;
  b.text = writer_.last_line();
  b.program_line = writer_.lines_written();
  b.cl_line = line;
  b.cl_from_mm = from.tip_mm;
  b.cl_to_mm = to.tip_mm;
  read_back_->start_from(in_force);
  try {
    b.to = read_back_->read(b.text);
  } catch (const std::runtime_error& e) {
    add_defect(summary_.verify, b.program_line, line, e.what());
    b.to = writer_.in_force();
  }
  return b;
}

/// The commands (mm, rad) the control reaches at the words `v` (machine axes or a tilted plane).
AxisPosition Poster::commands_of(const PerAxis<double>& v) const {
  if (plane_) return plane_executed(Vec3d(v[0], v[1], v[2]));
  AxisPosition q = words_.home();
  for (int i = 0; i < words_.count; ++i) {
    const auto u = static_cast<std::size_t>(i);
    q[i] = words_.angle[u] ? deg_to_rad(v[u]) : v[u];
  }
  return q;
}

/// The words of `a` and `b` interpolated at t (a word not in force stands at the other's value).
PerAxis<double> Poster::words_at(const WrittenState& a, const WrittenState& b, double t) const {
  PerAxis<double> v{};
  for (int i = 0; i < words_.count; ++i) {
    const auto u = static_cast<std::size_t>(i);
    const double va = a.values[u].value_or(b.values[u].value_or(0.0)), vb = b.values[u].value_or(va);
    v[u] = va + t * (vb - va);
  }
  return v;
}

/// Where the tool is (W) at t of the move from the words `a` to `b` (detail::ExecuteWords).
ToolPoseT<double> Poster::execute_words(const WrittenState& a, const WrittenState& b, double t) const {
  const PerAxis<double> v = words_at(a, b, t);
  ToolPoseT<double> pose = solver_.execute(commands_of(v), data_);
  if (options_.rtcp && !plane_) pose.tip_mm = Vec3d(v[0], v[1], v[2]);  // the control holds the tip on the words
  return pose;
}

/// --verify of the blocks written for one CL motion: their words, feeds and (rapids) their lines.
void Poster::check_written(const SolvedPoint& from, const SolvedPoint& to, int line, bool rapid, const NcMotion& m,
                           const std::optional<ReadBackBlock>& first, const std::optional<ReadBackBlock>& block) {
  for (const auto* b : {&first, &block}) {
    if (!*b) continue;
    const auto kind = (*b)->to.motion;
    if (kind != (rapid ? WrittenState::Motion::rapid : WrittenState::Motion::linear))
      add_defect(summary_.verify, (*b)->program_line, line,
                 fmt::format("'{}' is not written as a {}", (*b)->text, rapid ? "rapid" : "feed move"));
  }
  if (rapid) {
    check_written_rapid(from, to, line, first, block);
    return;
  }
  check_rapid_into_cut(from, line);
  last_rapid_.reset();
  last_was_feed_ = true;
  if (!block) return;
  check_feed_word(*block, from, to, line, m);
  if (options_.rtcp || !have_position_) return;  // under RTCP the control does the kinematics
  const double contour_mm =
      verify_block(solver_, data_, from.cl, commands_of(words_at(block->from, block->to, 0.0)), to.cl,
                   commands_of(words_at(block->from, block->to, 1.0)), line, summary_.verify);
  if (options_.on_verified) options_.on_verified(line, contour_mm);
}

/// A rapid out of the cut leaves along the tool axis line; the rapid is kept (an approach if a
/// feed follows).
void Poster::check_written_rapid(const SolvedPoint& from, const SolvedPoint& to, int line,
                                 const std::optional<ReadBackBlock>& first, const std::optional<ReadBackBlock>& block) {
  const double tol = kRapidLineToleranceMm;
  const std::optional<ReadBackBlock>& leaving = first ? first : block;
  // (rapids cut to the tolerance, subdivide_rapids, follow the CL line within it: not checked here)
  if (last_was_feed_ && leaving && !options_.subdivide_rapids &&
      (to.cl.tip_mm - from.cl.tip_mm).dot(from.cl.axis.normalized()) > tol) {
    const ExecuteWords execute = [this](const WrittenState& a, const WrittenState& b, double t) {
      return execute_words(a, b, t);
    };
    const double off = rapid_off_line_mm(*leaving, true, execute);
    if (off > tol)
      add_defect(summary_.verify, leaving->program_line, line,
                 fmt::format("the rapid out of the cut leaves the tool axis line (and the straight CL rapid) "
                             "by {:.4f} mm: the tool is dragged sideways",
                             off));
  }
  last_rapid_ = block ? block : first;
  last_was_feed_ = false;
}

/// The last rapid, before a feed that starts at `from`, comes in along the tool axis line.
void Poster::check_rapid_into_cut(const SolvedPoint& from, int line) {
  const double tol = kRapidLineToleranceMm;
  if (!last_rapid_ || options_.subdivide_rapids ||
      !((last_rapid_->cl_from_mm - from.cl.tip_mm).dot(from.cl.axis.normalized()) > tol))
    return;
  const ExecuteWords execute = [this](const WrittenState& a, const WrittenState& b, double t) {
    return execute_words(a, b, t);
  };
  const double off = rapid_off_line_mm(*last_rapid_, false, execute);
  if (off > tol)
    add_defect(summary_.verify, last_rapid_->program_line, last_rapid_->cl_line,
               fmt::format("the rapid into the cut of CL line {} leaves the tool axis line (and the straight "
                           "CL rapid) by {:.4f} mm: the tool comes in sideways",
                           line, off));
}

/// The feed word of a written feed block against its rule: per minute the CL feed; inverse time
/// 1 / (executed tip path / CL feed) (inverse_time.hpp) on the words as written.
void Poster::check_feed_word(const ReadBackBlock& b, const SolvedPoint& from, const SolvedPoint& to, int line,
                             const NcMotion& m) {
  const MotionWords& w = writer_.dialect().motion;
  const double feed = records_.feed_mm_min(options_.default_feed_mm_min);
  const bool inverse = m.feed_mode == NcMotion::FeedMode::inverse_time;
  for (int i = 0; i < words_.count; ++i)  // the first motion: it starts where the machine happens to be
    if (inverse && !b.from.values[static_cast<std::size_t>(i)]) return;
  if (b.to.inverse_time != inverse || !b.to.feed) {
    add_defect(summary_.verify, b.program_line, line,
               fmt::format("'{}' runs {}, the block needs {}", b.text,
                           !b.to.feed          ? "with no feed in force"
                           : b.to.inverse_time ? "in inverse time"
                                               : "per minute",
                           inverse ? "inverse time (G93: it turns a rotary axis)" : "a feed per minute"));
    return;
  }
  double expected = feed;
  double allowed = 0.5 * std::pow(10.0, -w.feed_decimals) + 1e-9;
  if (inverse) {
    const bool tip_moves = (to.cl.tip_mm - from.cl.tip_mm).norm() > kStillTipMm;
    const double path_mm = tip_moves ? executed_tip_path_mm(commands_of(words_at(b.from, b.to, 0.0)),
                                                            commands_of(words_at(b.from, b.to, 1.0)))
                                     : 0.0;
    const double deg = words_.rotary_count > 0 ? rad_to_deg(max_abs_step(to.q.rotary_rad, from.q.rotary_rad)) : 0.0;
    const double minutes = inverse_time_minutes(path_mm, tip_moves, deg, feed);
    expected = minutes > 0.0 ? 1.0 / minutes : 99999.0;
    allowed = 0.5 * std::pow(10.0, -w.inverse_time_decimals) + 1e-4 * expected;
  }
  if (std::abs(*b.to.feed - expected) > allowed)
    add_defect(summary_.verify, b.program_line, line,
               fmt::format("the feed word of '{}' is {}; by its rule it is {:.4f} ({})", b.text, *b.to.feed, expected,
                           inverse ? "1 / (tip path / CL feed)" : "the CL feed, mm/min"));
}

/// The words of a written arc block: its direction word and its feed (per minute, the CL feed).
void Poster::check_arc_words(const ReadBackBlock& b, const NcArc& arc) {
  using Motion = WrittenState::Motion;
  const Motion meant = arc.clockwise ? Motion::clockwise : Motion::counter_clockwise;
  if (b.to.motion != meant)
    add_defect(summary_.verify, b.program_line, b.cl_line,
               fmt::format("'{}' turns the arc {}: the CL circle runs {} in the program's plane", b.text,
                           b.to.motion == Motion::clockwise           ? "clockwise"
                           : b.to.motion == Motion::counter_clockwise ? "counter-clockwise"
                                                                      : "not as an arc",
                           arc.clockwise ? "clockwise" : "counter-clockwise"));
  const double allowed = 0.5 * std::pow(10.0, -writer_.dialect().motion.feed_decimals) + 1e-9;
  if (b.to.inverse_time || !b.to.feed || std::abs(*b.to.feed - arc.feed_mm_min) > allowed)
    add_defect(summary_.verify, b.program_line, b.cl_line,
               fmt::format("the feed of '{}' is not the CL feed {:.1f} mm/min per minute", b.text, arc.feed_mm_min));
}

/// `post --verify` of a native arc: the circle the control interpolates from the words as written
/// (the start where the axes stand, the centre offset and the end rounded), executed on the
/// machine, against the CL circle (verify_arc.hpp). Before previous_ and last_executed_ move on.
void Poster::verify_native_arc(const ReadBackBlock& written, const NcArc& arc,
                               const std::optional<PerAxis<double>>& start_words, const Vec3d& normal, double angle,
                               const cl::Circle& c, const cl::Motion& end, const AxisPosition& executed_end) {
  FrameArc run;
  run.start_mm = plane_ && start_words ? Vec3d((*start_words)[0], (*start_words)[1], (*start_words)[2])
                                       : Vec3d(last_executed_.linear_mm);
  // the circle of the words as written: the centre offset and the end read back, and the way
  // round the written G2/G3 gives (the other way round: about -normal, the rest of the turn)
  const PerAxis<double> end_words = words_at(written.from, written.to, 1.0);
  for (int k = 0; k < 3; ++k) {
    run.centre_mm[k] = run.start_mm[k] + written.to.centre_offset_mm[static_cast<std::size_t>(k)];
    run.end_mm[k] = end_words[static_cast<std::size_t>(k)];
  }
  const bool as_meant = (written.to.motion == WrittenState::Motion::clockwise) == arc.clockwise;
  run.normal = as_meant ? normal : Vec3d(-normal);
  run.sweep_rad = as_meant ? angle : 2.0 * kPi - angle;
  const RotaryAngles rotary = last_executed_.rotary_rad;
  const std::function<AxisPosition(const Vec3d&)> commands_at = [&](const Vec3d& x) {
    if (plane_) return plane_executed(x);
    AxisPosition q = executed_end;
    q.linear_mm = x;
    q.rotary_rad = rotary;
    return q;
  };
  const ClArc cl{previous_.cl.tip_mm, c.center_mm, end.point.tip_mm, c.axis.normalized(), previous_.cl.axis, angle};
  const double contour_mm = verify_arc(solver_, data_, run, commands_at, cl, end.where.line, summary_.verify);
  if (options_.on_verified) options_.on_verified(end.where.line, contour_mm);
}

}  // namespace ncpost::detail
