// SPDX-License-Identifier: Apache-2.0
#pragma once
// The TRR-XY machine (docs/trr-xy.md) as the post's KinematicModel: the common post (post.hpp) writes
// its programs, with --tolerance (trr_subdivider.hpp), --verify, --verify-on and --report.
//
// Commands: AxisPosition slots 0..4 (operator[]) are the words X Y (table) U V W (sliders of chains
// a, b, c), all in mm (CommandWords: no angles, none of a serial chain's capabilities). The commands come from the
// TRR-XY inverse kinematics on `commanded` (the nominal machine, or the machine of `--model`); the
// written program is re-executed (execute()) on `executing` (the same machine, or that of
// `--verify-on`): forward kinematics, Newton from the machine's home plate pose, so the solver keeps
// no state and may solve on the post's read-ahead thread. CL data in W, mm.
#include <string>

#include "ncpost/kinematics/trr_xy_forward.hpp"
#include "ncpost/postproc/solve/motion_solver.hpp"

namespace ncpost {

/// TRR-XY commands as an AxisPosition (slots X Y U V W) and back.
AxisPosition trr_slots(const trr::Command& c);
trr::Command trr_command(const AxisPosition& q);

class TrrSolver final : public KinematicModel {
 public:
  /// `commanded` and `executing` must outlive the solver (they may be the same object).
  TrrSolver(const trr::Kinematics& commanded, const trr::Kinematics& executing, const Vec3d& workpiece_origin_mm);

  IkOutcome solve_quiet(const ClPoint& cl, const AxisPosition& previous, SolverData& data,
                        SolveFigures* figures) const override;
  /// The commands of `cl` (the machine keeps no state: no data, no previous commands needed).
  IkOutcome inverse(const ClPoint& cl) const;
  bool concurrent() const override { return true; }
  /// The TRR-XY machine has no rotary words: the angles are ignored (the post never asks: words().angles_are_programmed
  /// is false).
  AxisPosition with_rotary(const ClPoint& cl, const RotaryAngles& rotary_rad, SolverData& data) const override;
  /// Tool tip and axis in W at the commands; throws Infeasible when the plate pose cannot be solved.
  ToolPoseT<double> execute(const AxisPosition& q, const SolverData& /*data*/) const override { return execute(q); }
  ToolPoseT<double> execute(const AxisPosition& q) const;
  /// The executing machine's pose less the commanded machine's at q (zero when they are the same).
  ToolPoseT<double> deviation(const AxisPosition& q, const SolverData& data) const override;
  /// execute() without throwing: nullopt, with `why`, where the plate pose cannot be solved.
  std::optional<ToolPoseT<double>> pose(const AxisPosition& q, std::string* why) const;
  /// The axes X Y U V W with their limits (all linear: not a serial chain, see words()).
  const Machine& machine() const override { return axes_; }
  CommandWords words() const override;

  const Vec3d& workpiece_origin_mm() const { return origin_; }
  const trr::Kinematics& commanded() const { return commanded_; }

 private:
  const trr::Kinematics& commanded_;
  const trr::Kinematics& executing_;
  Vec3d origin_;
  Machine axes_;
};

}  // namespace ncpost
