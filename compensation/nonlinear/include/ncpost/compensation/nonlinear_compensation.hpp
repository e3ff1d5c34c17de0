// SPDX-License-Identifier: Apache-2.0
#pragma once
// The entry point of nonlinear-error compensation for the post (`ncpost post --tolerance MM
// [--nonlinear adaptive|harmonic]`): one input block in, the output block end points out.
//
//   adaptive  adaptive_subdivision.hpp: inserted CL points on the straight segment (axis on the
//             great circle) solved exactly by the post's solver; every output block verified
//             within the tolerance (default);
//   harmonic  harmonic_compensation.hpp: the paper's L(t) = Emax·sin(πt) shift of interpolated
//             points (seed 001); fewer computations, but it leaves the model's own error (about 5%
//             of the block's error) and does not bound it by the tolerance.
//
// `errors` is the machine the program is for (NominalErrors, or the model functor of `--model`);
// `solver(cl, previous) -> IkOutcome` its inverse kinematics with the post's solution choice.
// Units: mm, rad; CL in W.
#include <cmath>
#include <optional>
#include <string>

#include "ncpost/compensation/adaptive_subdivision.hpp"
#include "ncpost/compensation/harmonic_compensation.hpp"

namespace ncpost::nonlinear {

enum class Method { adaptive, harmonic };

/// "adaptive" / "harmonic" (the CLI words); nullopt otherwise.
std::optional<Method> method_named(const std::string& name);

struct CompensationOptions {
  Method method = Method::adaptive;
  double tolerance_mm = 0.005;  ///< the bound on the nonlinear error of every output block
  /// Kept free for rounding the NC words: blocks are cut to tolerance_mm − this (see
  /// `rounding_allowance_mm`), so that the written program, re-executed, meets tolerance_mm.
  double rounding_allowance_mm = 0.0;
  /// The error model's own bow inside a block (adaptive_subdivision.hpp: what compensating the
  /// block's end points leaves between them, on a model whose errors vary along the axes) is
  /// bounded by this share of the tolerance: compensation is what `--model` asks for, and the
  /// tolerance is the linearisation's. Cheap: only long moves bow (a few blocks more). 0: the
  /// tolerance alone.
  double model_bow_share = 0.2;
  AdaptiveOptions adaptive;  ///< its tolerance_mm and model_bow_mm are replaced from the above
  HarmonicOptions harmonic;  ///< likewise
  bool valid() const {
    return tolerance_mm > rounding_allowance_mm && rounding_allowance_mm >= 0 && model_bow_share >= 0 &&
           model_bow_share <= 1 && adaptive.valid() && harmonic.valid();
  }
};

/// Largest tool-tip error (mm) from rounding the words to `linear_decimals` (mm) and
/// `angle_decimals` (deg), for tips within `reach_mm` of the rotary axes' lines.
inline double rounding_allowance_mm(int linear_decimals, int angle_decimals, double reach_mm) {
  const double linear = 0.5 * std::pow(10.0, -linear_decimals) * std::sqrt(3.0);
  const double angle_rad = deg_to_rad(0.5 * std::pow(10.0, -angle_decimals));
  return linear + 2.0 * angle_rad * reach_mm;  // two rotary axes
}

template <class Errors, class Solver>
SplitBlock compensate_block(const Machine& machine, const Setup& setup, const ClBlock& block, const Errors& errors,
                            Solver&& solver, const CompensationOptions& options) {
  if (options.method == Method::harmonic) {
    HarmonicOptions o = options.harmonic;
    o.tolerance_mm = options.tolerance_mm - options.rounding_allowance_mm;
    return harmonic_compensate(machine, setup, block, errors, o);
  }
  AdaptiveOptions o = options.adaptive;
  o.tolerance_mm = options.tolerance_mm - options.rounding_allowance_mm;
  o.model_bow_mm = options.model_bow_share * o.tolerance_mm;
  return subdivide_adaptive(machine, setup, block, errors, solver, o);
}

}  // namespace ncpost::nonlinear
