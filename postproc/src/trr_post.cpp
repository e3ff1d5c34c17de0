// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/trr_post.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ncpost/kinematics/trr_xy_inverse.hpp"
#include "ncpost/machines/input_error.hpp"
#include "record_blocks.hpp"

namespace ncpost::trr {
namespace {

Vec3d slerp(const Vec3d& a, const Vec3d& b, double t) {
  const double angle = std::atan2(a.cross(b).norm(), a.dot(b));
  if (angle < 1e-12) return ((1.0 - t) * a + t * b).normalized();
  return (std::sin((1.0 - t) * angle) / std::sin(angle) * a + std::sin(t * angle) / std::sin(angle) * b).normalized();
}

struct Solved {
  ClPoint cl;
  Command command;  ///< rounded as the control reads it
};

class Poster {
 public:
  Poster(const std::string& input, const Kinematics& k, NcWriter& writer, const PostOptions& o,
         const std::function<void(const PostedBlock&)>& on_block)
      : input_(input), k_(k), writer_(writer), o_(o), on_block_(on_block), split_(k, o.workpiece_origin_mm),
        check_(k, o.workpiece_origin_mm) {}

  PostSummary run(cl::Reader& reader) {
    writer_.begin_program(o_.program_name, o_.header_comments);
    while (auto record = reader.next()) {
      std::visit([this](const auto& r) { on(r); }, *record);
      for (auto& n : reader.take_notices()) summary_.notices.push_back(std::move(n));
    }
    writer_.end_program();
    summary_.blocks_out = writer_.blocks_written();
    return summary_;
  }

 private:
  void on(const cl::Motion& m) {
    ++summary_.motions_in;
    const bool rapid = m.rapid || m.from;
    if (pending_circle_ && have_position_) {
      const cl::Circle c = *pending_circle_;
      pending_circle_.reset();
      arc_to(c, m, rapid);
      return;
    }
    pending_circle_.reset();
    if (m.rotary_rad) notice(m.where, "programmed rotary angles have no meaning on the TRR-XY machine: ignored");
    move_to(m.point, m.where.line, rapid);
  }
  void on(const cl::Feed& f) {
    if (auto n = records_.feed(f)) notice(f.where, *n);
  }
  void on(const cl::Spindle& s) { records_.spindle(s); }
  void on(const cl::Coolant& c) { records_.coolant(c); }
  /// The dialect's tool call (the TRR-XY head carries the tool length in its kinematics).
  void on(const cl::ToolChange& t) {
    std::vector<std::string> blocks;
    for (const auto& b : writer_.dialect().tool_call) blocks.push_back(with_tool(b, t.number));
    writer_.tool_change(blocks);
  }
  void on(const cl::Circle& c) { pending_circle_ = c; }
  // Cycles and cutter compensation are not written on the TRR-XY machine: posting the hole
  // positions as plain points, or the path without its offset, would cut a wrong part.
  void on(const cl::Cycle& c) {
    if (c.kind != cl::Cycle::Kind::off)
      throw InputError({input_, c.where.line, c.where.column},
                       "drilling cycles are not posted on the TRR-XY machine (its holes would be plain points, never "
                       "drilled): post the operation as explicit moves",
                       "CYCLE/" + c.text);
  }
  void on(const cl::CutterComp& c) {
    if (c.side != cl::CutterComp::Side::off)
      throw InputError({input_, c.where.line, c.where.column},
                       "cutter radius compensation is not posted on the TRR-XY machine: post the tool centre path "
                       "without CUTCOM",
                       "CUTCOM/" + c.text);
  }
  void on(const cl::Comment& c) { records_.comment(c); }
  void on(const cl::Unsupported& u) { records_.unsupported(u); }
  void on(const cl::End&) {}

  void notice(cl::Location where, const std::string& what) {
    summary_.notices.push_back(fmt::format("{}:{}: {}", input_, where.line, what));
  }

  Solved solve(const ClPoint& cl, int line) {
    const InverseOutcome ik = inverse(k_, cl, o_.workpiece_origin_mm);
    if (!ik.ok())
      throw Infeasible(fmt::format("{}:{}: {} (tip {:.4f}, {:.4f}, {:.4f} mm, axis {:.6f}, {:.6f}, {:.6f}){}", input_, line,
                                   ik.failure, cl.tip_mm.x(), cl.tip_mm.y(), cl.tip_mm.z(), cl.axis.x(), cl.axis.y(),
                                   cl.axis.z(),
                                   o_.workpiece_origin_mm.isZero()
                                       ? "; the workpiece origin is at the TCP's home: set --workpiece-origin below it"
                                       : ""));
    Solved s{cl, *ik.command};
    auto w = s.command.words();
    for (int i = 0; i < 5; ++i) w[i] = writer_.rounded(i, w[i]);
    s.command = Command::from_words(w);
    return s;
  }

  void move_to(const ClPoint& cl_in, int line, bool rapid) {
    ClPoint cl = cl_in;
    cl.axis.normalize();
    const Solved next = solve(cl, line);
    if (!rapid && !records_.feed_given() && !default_feed_noticed_) {
      notice({line, 0}, fmt::format("motion before any FEDRAT: feed {} mm/min", o_.default_feed_mm_min));
      default_feed_noticed_ = true;
    }
    if (have_position_ && o_.tolerance_mm) split(previous_, next, line, rapid, 0);
    else emit(next, line, rapid);
    previous_ = next;
    have_position_ = true;
  }

  /// Emits `to`, after splitting (from, to) while its error is over the tolerance. The nonlinear
  /// error of a short block grows with the square of its length, so a block with error e is first
  /// cut into ceil(sqrt(e / target)) equal CL pieces; each piece is checked again (and cut again
  /// if needed).
  void split(const Solved& from, const Solved& to, int line, bool rapid, int depth) {
    const Block b{from.cl, to.cl, from.command, to.command};
    const BlockError e = split_.evaluate(b);
    const double target = o_.split_fraction * *o_.tolerance_mm;
    if (e.max_mm > target && depth < o_.max_split_depth) {
      const int pieces = std::clamp(static_cast<int>(std::ceil(std::sqrt(e.max_mm / target))), 2, 64);
      Solved start = from;
      for (int i = 1; i <= pieces; ++i) {
        if (i == pieces) {
          split(start, to, line, rapid, depth + 1);
          break;
        }
        const double t = static_cast<double>(i) / pieces;
        ClPoint p;
        p.tip_mm = (1.0 - t) * from.cl.tip_mm + t * to.cl.tip_mm;
        p.axis = slerp(from.cl.axis, to.cl.axis, t);
        const Solved mid = solve(p, line);
        ++summary_.blocks_inserted;
        split(start, mid, line, rapid, depth + 1);
        start = mid;
      }
      return;
    }
    summary_.max_block_error_mm = std::max(summary_.max_block_error_mm, e.max_mm);
    emit(to, line, rapid);
  }

  void emit(const Solved& to, int line, bool rapid) {
    NcMotion m;
    m.rapid = rapid;
    const auto w = to.command.words();
    for (int i = 0; i < 5; ++i) m.values[static_cast<std::size_t>(i)] = w[i];
    m.feed = records_.feed_mm_min(o_.default_feed_mm_min);
    const bool had = have_emitted_;
    if (!writer_.motion(m)) return;
    if (had) {
      const PostedBlock pb{line, rapid, Block{last_.cl, to.cl, last_.command, to.command}};
      if (o_.verify) verify(pb);
      if (on_block_) on_block_(pb);
    }
    last_ = to;
    have_emitted_ = true;
  }

  void verify(const PostedBlock& pb) {
    const BlockError e = check_.evaluate(pb.block);
    VerifyReport& v = summary_.verify;
    ++v.blocks;
    if (e.max_mm > v.max_contour_mm) {
      v.max_contour_mm = e.max_mm;
      v.worst_line = pb.line;
    }
    v.max_orientation_rad = std::max(v.max_orientation_rad, e.orientation_rad);
    std::string why;
    const auto end = check_.at(pb.block, 1.0, &why);
    if (!end) throw Infeasible(fmt::format("{}:{}: verify: {}", input_, pb.line, why));
    v.max_endpoint_mm = std::max(v.max_endpoint_mm, (end->tip_mm - pb.block.to_cl.tip_mm).norm());
  }

  /// CIRCLE + GOTO: points on the arc (counter-clockwise about the circle's axis, APT) within
  /// the chord tolerance; the tool axis is interpolated on the great circle.
  void arc_to(const cl::Circle& c, const cl::Motion& end, bool rapid) {
    const Vec3d n = c.axis.normalized();
    const Vec3d a = previous_.cl.tip_mm - c.center_mm, b = end.point.tip_mm - c.center_mm;
    const Vec3d ap = a - a.dot(n) * n, bp = b - b.dot(n) * n;
    double sweep = std::atan2(ap.cross(bp).dot(n), ap.dot(bp));
    if (sweep <= 1e-12) sweep += 2.0 * kPi;
    const double r = std::max(c.radius_mm, 1e-9);
    const double step = 2.0 * std::acos(std::max(-1.0, 1.0 - o_.arc_tolerance_mm / r));
    const int pieces = std::max(1, static_cast<int>(std::ceil(sweep / step)));
    const ClPoint start = previous_.cl;
    for (int i = 1; i <= pieces; ++i) {
      const double t = static_cast<double>(i) / pieces;
      ClPoint p;
      if (i == pieces) {
        p = end.point;
      } else {
        const Vec3d radial = rotation_about<double>(n, t * sweep) * ap;
        const double height = (1.0 - t) * a.dot(n) + t * b.dot(n);
        p.tip_mm = c.center_mm + radial + height * n;
        p.axis = slerp(start.axis.normalized(), end.point.axis.normalized(), t);
      }
      move_to(p, end.where.line, rapid);
    }
  }

  const std::string& input_;
  const Kinematics& k_;
  NcWriter& writer_;
  const PostOptions& o_;
  const std::function<void(const PostedBlock&)>& on_block_;
  BlockEvaluator split_, check_;
  PostSummary summary_;
  Solved previous_{}, last_{};
  bool have_position_ = false, have_emitted_ = false;
  detail::RecordBlocks records_{writer_};
  bool default_feed_noticed_ = false;
  std::optional<cl::Circle> pending_circle_;
};

}  // namespace

PostSummary post_program(cl::Reader& reader, const std::string& input_name, const Kinematics& k, NcWriter& writer,
                         const PostOptions& options, const std::function<void(const PostedBlock&)>& on_block) {
  Poster p(input_name, k, writer, options, on_block);
  return p.run(reader);
}

}  // namespace ncpost::trr
