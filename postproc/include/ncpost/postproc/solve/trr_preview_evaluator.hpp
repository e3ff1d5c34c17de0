// SPDX-License-Identifier: Apache-2.0
#pragma once
// `ncpost preview` on the TRR-XY machine: the preview's block evaluator (preview_blocks.hpp) on the
// TRR-XY kinematics (trr_block_error.hpp): the control interpolates X Y U V W linearly between the
// block's commands (AxisPosition slots, trr_solver.hpp); the executed tool tip leaves the straight
// CL segment. The harmonic columns are the midpoint fit of seed 001, as on the serial machines.
// Each block starts its forward solves from the plate pose of its start CL point (the inverse
// kinematics; no state between calls): far from home, a Newton solve from home can miss the pose.
// Units: mm, rad; CL in W.
#include "ncpost/compensation/trr_block_error.hpp"
#include "ncpost/postproc/verify/preview_blocks.hpp"

namespace ncpost::preview {

class TrrEvaluator final : public BlockEvaluator {
 public:
  /// `k` must outlive the evaluator.
  TrrEvaluator(const trr::Kinematics& k, const Vec3d& workpiece_origin_mm)
      : k_(k), origin_mm_(workpiece_origin_mm), evaluator_(k, workpiece_origin_mm) {}

  /// Throws PreviewInfeasible (naming the CL line) where the plate pose cannot be solved.
  void evaluate(BlockRow& row) const override;
  std::vector<double> error_curve(const nonlinear::ClBlock& block, int samples) const override;

 private:
  /// The forward solves of one block, warm-started at the plate pose of its start.
  trr::EvaluatorWork work_at(const ClPoint& start) const;

  const trr::Kinematics& k_;
  Vec3d origin_mm_;
  trr::BlockEvaluator evaluator_;
};

}  // namespace ncpost::preview
