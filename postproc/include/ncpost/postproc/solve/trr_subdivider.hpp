// SPDX-License-Identifier: Apache-2.0
#pragma once
// `post --tolerance MM` on the TRR-XY machine: the post's Subdivider (post.hpp) for TrrSolver.
// The control interpolates X, Y, U, V, W linearly between the *rounded* commands (the dialect's
// decimals); the executed tool tip (forward kinematics on the commanded machine,
// trr_block_error.hpp) leaves the straight CL segment. A block whose error exceeds
// `split_fraction` of the tolerance is cut into ceil(sqrt(error / target)) (2 to 64) equal CL
// pieces — tip interpolated linearly, axis on the great circle; the error of a short block grows
// with its length squared — each checked again, at most `max_depth` times. The interpolated axis
// is nonlinear::slerp (nonlinear_block.hpp), as everywhere in the post. With `--nonlinear harmonic`
// the block is cut by the paper's shift instead (make_trr_subdivider). mm, rad, CL in W.
#include "ncpost/compensation/nonlinear_compensation.hpp"
#include "ncpost/postproc/write/dialect.hpp"
#include "ncpost/postproc/post.hpp"
#include "ncpost/postproc/solve/trr_solver.hpp"

namespace ncpost {

struct TrrSubdivision {
  double tolerance_mm = 0.01;
  /// adaptive: the cutting above; harmonic: the paper's shift (harmonic_compensation.hpp), the
  /// tolerance choosing the number of blocks but not bounding what the model leaves.
  nonlinear::Method method = nonlinear::Method::adaptive;
  /// Blocks are cut while their error exceeds this fraction of the tolerance: a margin for a
  /// checker that samples the block differently.
  double split_fraction = 0.95;
  int max_depth = 24;
};

/// The post's options on this machine: no rotary words, so no native arcs or cycles (holes are
/// drilled by explicit moves), no rapid ordering by Z (there is none), rapids cut to the tolerance
/// too (the sliders interpolate far from the straight line), the tool length in the kinematics
/// (no tool-length block after a tool call).
PostOptions trr_post_options();

/// The subdivider; `solver` and `dialect` must outlive it. An inserted point out of reach throws
/// Infeasible saying why (the post adds the file and CL line).
Subdivider make_trr_subdivider(const TrrSolver& solver, const Dialect& dialect, const TrrSubdivision& options);
/// The same with the options of every machine kind (tolerance_subdivider.hpp): the tolerance and
/// the method, the cutting's own fractions at their defaults.
Subdivider make_tolerance_subdivider(const TrrSolver& solver, const nonlinear::CompensationOptions& options,
                                     const Dialect& dialect);

}  // namespace ncpost
