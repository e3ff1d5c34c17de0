// SPDX-License-Identifier: Apache-2.0
#pragma once
// The ideal subdivision of a block, the yardstick of the adaptive method (issue 4: at most 1.25x
// the blocks of an ideal per-block subdivision): the fewest output blocks, with end points on the
// CL segment solved exactly, that keep every output block within the tolerance.
//
// Computed greedily: from the start, the farthest point of the segment that one output block can
// reach within the tolerance (bisection on t), repeated. When a sub-segment within the tolerance
// keeps its sub-segments within it (true of bows, which shrink with the length), the greedy count is
// the minimum. Costly (about 30 exact errors per output block): for tests and benchmarks.
// Also the estimate by the 1/n² law, ceil(sqrt(E / tolerance)). Units: mm; t of the input block.
#include <cmath>

#include "ncpost/compensation/adaptive_subdivision.hpp"

namespace ncpost::nonlinear {

/// ceil(sqrt(E / tolerance)), at least 1: the output blocks the 1/n² law predicts.
inline int square_law_blocks(double error_mm, double tolerance_mm) {
  return std::max(1, static_cast<int>(std::ceil(std::sqrt(error_mm / tolerance_mm) - 1e-12)));
}

/// The greedy (ideal) number of output blocks; -1 if a node cannot be solved or no progress is made.
template <class Errors, class Solver>
int ideal_block_count(const Machine& machine, const Setup& setup, const ClBlock& block, const Errors& errors,
                      Solver&& solver, double tolerance_mm, const NonlinearErrorOptions& options = {}) {
  double ta = 0.0;
  ClPoint ca = block.start;
  AxisPosition qa = block.from;
  auto error = [&](const ClPoint& cb, const AxisPosition& qb) {
    return nonlinear_error(machine, setup, ClBlock{ca, cb, qa, qb}, errors, options).max_error_mm;
  };
  for (int count = 1; count < 100000; ++count) {
    if (error(block.end, block.to) <= tolerance_mm) return count;
    double lo = ta, hi = 1.0;
    AxisPosition q_lo = qa;
    for (int it = 0; it < 40 && hi - lo > 1e-10; ++it) {
      const double mid = 0.5 * (lo + hi);
      const IkOutcome o = solver(cl_at(block.start, block.end, mid), qa);
      if (!o.ok()) return -1;
      if (error(cl_at(block.start, block.end, mid), *o.position) <= tolerance_mm) {
        lo = mid;
        q_lo = *o.position;
      } else {
        hi = mid;
      }
    }
    if (lo <= ta) return -1;
    ta = lo;
    ca = cl_at(block.start, block.end, lo);
    qa = q_lo;
  }
  return -1;
}

}  // namespace ncpost::nonlinear
