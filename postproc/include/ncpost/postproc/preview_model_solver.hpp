#pragma once
// The actual machine of `--model` as a MotionSolver, for `preview --model` and the benchmark:
// commands from the compensated inverse kinematics (compensation/actual_ik.hpp, from the nominal
// solution with the post's solution choice; reversal offsets not tracked), executed through the
// error model. Frames and units as motion_solver.hpp. To give way to the post's own actual-machine
// solver when `post --model` lands.
#include "ncpost/compensation/actual_ik.hpp"
#include "ncpost/compensation/machine_model.hpp"
#include "ncpost/postproc/motion_solver.hpp"

namespace ncpost::preview {

class ModelMotionSolver final : public MotionSolver {
 public:
  ModelMotionSolver(const comp::MachineModel& model, const Setup& setup)
      : model_(model), setup_(setup), nominal_(model.machine(), setup) {}
  IkOutcome solve(const ClPoint& cl, const AxisPosition& previous) const override {
    IkOutcome o = nominal_.solve(cl, previous);
    if (!o.ok()) return o;
    const comp::ActualIkOutcome actual = comp::solve_actual(model_, cl, setup_, *o.position);
    if (!actual.ok()) {
      o.position.reset();
      o.failure.message = "compensated inverse kinematics: " + actual.message;
      return o;
    }
    o.position = actual.position;
    return o;
  }
  AxisPosition with_rotary(const ClPoint& cl, const Eigen::Vector2d& rotary_rad) const override {
    return nominal_.with_rotary(cl, rotary_rad);
  }
  ToolPoseT<double> execute(const AxisPosition& q) const override { return model_.tool_pose(q, setup_); }
  const Machine& machine() const override { return model_.machine(); }

 private:
  const comp::MachineModel& model_;
  Setup setup_;
  NominalSolver nominal_;
};

}  // namespace ncpost::preview
