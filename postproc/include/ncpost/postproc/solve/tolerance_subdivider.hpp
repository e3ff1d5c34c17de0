// SPDX-License-Identifier: Apache-2.0
#pragma once
// `post --tolerance MM [--nonlinear adaptive|harmonic]`: the post's Subdivider (post.hpp) built on
// nonlinear_compensation.hpp. Blocks are cut on the machine the program is for: the nominal one,
// or the actual machine of `--model` (ActualSolver: its error model, reversal offsets toward the
// block's end). Room is kept for rounding the NC words to the dialect's decimals, from how far the
// block's tips are from the rotary axes.
// A block that starts at a singular pose (tool axis along the inner rotary axis, e.g. vertical on a
// table-table machine, whose free angle the post kept from before) and leaves it in another
// direction first turns the free axis with the tool tip standing on the start point (the tool
// axis does not change), in blocks within the tolerance; then the block is cut as usual.
// Units: mm, rad; CL in W.
#include "ncpost/compensation/nonlinear_compensation.hpp"
#include "ncpost/postproc/solve/actual_solver.hpp"
#include "ncpost/postproc/write/dialect.hpp"
#include "ncpost/postproc/post.hpp"

namespace ncpost {

/// `post` bounds the nonlinear error of every block to this by default (mm, as NX and Fusion post
/// with a default tolerance); `--tolerance none` writes one block per CL motion.
constexpr double kDefaultTolerance_mm = 0.01;

/// Largest distance (mm) of the block's tips from the rotary pivots, in M at home, plus the tool
/// length: how far a rounded angle can move the tip.
double rotary_reach_mm(const Machine& machine, const Setup& setup, const ClPoint& a, const ClPoint& b);

/// The subdivider of a post with `solver`'s commands: the nominal chain, or the actual machine of
/// a model (with reversal: play_subdivision.hpp). One interface for every machine kind: the
/// TRR-XY machine's is in trr_subdivider.hpp. A block that cannot be compensated throws
/// Infeasible saying why (the post adds the file and CL line). `solver` and `dialect` must outlive
/// the returned function.
Subdivider make_tolerance_subdivider(const NominalSolver& solver, const nonlinear::CompensationOptions& options,
                                     const Dialect& dialect);
Subdivider make_tolerance_subdivider(const ActualSolver& solver, const nonlinear::CompensationOptions& options,
                                     const Dialect& dialect);

}  // namespace ncpost
