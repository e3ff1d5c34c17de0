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
#include <fmt/format.h>

#include "ncpost/compensation/harmonic_model.hpp"
#include "ncpost/compensation/nonlinear_bound.hpp"
#include "ncpost/compensation/nonlinear_split.hpp"

namespace ncpost::nonlinear {

struct HarmonicOptions {
  double tolerance_mm = 0.005;      ///< blocks whose model Emax is within it are left alone
  HarmonicFit fit = HarmonicFit::midpoint;
  int fixed_blocks = 0;             ///< > 0: this many output blocks per compensated block instead
  int max_blocks = 256;             ///< per input block
  NonlinearErrorOptions error = fast_error_options();      ///< for the peak fit and the verification
  bool verify = true;               ///< re-execute the output blocks and set the verified errors
  double screen_fraction = 0.5;     ///< leave a block alone when its bound is within this share of the tolerance
  bool valid() const { return tolerance_mm > 0 && fixed_blocks >= 0 && max_blocks >= 1 && error.valid(); }
};

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
  SplitBlock out;
  out.input_error_mm = model.amplitude_mm;  // the model's estimate; verify_split measures
  int n = options.fixed_blocks;
  if (n == 0 && model.amplitude_mm > options.tolerance_mm)
    n = static_cast<int>(std::ceil(std::sqrt(model.amplitude_mm / options.tolerance_mm)));
  n = std::clamp(n, 1, options.max_blocks);
  const Vec3d p0 = block.start.tip_mm, d = block.end.tip_mm - block.start.tip_mm;
  for (int k = 1; k < n; ++k) {
    const double t = static_cast<double>(k) / n;
    const AxisPosition interpolated = lerp(block.from, block.to, t);
    const Vec3d executed_tip = executed.pose_at(interpolated).tip_mm;
    BlockNode node;
    node.q = shift_linear_axes(executed, interpolated, executed_tip - model.offset_at(t));
    for (int i = 0; i < 3; ++i) {
      const Axis& axis = machine.axes[static_cast<std::size_t>(i)];
      if (axis.limits && !axis.limits->contains(node.q.linear_mm[i], 1e-6)) {
        out.failure = fmt::format("harmonic compensation: axis {} out of its limits at t = {:.3f}", axis.letter, t);
        return out;
      }
    }
    // the CL point this node stands for: where the executed point belongs on the segment
    const double s = d.squaredNorm() > 0 ? std::clamp((executed_tip - p0).dot(d) / d.squaredNorm(), 0.0, 1.0) : t;
    node.t = s;
    node.cl.tip_mm = p0 + s * d;
    node.cl.axis = lerp_axis(block.start.axis, block.end.axis, t);
    out.nodes.push_back(node);
  }
  out.nodes.push_back({1.0, block.end, block.to});
  if (options.verify) verify_split(machine, setup, block, out, errors, options.error);
  if (n == 1) out.input_error_mm = out.max_error_mm;
  return out;
}

}  // namespace ncpost::nonlinear
