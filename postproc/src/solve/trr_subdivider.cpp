// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/solve/trr_subdivider.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "ncpost/compensation/harmonic_compensation.hpp"
#include "ncpost/compensation/nonlinear_block.hpp"
#include "ncpost/compensation/trr_block_error.hpp"
#include "ncpost/machines/input_error.hpp"

namespace ncpost {
namespace {

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

/// The commands the control reads: each word rounded to the dialect's decimals.
trr::Command executed_command(const Dialect& d, const AxisPosition& q) {
  AxisPosition r;
  for (int i = 0; i < 5; ++i) r[i] = rounded(d, i, q[i]);
  return trr_command(r);
}

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
  trr::Command executed(const AxisPosition& q) const { return executed_command(dialect_, q); }

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
      p.axis = nonlinear::slerp(from.cl.axis, to.cl.axis, t);  // a great circle also between opposite axes
      const IkOutcome ik = solver_.inverse(p);
      if (!ik.ok())
        throw Infeasible(fmt::format("a point inserted for the tolerance is out of reach: {}", ik.failure.message));
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

/// `--nonlinear harmonic`: the paper's shift (harmonic_compensation.hpp, the same nodes as on the
/// serial machines): the block's error at t = ½ is the model's Emax·n; the block is cut into
/// ceil(sqrt(Emax / tolerance)) blocks whose ends are the commands putting the tool tip at
/// E(t_k) − L(t_k) with the tool axis the control has there (TRR-XY inverse kinematics: the
/// sliders and the table both move, where a serial machine moves its linear axes only).
class HarmonicCutter {
 public:
  HarmonicCutter(const TrrSolver& solver, const Dialect& dialect, const TrrSubdivision& o)
      : solver_(solver), dialect_(dialect), evaluator_(solver.commanded(), solver.workpiece_origin_mm()) {
    options_.tolerance_mm = o.tolerance_mm;
  }

  std::vector<SolvedPoint> cut(const SolvedPoint& from, const SolvedPoint& to) {
    const trr::Block b{from.cl, to.cl, executed_command(dialect_, from.q), executed_command(dialect_, to.q)};
    const auto executed_at = [&](double t) {
      std::string why;
      const std::optional<trr::ExecutedPoint> e = evaluator_.at(b, t, work_, &why);
      if (!e) throw Infeasible(why);
      return *e;
    };
    const nonlinear::HarmonicModel model = nonlinear::harmonic_from_offset(executed_at(0.5).offset_mm);
    const int n = nonlinear::harmonic_block_count(model.amplitude_mm, options_);
    if (n == 1) return {to};
    const nonlinear::ClBlock block{from.cl, to.cl, from.q, to.q};
    const nonlinear::SplitBlock split = nonlinear::harmonic_shift(
        block, model, n, executed_at,
        [&](double t, const trr::ExecutedPoint& e, const Vec3d& tip_W,
            std::string& failure) -> std::optional<AxisPosition> {
          ClPoint p;
          p.tip_mm = tip_W;
          p.axis = e.axis;
          const IkOutcome ik = solver_.inverse(p);
          if (ik.ok()) return *ik.position;
          failure = fmt::format("a point shifted by the harmonic model is out of reach: {}", ik.failure.message);
          return std::nullopt;
        });
    if (!split.ok()) throw Infeasible(split.failure);
    std::vector<SolvedPoint> out;
    for (const nonlinear::BlockNode& node : split.nodes) out.push_back({node.cl, node.q});
    return out;
  }

 private:
  const TrrSolver& solver_;
  const Dialect& dialect_;
  nonlinear::HarmonicOptions options_;
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

Subdivider make_tolerance_subdivider(const TrrSolver& solver, const nonlinear::CompensationOptions& options,
                                     const Dialect& dialect) {
  return make_trr_subdivider(solver, dialect, TrrSubdivision{options.tolerance_mm, options.method});
}

Subdivider make_trr_subdivider(const TrrSolver& solver, const Dialect& dialect, const TrrSubdivision& options) {
  if (options.method == nonlinear::Method::harmonic) {
    auto cutter = std::make_shared<HarmonicCutter>(solver, dialect, options);
    return [cutter](const SolvedPoint& from, const SolvedPoint& to) { return cutter->cut(from, to); };
  }
  auto cutter = std::make_shared<Cutter>(solver, dialect, options);
  return [cutter](const SolvedPoint& from, const SolvedPoint& to) { return cutter->cut(from, to); };
}

}  // namespace ncpost
