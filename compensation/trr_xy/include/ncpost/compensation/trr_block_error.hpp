// SPDX-License-Identifier: Apache-2.0
#pragma once
// The nonlinear error of one block on the TRR-XY machine (docs/conventions.md "Execution model"):
// the control interpolates X, Y, U, V, W linearly between the block's end commands; the executed
// tool tip (forward kinematics, trr_xy_forward.hpp, relative to the workpiece, in W) leaves the
// straight CL segment between the end points. Measured in W (mm) as the distance from the
// segment, and the orientation error as the angle between the executed tool axis and the
// normalised linear interpolation of the CL axes (rad).
#include <optional>
#include <string>
#include <vector>

#include "ncpost/kinematics/machine.hpp"
#include "ncpost/kinematics/trr_xy_forward.hpp"

namespace ncpost::trr {

/// A block: CL end points (W) and the commands the control interpolates.
struct Block {
  ClPoint from_cl, to_cl;
  Command from, to;
};

/// The executed tool at fraction t of a block.
struct ExecutedPoint {
  Vec3d tip_mm = Vec3d::Zero();     ///< in W
  Vec3d axis = Vec3d::UnitZ();      ///< in W
  Vec3d offset_mm = Vec3d::Zero();  ///< from the nearest point of the straight CL segment to the tip
  double orientation_rad = 0.0;
};

struct BlockError {
  double max_mm = 0.0;
  double at_t = 0.0;
  Vec3d offset_mm = Vec3d::Zero();  ///< at the maximum
  double orientation_rad = 0.0;     ///< largest orientation error
  double orientation_at_t = 0.0;
  double midpoint_mm = 0.0;           ///< |deviation| at t = ½ (the harmonic model's Emax, seed 001)
  double harmonic_residual_mm = 0.0;  ///< max over the samples of | |e(t)| − Emax·sin(πt) |
};

/// The working data of one thread's forward solves: the last plate pose, the warm start of the
/// next Newton solve (blocks follow each other, so it is near). Owned by the caller, one per thread.
struct EvaluatorWork {
  std::optional<Rigidd> warm_plate;
};

/// Evaluates blocks on one machine (immutable: any number of threads, each with its own work).
class BlockEvaluator {
 public:
  BlockEvaluator(const Kinematics& k, const Vec3d& workpiece_origin_mm) : k_(k), origin_(workpiece_origin_mm) {}

  /// The executed tool at t ∈ [0, 1]; nullopt (with `why`) if the forward kinematics fails.
  std::optional<ExecutedPoint> at(const Block& b, double t, EvaluatorWork& work, std::string* why = nullptr) const;
  /// Largest errors over the block: `samples` equal steps, then a golden-section refinement
  /// around the largest sample. Throws std::runtime_error if a pose cannot be solved.
  BlockError evaluate(const Block& b, EvaluatorWork& work, int samples = 24) const;

 private:
  const Kinematics& k_;
  Vec3d origin_;
};

}  // namespace ncpost::trr
