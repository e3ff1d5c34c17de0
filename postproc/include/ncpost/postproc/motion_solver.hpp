#pragma once
// How the post turns a CL point into axis commands, and how it re-executes commands: the
// nominal machine (closed-form inverse kinematics), or an actual machine with identified errors
// (plugged in by `post --model`). Frames: CL in W (mm, unit axis), commands in mm and rad.
#include "ncpost/kinematics/forward.hpp"
#include "ncpost/kinematics/inverse.hpp"

namespace ncpost {

class MotionSolver {
 public:
  virtual ~MotionSolver() = default;
  /// Commands that put the tool on `cl`, nearest `previous` (continuity, limits).
  virtual IkOutcome solve(const ClPoint& cl, const AxisPosition& previous) const = 0;
  /// Commands for `cl` with the rotary angles given (programmed angles of G-code input).
  virtual AxisPosition with_rotary(const ClPoint& cl, const Eigen::Vector2d& rotary_rad) const = 0;
  /// Where the tool is at the commands q (tip and axis in W) on the machine the program is for.
  virtual ToolPoseT<double> execute(const AxisPosition& q) const = 0;
  virtual const Machine& machine() const = 0;
  /// Called once a block to the commands q is written: machines with state (reversal) follow it.
  virtual void advance(const AxisPosition& /*q*/) const {}
  /// The tool tip (W) an RTCP program writes for `cl` solved as q (the control inverts it nominally).
  virtual Vec3d programmed_tip(const ClPoint& cl, const AxisPosition& /*q*/) const { return cl.tip_mm; }
};

/// The nominal machine.
class NominalSolver final : public MotionSolver {
 public:
  NominalSolver(const Machine& machine, const Setup& setup) : machine_(machine), setup_(setup) {}
  IkOutcome solve(const ClPoint& cl, const AxisPosition& previous) const override {
    return ncpost::solve(machine_, cl, setup_, previous);
  }
  AxisPosition with_rotary(const ClPoint& cl, const Eigen::Vector2d& rotary_rad) const override {
    AxisPosition q;
    q.rotary_rad = rotary_rad;
    q.linear_mm = linear_for(machine_, rotary_rad, cl.tip_mm, setup_);
    return q;
  }
  ToolPoseT<double> execute(const AxisPosition& q) const override { return forward(machine_, q, setup_); }
  const Machine& machine() const override { return machine_; }

 private:
  const Machine& machine_;
  Setup setup_;
};

}  // namespace ncpost
