// SPDX-License-Identifier: Apache-2.0
#pragma once
// Compensating many blocks on several threads (issue 4 "Speed": use both cores where it pays).
//
// The blocks of a program are independent once their end points are solved (the inverse
// kinematics of the CL points is sequential — continuity — and cheap; the nonlinear error of each
// block is what costs). A post reads a batch of motions, solves them in order, hands the blocks to
// `compensate_blocks`, and emits the results in order: memory stays bounded by the batch size.
// `errors` and `solver` are called from several threads at once: they must be safe for concurrent
// const calls (the nominal IK and the model functors are). Units as nonlinear_compensation.hpp.
#include <algorithm>
#include <thread>
#include <vector>

#include "ncpost/compensation/nonlinear_compensation.hpp"

namespace ncpost::nonlinear {

/// Compensates `blocks` with `threads` workers (1: in the calling thread); result i is block i's.
template <class Errors, class Solver>
std::vector<SplitBlock> compensate_blocks(const Machine& machine, const Setup& setup,
                                          const std::vector<ClBlock>& blocks, const Errors& errors,
                                          const Solver& solver, const CompensationOptions& options, int threads = 2) {
  std::vector<SplitBlock> out(blocks.size());
  auto work = [&](std::size_t first, std::size_t step) {
    Solver local = solver;  // callables are copied per thread (they may hold references only)
    for (std::size_t i = first; i < blocks.size(); i += step)
      out[i] = compensate_block(machine, setup, blocks[i], errors, local, options);
  };
  const std::size_t n = static_cast<std::size_t>(std::max(1, threads));
  if (n == 1 || blocks.size() < 64) {
    work(0, 1);
    return out;
  }
  // interleaved: neighbouring blocks cost alike, so the threads finish together
  std::vector<std::thread> pool;
  for (std::size_t k = 1; k < n; ++k) pool.emplace_back(work, k, n);
  work(0, n);
  for (auto& t : pool) t.join();
  return out;
}

}  // namespace ncpost::nonlinear
