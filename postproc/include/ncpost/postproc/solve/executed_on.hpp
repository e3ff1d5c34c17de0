// SPDX-License-Identifier: Apache-2.0
#pragma once
// A KinematicModel whose commands come from one solver and whose execution is another machine's:
// `post --verify-on TRUTH.json` re-executes the written program on a machine other than the one
// it was compensated for (a simulated true machine, or a newer model), the way a test cuts a part.
// Frames and units as motion_solver.hpp. Reversal offsets of the executing machine are followed
// block by block in SolverData::executing_stands, as ActualSolver does in SolverData::stands.
#include <optional>

#include "ncpost/compensation/actual_ik.hpp"
#include "ncpost/compensation/machine_model.hpp"
#include "ncpost/postproc/solve/motion_solver.hpp"
#include "ncpost/postproc/solve/post_hooks.hpp"

namespace ncpost {

class ExecutedOn final : public KinematicModel, public PostHooks {
 public:
  ExecutedOn(const KinematicModel& commands, const comp::MachineModel& executing, const Setup& setup)
      : commands_(commands), executing_(executing), setup_(setup) {}
  IkOutcome solve_quiet(const ClPoint& cl, const AxisPosition& previous, SolverData& data,
                        SolveFigures* figures) const override {
    return commands_.solve_quiet(cl, previous, data, figures);
  }
  bool concurrent() const override { return commands_.concurrent(); }
  bool stateless_execute() const override { return !executing_.has_reversal(); }
  AxisPosition with_rotary(const ClPoint& cl, const RotaryAngles& rotary_rad, SolverData& data) const override {
    return commands_.with_rotary(cl, rotary_rad, data);
  }
  /// On the executing machine, its axes standing at data.executing_stands.
  ToolPoseT<double> execute(const AxisPosition& q, const SolverData& data) const override {
    return executing_.tool_pose(q, setup_, comp::reversal_state(executing_, q, data.executing_stands));
  }
  void advance(const AxisPosition& q, SolverData& data) const override {
    post_hooks_of(commands_).advance(q, data);
    if (executing_.has_reversal()) data.executing_stands = comp::actual_after(executing_, q, data.executing_stands);
  }
  Vec3d programmed_tip(const ClPoint& cl, const AxisPosition& q) const override {
    return post_hooks_of(commands_).programmed_tip(cl, q);
  }
  std::optional<AxisPosition> take_up(const AxisPosition& from, const AxisPosition& to,
                                      const SolverData& data) const override {
    return post_hooks_of(commands_).take_up(from, to, data);
  }
  const Machine& machine() const override { return commands_.machine(); }

 private:
  const KinematicModel& commands_;
  const comp::MachineModel& executing_;
  Setup setup_;
};

}  // namespace ncpost
