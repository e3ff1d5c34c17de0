// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/trr_subdivider.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "ncpost/compensation/trr_block_error.hpp"
#include "ncpost/machines/input_error.hpp"

namespace ncpost {
namespace {

Vec3d slerp(const Vec3d& a, const Vec3d& b, double t) {
  const double angle = std::atan2(a.cross(b).norm(), a.dot(b));
  if (angle < 1e-12) return ((1.0 - t) * a + t * b).normalized();
  return (std::sin((1.0 - t) * angle) / std::sin(angle) * a + std::sin(t * angle) / std::sin(angle) * b).normalized();
}

/// The value the control reads for word `slot` (NcWriter::rounded: slots 0-2 with the linear
/// decimals, the others with the angle decimals).
double rounded(const Dialect& d, int slot, double v) {
  const int decimals = slot < 3 ? d.linear_decimals : d.angle_decimals;
  const double scale = std::pow(10.0, decimals);
  const double r = std::round(v * scale) / scale;
  return r == 0.0 ? 0.0 : r;
}

/// More blocks than this for one CL move: the tolerance is finer than the machine's words can
/// follow (a tolerance of nanometres split the move 2^24 times); refused instead (exit 3).
constexpr std::size_t kMaxBlocksPerMove = 4096;

class Cutter {
 public:
  Cutter(const TrrSolver& solver, const Dialect& dialect, const TrrSubdivision& o)
      : solver_(solver), dialect_(dialect), o_(o), evaluator_(solver.commanded(), solver.workpiece_origin_mm()) {}

  std::vector<SolvedPoint> cut(const SolvedPoint& from, const SolvedPoint& to) {
    std::vector<SolvedPoint> out;
    split(from, to, 0, out);
    return out;
  }

 private:
  trr::Command executed(const AxisPosition& q) const {
    AxisPosition r;
    for (int i = 0; i < 5; ++i) r[i] = rounded(dialect_, i, q[i]);
    return trr_command(r);
  }

  void split(const SolvedPoint& from, const SolvedPoint& to, int depth, std::vector<SolvedPoint>& out) {
    const trr::Block b{from.cl, to.cl, executed(from.q), executed(to.q)};
    trr::BlockError e;
    try {
      e = evaluator_.evaluate(b, work_);
    } catch (const std::runtime_error& ex) {
      throw Infeasible(ex.what());
    }
    const double target = o_.split_fraction * o_.tolerance_mm;
    if (!(e.max_mm > target) || (depth >= o_.max_depth && !(e.max_mm > o_.tolerance_mm))) {
      out.push_back(to);
      return;
    }
    if (depth >= o_.max_depth || out.size() >= kMaxBlocksPerMove)
      throw Infeasible(fmt::format(
          "the move cannot be cut within the tolerance {:g} mm: after {} levels of subdivision ({} blocks so far) a "
          "block still errs by {:.3g} mm (the words' resolution limits what the machine can follow): raise --tolerance",
          o_.tolerance_mm, depth, out.size(), e.max_mm));
    const int pieces = std::clamp(static_cast<int>(std::ceil(std::sqrt(e.max_mm / target))), 2, 64);
    SolvedPoint start = from;
    for (int i = 1; i < pieces; ++i) {
      const double t = static_cast<double>(i) / pieces;
      ClPoint p;
      p.tip_mm = (1.0 - t) * from.cl.tip_mm + t * to.cl.tip_mm;
      p.axis = slerp(from.cl.axis, to.cl.axis, t);
      const IkOutcome ik = solver_.inverse(p);
      if (!ik.ok()) throw Infeasible(fmt::format("a point inserted for the tolerance is out of reach: {}", ik.failure.message));
      const SolvedPoint mid{p, *ik.position};
      split(start, mid, depth + 1, out);
      start = mid;
    }
    split(start, to, depth + 1, out);
  }

  const TrrSolver& solver_;
  const Dialect& dialect_;
  TrrSubdivision o_;
  const trr::BlockEvaluator evaluator_;
  trr::EvaluatorWork work_;  ///< the post thread's forward solves (the cutter runs on it alone)
};

}  // namespace

PostOptions trr_post_options() {
  PostOptions o;
  o.native_arcs = false;
  o.native_cycles = false;
  o.order_rapids = false;
  o.subdivide_rapids = true;
  o.tool_length_on_change = false;
  return o;
}

Subdivider make_trr_subdivider(const TrrSolver& solver, const Dialect& dialect, const TrrSubdivision& options) {
  auto cutter = std::make_shared<Cutter>(solver, dialect, options);
  return [cutter](const SolvedPoint& from, const SolvedPoint& to) { return cutter->cut(from, to); };
}

}  // namespace ncpost
