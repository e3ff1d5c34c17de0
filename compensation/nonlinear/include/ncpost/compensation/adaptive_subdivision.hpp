// SPDX-License-Identifier: Apache-2.0
#pragma once
// Adaptive block insertion to a tolerance (`ncpost post --tolerance MM`, the default
// `--nonlinear adaptive`): an input block whose exact nonlinear error (nonlinear_error.hpp)
// exceeds the tolerance is cut into output blocks whose end points are CL points on the straight
// CL segment (tip linear, tool axis on the great circle: `cl_at`), each solved exactly by the
// caller's solver (nominal IK, or the IK of the actual machine under a model), with continuity from
// the previous node. Every output block is re-executed and measured, so the result is verified.
//
// The error model's own bow (`model_bow_mm`, on the machine of a model whose errors vary along
// the axes: component error functions, tables, reversal): the actual minus the nominal executed
// tip, d(t), is what compensating the block's end points corrects exactly at the ends only;
// inside the block it leaves d(t) away from the chord of d(0), d(1). Across the CL segment
// (along it the tip is only early or late) that is sampled at t = k/8 and bounded by its own
// bound, tighter than the tolerance: a long move of a three-axis machine has no other bow, and
// the straightness and angular errors of its axes bend it by µm over a few hundred mm. A piece
// passes when both its error and its model bow are within their bounds; `need` below is the
// larger ratio of the two.
//
// Number and placement of the nodes (the bow of a block falls about as 1/n² with n pieces):
//   1. n = ceil(sqrt(need)) pieces of equal parameter (need = E / tolerance without a model bow);
//   2. if some piece fails, its measured needs give the local density; n' =
//      ceil(Σ sqrt(need_k)) pieces placed at equal increments of the cumulative
//      Σ sqrt(need_k) (equidistribution), tried once;
//   3. pieces that still fail are cut again the same way (recursively, `max_depth`).
// Cost: blocks whose cheap upper bound (nonlinear_bound.hpp) is within `screen_fraction` of the
// tolerance are emitted as they are without the exact maximisation (`SplitBlock::screened`); a
// block whose mid-point deviation alone exceeds `estimate_factor` × tolerance takes n from that
// (never larger) estimate instead of the exact error; output pieces whose bound is within
// `piece_screen_fraction` of the tolerance are accepted on the bound. Every accepted piece is
// therefore within the tolerance by the exact error or by the upper bound.
// Axis limits and rotary continuity: the solver applies the limits and the choice of solution.
// Near the singular cone the block's end points can sit on different branches (e.g. A +2° → −2° with
// C nearly still, while the exact path along the CL segment needs C to swing ~180°): no continuous
// exact subdivision exists. This is detected up front (the exact solution at t = ¼, ½, ¾ more than
// `branch_deviation_rad` from the linear interpolation of the block's rotary angles); such a block,
// and any single node without an admissible continuous solution, keeps the rotary angles of the
// interpolation q0 + t·(q1 − q0) and only the linear axes put the tool tip on the CL point (exact in
// position; the orientation is the block's own: counted in `rotary_kept_nodes`). No flip is ever
// emitted inside a block; linear axes out of their limits make the block fail with a message.
// Units: mm, rad; CL in W; t is the parameter of the input block.
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <optional>
#include <vector>

#include "ncpost/compensation/nonlinear_bound.hpp"
#include "ncpost/compensation/nonlinear_split.hpp"
#include "ncpost/kinematics/inverse.hpp"

namespace ncpost::nonlinear {

struct AdaptiveOptions {
  double tolerance_mm = 0.005;
  int max_depth = 8;
  int max_blocks = 4096;               ///< output blocks per input block
  double max_rotary_step_rad = 0.5;    ///< node-to-node jump beyond the block's own rotary travel
  double branch_deviation_rad = 0.5;   ///< exact IK this far from the interpolation: keep rotaries
  double screen_fraction = 0.5;        ///< skip the exact error when the bound is within this share
                                       ///< of the tolerance (0: always exact)
  double piece_screen_fraction = 0.9;  ///< the same for output pieces (0: always exact)
  double estimate_factor = 2.0;        ///< mid-point deviation above this × tolerance: no exact input
                                       ///< error (0: always exact); `input_error_mm` is then that estimate
  double model_bow_mm = 0.0;           ///< bound on the error model's own bow across the segment (mm;
                                       ///< 0: none, only the tolerance; rigid chains have none)
  NonlinearErrorOptions error = fast_error_options();
  bool valid() const {
    return tolerance_mm > 0 && max_depth >= 0 && max_blocks >= 1 && screen_fraction >= 0 && screen_fraction <= 1 &&
           piece_screen_fraction >= 0 && piece_screen_fraction <= 1 && estimate_factor >= 0 && model_bow_mm >= 0 &&
           error.valid();
  }
};

/// The nominal solver: closed-form IK of the nominal machine with the post's solution choice.
struct NominalSolver {
  const Machine& machine;
  Setup setup;
  IkPolicy policy{};
  IkOutcome operator()(const ClPoint& cl, const AxisPosition& previous) const {
    return solve(machine, cl, setup, previous, policy);
  }
};

/// The error model's own bow of a block: the largest distance, across the CL segment, of the
/// actual minus the nominal executed tip from the chord of its values at the block's ends, at
/// t = k/8 (mm, W).
template <class Errors>
double model_bow_mm(const Machine& machine, const Setup& setup, const ClBlock& block, const Errors& errors) {
  const ExecutedBlock<Errors> actual(machine, setup, block, errors);
  const ExecutedBlock<NominalErrors> nominal(machine, setup, block);
  auto d = [&](double t) {
    const AxisPosition q = lerp(block.from, block.to, t);
    return Vec3d(actual.pose_at(q).tip_mm - nominal.pose_at(q).tip_mm);
  };
  const Vec3d d0 = d(0.0), d1 = d(1.0);
  const Vec3d along = block.end.tip_mm - block.start.tip_mm;
  const Vec3d u = along.norm() > 0.0 ? Vec3d(along.normalized()) : Vec3d::Zero();
  double bow = 0.0;
  for (int k = 1; k < 8; ++k) {
    const double t = k / 8.0;
    const Vec3d off = d(t) - ((1.0 - t) * d0 + t * d1);
    bow = std::max(bow, (off - off.dot(u) * u).norm());
  }
  return bow;
}

namespace detail {

template <class Errors, class Solver>
class Subdivider {
 public:
  Subdivider(const Machine& m, const Setup& s, const ClBlock& b, const Errors& e, Solver& solver,
             const AdaptiveOptions& o)
      : machine_(m), setup_(s), block_(b), errors_(e), solver_(solver), options_(o) {
    const double travel = max_abs_step(b.to.rotary_rad, b.from.rotary_rad);
    max_step_ = travel + o.max_rotary_step_rad;
    bow_bounded_ = o.model_bow_mm > 0.0 && !rigid_chain(e);
  }

  SplitBlock run() {
    SplitBlock out;
    if (options_.screen_fraction > 0) {
      const NonlinearBound bound =
          nonlinear_bound(ExecutedBlock<Errors>(machine_, setup_, block_, errors_), machine_, setup_);
      if (bound.error_mm <= options_.screen_fraction * options_.tolerance_mm &&
          bow_within(bound.error_mm, block_.start, block_.from, block_.end, block_.to) <= options_.model_bow_mm) {
        out.nodes.push_back({1.0, block_.end, block_.to});
        out.input_error_mm = out.max_error_mm = bound.error_mm;
        out.max_orientation_rad = bound.orientation_rad;
        out.screened = true;
        return out;
      }
    }
    NonlinearError e;
    if (options_.estimate_factor > 0) {
      const Deviation mid = ExecutedBlock<Errors>(machine_, setup_, block_, errors_).at(0.5);
      if (mid.error_mm() > options_.estimate_factor * options_.tolerance_mm) {
        e.max_error_mm = mid.error_mm();
        e.at_t = 0.5;
        e.offset_mm = mid.offset_mm;
      }
    }
    if (e.max_error_mm == 0.0) e = exact_error(block_.start, block_.from, block_.end, block_.to);
    out.input_error_mm = e.max_error_mm;
    Piece whole{0.0,        block_.start, block_.from, 1.0,
                block_.end, block_.to,    e,           bow(block_.start, block_.from, block_.end, block_.to)};
    if (need(whole) > 1.0) keep_rotary_ = !branch_consistent();
    refine(whole, 0, out);
    out.rotary_kept_nodes = rotary_kept_;
    return out;
  }

 private:
  struct Piece {
    double ta;
    ClPoint ca;
    AxisPosition qa;
    double tb;
    ClPoint cb;
    AxisPosition qb;
    NonlinearError error;
    double bow_mm = 0.0;  ///< the model's own bow (0 when not bounded)
  };

  /// The model's own bow of a piece when it is bounded, else 0.
  double bow(const ClPoint& ca, const AxisPosition& qa, const ClPoint& cb, const AxisPosition& qb) const {
    return bow_bounded_ ? model_bow_mm(machine_, setup_, ClBlock{ca, cb, qa, qb}, errors_) : 0.0;
  }

  /// The same, given the piece's upper bound (nonlinear_bound.hpp; it covers the chord deviation
  /// of the actual executed tip, hence the model's bow): that bound when it is already within the
  /// model bow's bound (the sampling is skipped: dense paths), else the sampled bow.
  double bow_within(double bound_mm, const ClPoint& ca, const AxisPosition& qa, const ClPoint& cb,
                    const AxisPosition& qb) const {
    if (!bow_bounded_) return 0.0;
    return bound_mm <= options_.model_bow_mm ? bound_mm : bow(ca, qa, cb, qb);
  }

  /// How far a piece is beyond its bounds: the larger of error / tolerance and bow / model bound
  /// (<= 1: within both).
  double need(const Piece& p) const {
    const double n = p.error.max_error_mm / options_.tolerance_mm;
    return bow_bounded_ ? std::max(n, p.bow_mm / options_.model_bow_mm) : n;
  }

  NonlinearError exact_error(const ClPoint& ca, const AxisPosition& qa, const ClPoint& cb,
                             const AxisPosition& qb) const {
    return nonlinear_error(machine_, setup_, ClBlock{ca, cb, qa, qb}, errors_, options_.error);
  }

  /// The piece: its error is its upper bound when that is within `piece_screen_fraction` of the
  /// tolerance, else the exact error; its model bow as `bow_within`.
  Piece piece(double ta, const ClPoint& ca, const AxisPosition& qa, double tb, const ClPoint& cb,
              const AxisPosition& qb) const {
    Piece p{ta, ca, qa, tb, cb, qb, {}, 0.0};
    double bound_mm = std::numeric_limits<double>::infinity();
    if (options_.piece_screen_fraction > 0) {
      const ClBlock block{ca, cb, qa, qb};
      const NonlinearBound bound =
          nonlinear_bound(ExecutedBlock<Errors>(machine_, setup_, block, errors_), machine_, setup_);
      bound_mm = bound.error_mm;
      if (bound.error_mm <= options_.piece_screen_fraction * options_.tolerance_mm) {
        p.error.max_error_mm = bound.error_mm;
        p.error.max_orientation_rad = bound.orientation_rad;
      }
    }
    if (!(bound_mm <= options_.piece_screen_fraction * options_.tolerance_mm)) p.error = exact_error(ca, qa, cb, qb);
    p.bow_mm = bow_within(bound_mm, ca, qa, cb, qb);
    return p;
  }

  void emit(const Piece& p, SplitBlock& out) const {
    out.nodes.push_back({p.tb, p.cb, p.qb});
    out.max_error_mm = std::max(out.max_error_mm, p.error.max_error_mm);
    out.max_orientation_rad = std::max(out.max_orientation_rad, p.error.max_orientation_rad);
  }

  /// Cuts `p` at the parameters `cuts` (strictly inside (p.ta, p.tb), ascending); nullopt with
  /// `failure` set when a node cannot be solved or jumps.
  std::optional<std::vector<Piece>> cut(const Piece& p, const std::vector<double>& cuts, std::string& failure) {
    std::vector<Piece> pieces;
    double ta = p.ta;
    ClPoint ca = p.ca;
    AxisPosition qa = p.qa;
    for (std::size_t k = 0; k <= cuts.size(); ++k) {
      double tb = p.tb;
      ClPoint cb = p.cb;
      AxisPosition qb = p.qb;
      if (k < cuts.size()) {
        tb = cuts[k];
        cb = cl_at(block_.start, block_.end, tb);
        // the solution nearest the block's own interpolation of its end points (their branch and
        // turn: a node nearest qa alone may take another turn of a continuous axis than the end,
        // and the last piece would swing a whole turn), within max_step_ of qa
        const IkOutcome o = keep_rotary_ ? IkOutcome{} : solver_(cb, lerp(block_.from, block_.to, tb));
        if (o.ok() && max_abs_step(o.position->rotary_rad, qa.rotary_rad) <= max_step_) {
          qb = *o.position;
        } else {
          auto kept = rotary_kept_node(tb, cb, failure);
          if (!kept) return std::nullopt;
          qb = *kept;
        }
      }
      pieces.push_back(piece(ta, ca, qa, tb, cb, qb));
      ta = tb;
      ca = cb;
      qa = qb;
    }
    return pieces;
  }

  /// False when the exact solutions inside the block leave the interpolation of its end points
  /// (end points on different branches, near the singular cone).
  bool branch_consistent() const {
    const double limit =
        std::max(options_.branch_deviation_rad, max_abs_step(block_.to.rotary_rad, block_.from.rotary_rad));
    for (double t : {0.25, 0.5, 0.75}) {
      const AxisPosition hint = lerp(block_.from, block_.to, t);
      const IkOutcome o = solver_(cl_at(block_.start, block_.end, t), hint);
      if (o.ok() && max_abs_step(o.position->rotary_rad, hint.rotary_rad) > limit) return false;
    }
    return true;
  }

  /// The node at tb with the block's interpolated rotary angles and the tip on cb.
  std::optional<AxisPosition> rotary_kept_node(double tb, const ClPoint& cb, std::string& failure) {
    const ExecutedBlock<Errors> executed(machine_, setup_, block_, errors_);
    const AxisPosition q = shift_linear_axes(executed, lerp(block_.from, block_.to, tb), cb.tip_mm);
    for (int i = 0; i < 3; ++i) {
      const Axis& axis = machine_.axes[static_cast<std::size_t>(i)];
      if (axis.limits && !axis.limits->contains(q.linear_mm[i], 1e-6)) {
        failure = fmt::format("an inserted point at t = {:.4f} needs axis {} = {:.3f} mm, out of its limits", tb,
                              axis.letter, q.linear_mm[i]);
        return std::nullopt;
      }
    }
    ++rotary_kept_;
    return q;
  }

  int failures(const std::vector<Piece>& pieces) const {
    return static_cast<int>(std::count_if(pieces.begin(), pieces.end(), [&](const Piece& q) { return need(q) > 1.0; }));
  }

  void refine(const Piece& p, int depth, SplitBlock& out) {
    const double tol = options_.tolerance_mm;
    if (!out.ok()) return;
    if (need(p) <= 1.0) return emit(p, out);
    if (depth > options_.max_depth || out.output_blocks() >= options_.max_blocks) {
      if (p.error.max_error_mm > tol)
        out.failure =
            fmt::format("tolerance {} mm not reached after {} levels of subdivision (error {:.4g} mm at t = {:.4f})",
                        tol, depth, p.error.max_error_mm, p.ta + p.error.at_t * (p.tb - p.ta));
      else
        out.failure = fmt::format(
            "the error model's own bow {:.4g} mm (bound {} mm) not reached after {} levels of "
            "subdivision (t = {:.4f} to {:.4f})",
            p.bow_mm, options_.model_bow_mm, depth, p.ta, p.tb);
      return;
    }
    // 1. equal parameter
    const int n = std::max(2, static_cast<int>(std::ceil(std::sqrt(need(p)))));
    std::vector<double> cuts;
    for (int k = 1; k < n; ++k) cuts.push_back(p.ta + (p.tb - p.ta) * k / n);
    auto pieces = cut(p, cuts, out.failure);
    if (!pieces) return;
    // 2. equidistribution from the measured errors of the pieces
    if (failures(*pieces) > 0) {
      std::vector<double> density;
      double total = 0;
      for (const Piece& q : *pieces) {
        density.push_back(std::sqrt(need(q)));
        total += density.back();
      }
      const int n2 = std::max(n, static_cast<int>(std::ceil(total)));
      if (n2 < n + failures(*pieces)) {  // only when it can beat cutting the failed pieces
        std::vector<double> cuts2;
        double acc = 0;
        std::size_t k = 0;
        for (int j = 1; j < n2; ++j) {
          const double target = total * j / n2;
          while (k + 1 < density.size() && acc + density[k] < target) acc += density[k++];
          const double frac = density[k] > 0 ? std::clamp((target - acc) / density[k], 0.0, 1.0) : 0.5;
          cuts2.push_back((*pieces)[k].ta + frac * ((*pieces)[k].tb - (*pieces)[k].ta));
        }
        std::string failure2;
        auto pieces2 = cut(p, cuts2, failure2);
        if (pieces2 && n2 + failures(*pieces2) < n + failures(*pieces)) pieces = std::move(pieces2);
      }
    }
    // 3. recurse on what still fails
    for (const Piece& q : *pieces) refine(q, depth + 1, out);
  }

  const Machine& machine_;
  const Setup& setup_;
  const ClBlock& block_;
  const Errors& errors_;
  Solver& solver_;
  const AdaptiveOptions& options_;
  double max_step_ = 0.0;
  int rotary_kept_ = 0;  ///< nodes placed by rotary_kept_node (counted as the block is cut)
  bool keep_rotary_ = false;
  bool bow_bounded_ = false;
};

}  // namespace detail

/// Subdivides `block` until every output block's exact nonlinear error, on the machine of `errors`,
/// is within `options.tolerance_mm`. `solver(cl, previous)` returns an `IkOutcome` for a CL point
/// (W) given the previous axis position. The block's end keeps its axis position `block.to`.
template <class Errors, class Solver>
SplitBlock subdivide_adaptive(const Machine& machine, const Setup& setup, const ClBlock& block, const Errors& errors,
                              Solver&& solver, const AdaptiveOptions& options = {}) {
  detail::Subdivider<Errors, std::remove_reference_t<Solver>> s(machine, setup, block, errors, solver, options);
  return s.run();
}

/// Nominal machine, nominal IK.
inline SplitBlock subdivide_adaptive(const Machine& machine, const Setup& setup, const ClBlock& block,
                                     const AdaptiveOptions& options = {}) {
  NominalSolver solver{machine, setup};
  return subdivide_adaptive(machine, setup, block, NominalErrors{}, solver, options);
}

}  // namespace ncpost::nonlinear
