// SPDX-License-Identifier: Apache-2.0
#pragma once
// The paper's harmonic compensation (seed 001, Zhang, Wang, Tang 2023, eq. 4: P = E − L(t)),
// realised as NC blocks (`ncpost post --nonlinear harmonic`).
//
// The paper shifts the *interpolated* points of a block by the modelled error. A post cannot
// change how the control interpolates, so ncpost inserts those shifted points as block ends:
//   - the block is cut into n output blocks at t_k = k/n (parameter of the input block, linear in
//     axis space), n = ceil(sqrt(Emax / tolerance)) (the bow of an output block falls as 1/n²);
//   - at each t_k the rotary axes keep their linearly interpolated angles (as the control would
//     have them; the orientation error is not compensated, as in the paper) and the linear axes are
//     moved so that the executed tool tip moves by −L(t_k) = −Emax·sin(πt_k)·n (W): the point the
//     control would have executed, E(t_k), becomes E(t_k) − L(t_k), on the CL segment as far as
//     the model is right;
//   - Emax and n come from the model fit (harmonic_model.hpp), by default at the midpoint of the
//     block (one forward evaluation, no inverse kinematics per inserted point).
// What is left: the model error |e(t_k) − L(t_k)| at the nodes (0.096 mm of 1.72 mm on the seed
// 001 segment: the true bow is parabolic, not a sine) plus the small bow of each output block.
// `verify_split` measures it; the adaptive method (adaptive_subdivision.hpp) meets a tolerance.
// Units: mm, rad; CL in W.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <fmt/format.h>

#include "ncpost/compensation/harmonic_model.hpp"
#include "ncpost/compensation/nonlinear_bound.hpp"
#include "ncpost/compensation/nonlinear_split.hpp"

namespace ncpost::nonlinear {

struct HarmonicOptions {
  double tolerance_mm = 0.005;  ///< blocks whose model Emax is within it are left alone
  HarmonicFit fit = HarmonicFit::midpoint;
  int fixed_blocks = 0;                                ///< > 0: this many output blocks per compensated block instead
  int max_blocks = 256;                                ///< per input block
  NonlinearErrorOptions error = fast_error_options();  ///< for the peak fit and the verification
  bool verify = true;                                  ///< re-execute the output blocks and set the verified errors
  double screen_fraction = 0.5;  ///< leave a block alone when its bound is within this share of the tolerance
  bool valid() const { return tolerance_mm > 0 && fixed_blocks >= 0 && max_blocks >= 1 && error.valid(); }
};

/// Output blocks for a block whose model amplitude is `amplitude_mm`: ceil(sqrt(Emax / tolerance))
/// (the bow of an output block falls as 1/n²), or `fixed_blocks`; 1 to `max_blocks`.
inline int harmonic_block_count(double amplitude_mm, const HarmonicOptions& options) {
  int n = options.fixed_blocks;
  if (n == 0 && amplitude_mm > options.tolerance_mm)
    n = static_cast<int>(std::ceil(std::sqrt(amplitude_mm / options.tolerance_mm)));
  return std::clamp(n, 1, options.max_blocks);
}

/// The paper's shift (eq. 4) on any machine, serial or parallel: the nodes of `block` cut into `n`
/// output blocks at t_k = k/n, each node the commands that put the executed tool tip at
/// E(t_k) − L(t_k). `executed_at(t)` is the executed tool (`.tip_mm`, `.axis` in W) at fraction t of
/// the block, its commands interpolated linearly as the control does; `shifted(t, executed, tip_W,
/// failure)` the commands near those at t that put the tip at `tip_W` with the tool axis the
/// control has there (`executed.axis`), or nullopt with `failure` set. Each node stands for the
/// point of the CL segment nearest its executed tip. The last node is the block's end.
template <class ExecutedAt, class Shifted>
SplitBlock harmonic_shift(const ClBlock& block, const HarmonicModel& model, int n, ExecutedAt&& executed_at,
                          Shifted&& shifted) {
  SplitBlock out;
  const Vec3d p0 = block.start.tip_mm, d = block.end.tip_mm - block.start.tip_mm;
  for (int k = 1; k < n; ++k) {
    const double t = static_cast<double>(k) / n;
    const auto executed = executed_at(t);
    const Vec3d executed_tip = executed.tip_mm;
    std::optional<AxisPosition> q = shifted(t, executed, Vec3d(executed_tip - model.offset_at(t)), out.failure);
    if (!q) return out;
    BlockNode node;
    node.q = *q;
    // the CL point this node stands for: where the executed point belongs on the segment
    const double s = d.squaredNorm() > 0 ? std::clamp((executed_tip - p0).dot(d) / d.squaredNorm(), 0.0, 1.0) : t;
    node.t = s;
    node.cl.tip_mm = p0 + s * d;
    node.cl.axis = lerp_axis(block.start.axis, block.end.axis, t);
    out.nodes.push_back(node);
  }
  out.nodes.push_back({1.0, block.end, block.to});
  return out;
}

template <class Errors = NominalErrors>
SplitBlock harmonic_compensate(const Machine& machine, const Setup& setup, const ClBlock& block,
                               const Errors& errors = {}, const HarmonicOptions& options = {}) {
  const ExecutedBlock<Errors> executed(machine, setup, block, errors);
  if (options.screen_fraction > 0 && options.fixed_blocks == 0) {
    const NonlinearBound bound = nonlinear_bound(executed, machine, setup);
    if (bound.error_mm <= options.screen_fraction * options.tolerance_mm) {
      SplitBlock out;
      out.nodes.push_back({1.0, block.end, block.to});
      out.input_error_mm = out.max_error_mm = bound.error_mm;
      out.max_orientation_rad = bound.orientation_rad;
      out.screened = true;
      return out;
    }
  }
  const HarmonicModel model = fit_harmonic(executed, options.fit, options.error);
  const int n = harmonic_block_count(model.amplitude_mm, options);
  // the rotary axes keep their interpolated angles; the linear axes carry the shift
  SplitBlock out = harmonic_shift(
      block, model, n, [&](double t) { return executed.pose_at(lerp(block.from, block.to, t)); },
      [&](double t, const auto&, const Vec3d& tip_W, std::string& failure) -> std::optional<AxisPosition> {
        const AxisPosition q = shift_linear_axes(executed, lerp(block.from, block.to, t), tip_W);
        for (int i = 0; i < 3; ++i) {
          const Axis& axis = machine.axes[static_cast<std::size_t>(i)];
          if (axis.limits && !axis.limits->contains(q.linear_mm[i], 1e-6)) {
            failure = fmt::format("harmonic compensation: axis {} out of its limits at t = {:.3f}", axis.letter, t);
            return std::nullopt;
          }
        }
        return q;
      });
  out.input_error_mm = model.amplitude_mm;  // the model's estimate; verify_split measures
  if (!out.ok()) return out;
  if (options.verify) verify_split(machine, setup, block, out, errors, options.error);
  if (n == 1) out.input_error_mm = out.max_error_mm;
  return out;
}

}  // namespace ncpost::nonlinear
