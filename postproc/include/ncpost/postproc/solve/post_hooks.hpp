// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the post asks of a kinematic model beyond its kinematics. The kinematic model
// (kinematics/kinematic_model.hpp) keeps the axis words, limits, branches, forward and inverse;
// these are the post's: a machine with state (reversal) follows each written block and takes up
// its play before a block that reverses an axis, and an RTCP program writes the tool tip that the
// control inverts nominally. A model that needs them implements PostHooks beside KinematicModel
// (ActualSolver, ExecutedOn); every other model has none (post_hooks_of). Frames and units as
// motion_solver.hpp: CL in W (mm, unit axis), commands in mm and rad.
#include <optional>

#include "ncpost/kinematics/kinematic_model.hpp"

namespace ncpost {

/// The post's hooks of a kinematic model (immutable; the state is in the caller's SolverData).
/// The defaults are those of a machine without state.
class PostHooks {
 public:
  virtual ~PostHooks() = default;
  /// Called once a block to the commands q is written: machines with state (reversal) follow it in `data`.
  virtual void advance(const AxisPosition& /*q*/, SolverData& /*data*/) const {}
  /// Before a feed block from `from` to `to`: commands that take up the reversal play of the axes
  /// whose direction reverses (the tool stands still), so that the block itself runs without lag;
  /// nullopt when there is nothing to take up (machines without reversal).
  virtual std::optional<AxisPosition> take_up(const AxisPosition& /*from*/, const AxisPosition& /*to*/,
                                              const SolverData& /*data*/) const {
    return std::nullopt;
  }
  /// The tool tip (W) an RTCP program writes for `cl` solved as q (the control inverts it nominally).
  virtual Vec3d programmed_tip(const ClPoint& cl, const AxisPosition& /*q*/) const { return cl.tip_mm; }
};

/// The hooks of `model`: its own where it implements PostHooks, else the defaults (nothing to
/// follow or take up; the CL tip programmed).
const PostHooks& post_hooks_of(const KinematicModel& model);

}  // namespace ncpost
