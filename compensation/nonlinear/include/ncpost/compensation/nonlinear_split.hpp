// SPDX-License-Identifier: Apache-2.0
#pragma once
// A block replaced by several output blocks (nonlinear-error compensation): the inserted nodes
// and the verified result. Shared by the adaptive subdivision (adaptive_subdivision.hpp) and the
// harmonic compensation (harmonic_compensation.hpp).
//
// Frames and units: CL points in W (mm, unit axis); axis positions in mm and rad; t is the
// parameter of the *input* block's CL segment (0 at its start, 1 at its end).
#include <string>
#include <vector>

#include "ncpost/compensation/nonlinear_error.hpp"

namespace ncpost::nonlinear {

/// One output block end point.
struct BlockNode {
  double t = 1.0;  ///< where on the input CL segment the node's CL point lies
  ClPoint cl;      ///< the CL point the node stands for (on the straight segment)
  AxisPosition q;  ///< the commanded axis position emitted
};

/// The output of compensating one input block: emit `nodes` in order, each as one G1 block
/// (the last node is the input block's end, with its axis position unchanged).
struct SplitBlock {
  std::vector<BlockNode> nodes;
  double input_error_mm = 0.0;       ///< nonlinear error of the input block
  double max_error_mm = 0.0;         ///< largest verified error of the output blocks
  double max_orientation_rad = 0.0;  ///< largest verified orientation error of the output blocks
  bool screened = false;             ///< within the tolerance by `nonlinear_bound`: the errors above
                                     ///< are that upper bound, the exact maximisation was skipped
  int rotary_kept_nodes = 0;         ///< inserted nodes without an admissible continuous IK solution:
                                     ///< rotary angles interpolated, tip exact (adaptive)
  std::string failure;               ///< set when the block could not be compensated (limits, IK)
  bool ok() const { return failure.empty(); }
  int output_blocks() const { return static_cast<int>(nodes.size()); }
  int inserted_blocks() const { return static_cast<int>(nodes.size()) - 1; }
};

/// Re-executes the output blocks of `split` (starting at `block.from`) and sets its verified
/// largest errors: every output block is measured against its own CL sub-segment.
template <class Errors>
void verify_split(const Machine& machine, const Setup& setup, const ClBlock& block, SplitBlock& split,
                  const Errors& errors, const NonlinearErrorOptions& options = {}) {
  split.max_error_mm = 0.0;
  split.max_orientation_rad = 0.0;
  ClPoint start = block.start;
  AxisPosition from = block.from;
  for (const BlockNode& node : split.nodes) {
    const NonlinearError e = nonlinear_error(machine, setup, ClBlock{start, node.cl, from, node.q}, errors, options);
    split.max_error_mm = std::max(split.max_error_mm, e.max_error_mm);
    split.max_orientation_rad = std::max(split.max_orientation_rad, e.max_orientation_rad);
    start = node.cl;
    from = node.q;
  }
}

}  // namespace ncpost::nonlinear
