// SPDX-License-Identifier: Apache-2.0
#pragma once
// The actual machine of `--model` as a KinematicModel (`post --model`, `preview --model`): commands
// from the compensated inverse kinematics (compensation/actual_ik.hpp), started from the nominal
// solution with the post's solution choice (limits, continuity), executed through the error model.
// Frames and units as motion_solver.hpp: CL in W (mm, unit axis), commands in mm and rad.
//
// Reversal: where the model has reversal terms, the solver follows where the axes actually stand
// after each emitted block (`advance`, in the caller's SolverData::stands), solves the next
// commands consistently with the direction they imply, and re-executes a block from that state. Within one block each
// axis is taken to move one way (true of blocks cut to a tolerance; a reversal happens at a block end).
//
// It also measures what compensation buys: SolverData::uncompensated is the tool-tip error at the
// CL points of the nominal solution executed on this machine (the program without `--model`).
//
// The solver is immutable (any number of threads); what changes as a program is posted (reversal
// state, the last solution's error, the figures) is in the SolverData each caller passes.
#include <optional>
#include <vector>

#include "ncpost/compensation/actual_ik.hpp"
#include "ncpost/compensation/machine_model.hpp"
#include "ncpost/postproc/solve/motion_solver.hpp"
#include "ncpost/postproc/solve/post_hooks.hpp"

namespace ncpost {

class ActualSolver final : public KinematicModel, public PostHooks {
 public:
  /// Convergence of the compensated IK when posting: a tenth of the NC words' resolution
  /// (4 decimals: 1e-4 mm, 1e-4 deg = 1.7e-6 rad). One fixed-point step reaches it on smooth
  /// models where the library default (1e-6 mm, 1e-8 rad) takes two.
  static constexpr double kPostTipToleranceMm = 1e-5;
  static constexpr double kPostAxisToleranceRad = 1e-7;

  ActualSolver(const comp::MachineModel& model, const Setup& setup)
      : model_(model),
        setup_(setup),
        nominal_(model.machine(), setup),
        home_(model.home_inverse(setup.tool_length_mm)) {}

  /// Whether solve() measures the uncompensated tip error of each CL point (SolverData::uncompensated;
  /// one more nominal IK and model evaluation per point). On by default; the post turns it off
  /// when nothing reports it.
  void set_measure_uncompensated(bool on) { measure_uncompensated_ = on; }

  IkOutcome solve_quiet(const ClPoint& cl, const AxisPosition& previous, SolverData& data,
                        SolveFigures* figures) const override;
  /// solve_quiet with the axes standing at `stands` (reversal; nullopt: no history) instead of
  /// where the emitted program left them (data.stands): the nodes of a block after a reversal inside it.
  IkOutcome solve_standing(const ClPoint& cl, const AxisPosition& previous, SolverData& data, SolveFigures* figures,
                           const std::optional<AxisPosition>& stands) const;
  /// Without reversal terms the commands depend on the CL point and the previous commands only.
  bool concurrent() const override { return !model_.has_reversal(); }
  AxisPosition with_rotary(const ClPoint& cl, const RotaryAngles& rotary_rad, SolverData& data) const override;
  ToolPoseT<double> execute(const AxisPosition& q, const SolverData& data) const override;
  void advance(const AxisPosition& command, SolverData& data) const override;
  std::optional<AxisPosition> take_up(const AxisPosition& from, const AxisPosition& to,
                                      const SolverData& data) const override;
  Vec3d programmed_tip(const ClPoint& cl, const AxisPosition& q) const override;
  const Machine& machine() const override { return model_.machine(); }
  /// Each branch of the nominal chain within the limits, compensated (those that converge).
  std::vector<AxisPosition> branches(const ClPoint& cl, const AxisPosition& previous, SolverData& data) const override;
  /// The error model at q (its error hook through the chain), from where data.stands has the axes.
  ToolPoseT<double> deviation(const AxisPosition& q, const SolverData& data) const override;

  /// The error hook for a block from axes standing at `stands` (nullopt: no history, offsets 0;
  /// data.stands: where the emitted program left them): each command's reversal offset is that of
  /// the dead band from there (RowState::previous_actual).
  comp::ErrorFunctor<double> errors_from(const std::optional<AxisPosition>& stands) const {
    comp::RowState<double> state;
    if (stands) {
      PerAxis<double> previous{};
      for (int a = 0; a < stands->size(); ++a) previous[static_cast<std::size_t>(a)] = (*stands)[a];
      state.previous_actual = previous;
    }
    return model_.errors(state).with_home(&home_);
  }
  /// Where they stand after moving to `command` from `stands`.
  AxisPosition stands_after(const AxisPosition& command, const std::optional<AxisPosition>& stands) const {
    return comp::actual_after(model_, command, stands);
  }
  /// True when commands q, reached from `stands`, put the tool on `cl` within the IK's tolerances.
  bool reaches(const ClPoint& cl, const AxisPosition& q, const std::optional<AxisPosition>& stands) const;
  const comp::MachineModel& model() const { return model_; }
  const Setup& setup() const { return setup_; }

 private:
  /// `guess` solves `guess_solves` nominally (nullopt: programmed angles).
  /// `executed` (if given) gets the actual pose at the result when it is that of every execution
  /// there (models without reversal). `previous` (the previous commands, if known): with reversal
  /// an axis that need not move keeps its command inside the play.
  AxisPosition compensate(const ClPoint& cl, const AxisPosition& guess, const std::optional<ClPoint>& guess_solves,
                          SolverData& data, SolveFigures* figures, std::string& failure,
                          std::optional<ToolPoseT<double>>* executed, const std::optional<AxisPosition>& previous,
                          const std::optional<AxisPosition>& stands) const;
  /// The error of the machine at commands q (actual − nominal tip and axis in W): the prediction
  /// for the next CL point. Kept in `data` for the last solution, so a path pays nothing for it.
  ToolPoseT<double> error_at(const AxisPosition& q, SolverData& data) const;
  void keep_error(const AxisPosition& q, const ToolPoseT<double>& actual, SolverData& data) const;

  const comp::MachineModel& model_;
  Setup setup_;
  NominalSolver nominal_;
  HomeInverse home_;
  bool measure_uncompensated_ = true;
};

}  // namespace ncpost
