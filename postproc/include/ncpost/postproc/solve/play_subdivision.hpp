// SPDX-License-Identifier: Apache-2.0
#pragma once
// `post --model --tolerance` on a model with reversal: the block subdivision that follows the play.
//
// The adaptive subdivision (adaptive_subdivision.hpp) solves and measures every node of a block
// from where the axes stood at its start, as if each axis moved one way along the block. An axis
// with reversal often turns back inside a block: on a five-axis path at constant tilt the exact
// tilt dips between two CL points (the tool axis on the great circle), so the tilt axis falls and
// rises inside every block. Solved from the block's start, the nodes after the turn are on the
// wrong side of the play, and executed in sequence the axis stands in its band instead.
//
// Here the block is cut into stretches in which every axis with reversal moves one way:
//   1. subdivide the rest of the block from where the axes stand (its end re-solved from there
//      when the held end is not reached from there);
//   2. before the first node, take up the play of every axis that must start the other way than
//      its command stands in the band (a node with the tool still, only the command moves). The
//      way an axis starts is that of its first move beyond one step of the NC words: the axes
//      stand at the written (rounded) commands, so a target within a step of them lies on either
//      side by rounding alone — taking up the play toward it would make an axis that barely moves
//      over the block (a few µm of compensation) cross its whole play while the tool moves;
//   3. replay the nodes through the dead band in sequence; at the first node whose actual position
//      differs from the stretch's model (an axis turned back before it), keep the nodes before it,
//      stand there, and go to 1 with the rest of the block;
//   4. at the end, if the block's held end commands differ from the stretch's, a last node moves
//      the commands there inside the play (tool still), so the post goes on from its own end.
// Each stretch meets the tolerance by the adaptive subdivision, and its model is exact.
// Units: mm, rad; CL in W.
#include <string>
#include <vector>

#include "ncpost/compensation/nonlinear_compensation.hpp"
#include "ncpost/postproc/solve/actual_solver.hpp"
#include "ncpost/postproc/post.hpp"

namespace ncpost {

/// One unit of the last decimal of the NC words: linear axes (mm), rotary axes (rad).
struct WordSteps {
  double linear_mm = 1e-4;
  double rotary_rad = 1e-4 * kPi / 180.0;
};

/// The nodes of the block (from, to) ending with `to`'s commands; empty with `failure` set when a
/// stretch cannot be compensated. `steps`: the resolution the commands are written with. `data`:
/// the post's (the axes stand at data.stands; the solver's caches).
std::vector<SolvedPoint> subdivide_with_play(const Machine& machine, const Setup& setup, const ActualSolver& actual,
                                             SolverData& data, const SolvedPoint& from, const SolvedPoint& to,
                                             const nonlinear::CompensationOptions& options, const WordSteps& steps,
                                             std::string& failure);

}  // namespace ncpost
