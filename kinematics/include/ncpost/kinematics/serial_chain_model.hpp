// SPDX-License-Identifier: Apache-2.0
#pragma once
// The nominal serial chain as a KinematicModel (kinematic_model.hpp). Frames and units as there.
#include "ncpost/kinematics/forward.hpp"
#include "ncpost/kinematics/inverse.hpp"
#include "ncpost/kinematics/kinematic_model.hpp"

namespace ncpost {

/// The serial chain of a Machine file, nominal (closed-form inverse kinematics, inverse.hpp): no
/// state, no figures; the data passed is left untouched.
class SerialChainModel final : public KinematicModel {
 public:
  SerialChainModel(const Machine& machine, const Setup& setup) : machine_(machine), setup_(setup) {}
  IkOutcome solve_quiet(const ClPoint& cl, const AxisPosition& previous, SolverData&, SolveFigures*) const override {
    return solve(cl, previous);
  }
  using KinematicModel::solve;
  /// The nominal machine keeps no state and measures nothing: solve() needs no data.
  IkOutcome solve(const ClPoint& cl, const AxisPosition& previous) const {
    return ncpost::solve(machine_, cl, setup_, previous);
  }
  bool concurrent() const override { return true; }
  AxisPosition with_rotary(const ClPoint& cl, const RotaryAngles& rotary_rad, SolverData&) const override {
    return with_rotary(cl, rotary_rad);
  }
  /// with_rotary() needs no data on the nominal machine.
  AxisPosition with_rotary(const ClPoint& cl, const RotaryAngles& rotary_rad) const {
    const RotaryAngles rotary = rotary_rad.size() == machine_.rotary_count()
                                    ? rotary_rad
                                    : rotary_of(AxisPosition(Vec3d::Zero(), rotary_rad), machine_.rotary_count());
    return AxisPosition(linear_for(machine_, rotary, cl.tip_mm, setup_), rotary);
  }
  ToolPoseT<double> execute(const AxisPosition& q, const SolverData&) const override { return execute(q); }
  /// execute() needs no data on the nominal machine.
  ToolPoseT<double> execute(const AxisPosition& q) const { return forward(machine_, q, setup_); }
  const Machine& machine() const override { return machine_; }
  const Setup& setup() const { return setup_; }
  std::vector<AxisPosition> branches(const ClPoint& cl, const AxisPosition& previous, SolverData&) const override {
    const SmallList<AxisPosition, 2> all = admissible_solutions(machine_, cl, setup_, previous);
    return {all.begin(), all.end()};
  }

 private:
  const Machine& machine_;
  Setup setup_;
};

}  // namespace ncpost
