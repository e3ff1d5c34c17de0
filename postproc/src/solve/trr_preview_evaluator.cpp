// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/solve/trr_preview_evaluator.hpp"

#include <fmt/format.h>

#include "ncpost/kinematics/trr_xy_inverse.hpp"
#include "ncpost/postproc/solve/trr_solver.hpp"

namespace ncpost::preview {
namespace {

trr::Block trr_block(const nonlinear::ClBlock& b) { return {b.start, b.end, trr_command(b.from), trr_command(b.to)}; }

}  // namespace

trr::EvaluatorWork TrrEvaluator::work_at(const ClPoint& start) const {
  trr::EvaluatorWork work;
  const trr::InverseOutcome at_start = trr::inverse(k_, start, origin_mm_, false);
  if (at_start.ok()) work.warm_plate = at_start.machine_T_plate;
  return work;
}

void TrrEvaluator::evaluate(BlockRow& row) const {
  trr::EvaluatorWork work = work_at(row.cl.start);
  trr::BlockError e;
  try {
    e = evaluator_.evaluate(trr_block(row.cl), work);
  } catch (const std::runtime_error& ex) {
    throw PreviewInfeasible(fmt::format("CL line {}: {}", row.line, ex.what()));
  }
  row.exact.max_error_mm = e.max_mm;
  row.exact.at_t = e.at_t;
  row.exact.offset_mm = e.offset_mm;
  row.exact.max_orientation_rad = e.orientation_rad;
  row.exact.orientation_at_t = e.orientation_at_t;
  row.harmonic_mm = e.midpoint_mm;
  row.harmonic_residual_mm = e.harmonic_residual_mm;
}

std::vector<double> TrrEvaluator::error_curve(const nonlinear::ClBlock& block, int samples) const {
  const trr::Block b = trr_block(block);
  trr::EvaluatorWork work = work_at(block.start);
  std::vector<double> out;
  for (int k = 0; k <= samples; ++k) {
    const auto e = evaluator_.at(b, static_cast<double>(k) / samples, work);
    out.push_back(e ? e->offset_mm.norm() : 0.0);
  }
  return out;
}

}  // namespace ncpost::preview
