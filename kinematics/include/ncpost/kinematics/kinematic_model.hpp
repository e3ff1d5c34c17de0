// SPDX-License-Identifier: Apache-2.0
#pragma once
// One kinematic model interface for every machine, like the kinematics modules of LinuxCNC and
// the Model/Data split of Pinocchio: the model (this class) is immutable — its axes and their NC
// words, their limits, the forward kinematics (execute), the inverse with the post's choice of
// solution (solve) and with all branches (branches), the error hook (deviation) — and the working
// data (SolverData, solver_data.hpp) is passed explicitly, one per thread. What only the post asks
// (following a written block, reversal take-up, the tip an RTCP program writes) is not here: the
// post's hooks (postproc/solve/post_hooks.hpp), implemented by the models that need them. Implementations: the
// serial chain (serial_chain_model.hpp), the serial chain with an error model (ActualSolver,
// postproc/actual_solver.hpp, on compensation/'s MachineModel) and the TRR-XY machine (TrrSolver,
// postproc/trr_solver.hpp). Frames: CL in W (mm, unit axis), commands in mm and rad.
#include <vector>

#include "ncpost/kinematics/command_words.hpp"
#include "ncpost/kinematics/inverse.hpp"
#include "ncpost/kinematics/solver_data.hpp"

namespace ncpost {

/// A machine's kinematics (immutable: any number of threads, each with its own SolverData).
class KinematicModel {
 public:
  virtual ~KinematicModel() = default;
  /// Commands that put the tool on `cl`, nearest `previous` (continuity, limits), recording the
  /// figures of the point in `data` (solve_quiet + SolverData::record).
  IkOutcome solve(const ClPoint& cl, const AxisPosition& previous, SolverData& data) const {
    SolveFigures figures;
    IkOutcome o = solve_quiet(cl, previous, data, &figures);
    data.record(figures);
    return o;
  }
  /// solve() without recording: the figures go to `figures` (if given). When `concurrent()`, it
  /// may run on another thread (with that thread's own `data`) while the post calls anything else.
  virtual IkOutcome solve_quiet(const ClPoint& cl, const AxisPosition& previous, SolverData& data,
                                SolveFigures* figures) const = 0;
  /// True when solve_quiet() depends on nothing the post's progress changes (no reversal state).
  virtual bool concurrent() const { return false; }
  /// Commands for `cl` with the rotary angles given (programmed angles of G-code input).
  virtual AxisPosition with_rotary(const ClPoint& cl, const RotaryAngles& rotary_rad, SolverData& data) const = 0;
  /// Where the tool is at the commands q (tip and axis in W) on the machine the program is for,
  /// the axes standing where `data` says.
  virtual ToolPoseT<double> execute(const AxisPosition& q, const SolverData& data) const = 0;
  /// True when execute() depends on q alone, not on where `data` says the axes stand.
  virtual bool stateless_execute() const { return concurrent(); }
  /// The axes, their letters and limits (a serial chain's Machine; the TRR-XY machine's X Y U V W).
  virtual const Machine& machine() const = 0;
  /// The inverse with all its branches: every solution of `cl` within the limits (unwound near
  /// `previous`), best first. Default: solve()'s only.
  virtual std::vector<AxisPosition> branches(const ClPoint& cl, const AxisPosition& previous, SolverData& data) const {
    const IkOutcome o = solve_quiet(cl, previous, data, nullptr);
    if (!o.ok()) return {};
    return {*o.position};
  }
  /// The error hook: the machine's error at the commands q (executed − nominal tool tip, mm, and
  /// tool axis, W), the axes standing where `data` says. Default: none (a nominal machine).
  virtual ToolPoseT<double> deviation(const AxisPosition& /*q*/, const SolverData& /*data*/) const {
    return {Vec3d::Zero(), Vec3d::Zero()};
  }
  /// The NC words of the commands (default: those of machine(), a serial chain).
  virtual CommandWords words() const { return CommandWords::of(machine()); }
};

}  // namespace ncpost
