// SPDX-License-Identifier: Apache-2.0
#pragma once
// How the post turns a CL point into axis commands, and how it re-executes commands: the
// nominal machine (closed-form inverse kinematics), or an actual machine with identified errors
// (plugged in by `post --model`). Frames: CL in W (mm, unit axis), commands in mm and rad.
#include <array>
#include <optional>

#include "ncpost/kinematics/forward.hpp"
#include "ncpost/kinematics/inverse.hpp"

namespace ncpost {

/// What solving one CL point measured, kept by the solver as running figures (ActualSolver: the
/// tip error of the uncompensated commands and the residual of the compensated ones, mm; < 0: none).
struct SolveFigures {
  double uncompensated_tip_mm = -1.0;
  double residual_mm = -1.0;
};

/// The NC words of a solver's commands: AxisPosition slot i (operator[]) is the word `letters[i]`,
/// an angle (rad inside, degrees in the program) where `angle[i]`, else a length (mm). Serial
/// machines: X Y Z and their rotary axes; the TRR-XY machine: X Y U V W, all lengths. Read once
/// per post (not per point).
struct CommandWords {
  int count = 5;
  std::array<char, 5> letters{'X', 'Y', 'Z', 'A', 'B'};
  std::array<bool, 5> angle{false, false, false, true, true};
  int rotary_count = 2;  ///< how many words are angles (slots 3 and 4 on a serial machine)
  /// True for a serial chain (Machine, closed-form inverse): with_rotary() and the rotary-axis
  /// strategies of the post (branch changes, native arcs and cycles, cutter compensation) apply.
  bool serial = true;

  /// The words of a serial machine (X Y Z, then its rotary axes).
  static CommandWords of(const Machine& m) {
    CommandWords w;
    w.count = static_cast<int>(m.axes.size());
    for (int i = 0; i < w.count && i < 5; ++i) {
      w.letters[static_cast<std::size_t>(i)] = m.axes[static_cast<std::size_t>(i)].letter;
      w.angle[static_cast<std::size_t>(i)] = m.axes[static_cast<std::size_t>(i)].is_rotary();
    }
    w.rotary_count = m.rotary_count();
    return w;
  }
};

class MotionSolver {
 public:
  virtual ~MotionSolver() = default;
  /// Commands that put the tool on `cl`, nearest `previous` (continuity, limits); the solver
  /// records its figures of the point (solve_quiet + record).
  virtual IkOutcome solve(const ClPoint& cl, const AxisPosition& previous) const {
    SolveFigures figures;
    IkOutcome o = solve_quiet(cl, previous, &figures);
    record(figures);
    return o;
  }
  /// solve() without recording: the figures go to `figures` (if given). When `concurrent()`, it
  /// may run on another thread while the post calls anything else (the post's read-ahead).
  virtual IkOutcome solve_quiet(const ClPoint& cl, const AxisPosition& previous, SolveFigures* figures) const = 0;
  /// Records the figures of a solve_quiet() whose commands the post uses.
  virtual void record(const SolveFigures& /*figures*/) const {}
  /// True when solve_quiet() depends on nothing the post's progress changes (no reversal state).
  virtual bool concurrent() const { return false; }
  /// Commands for `cl` with the rotary angles given (programmed angles of G-code input).
  virtual AxisPosition with_rotary(const ClPoint& cl, const Eigen::Vector2d& rotary_rad) const = 0;
  /// Where the tool is at the commands q (tip and axis in W) on the machine the program is for.
  virtual ToolPoseT<double> execute(const AxisPosition& q) const = 0;
  virtual const Machine& machine() const = 0;
  /// The NC words of the commands (default: those of machine(), a serial chain).
  virtual CommandWords words() const { return CommandWords::of(machine()); }
  /// Called once a block to the commands q is written: machines with state (reversal) follow it.
  virtual void advance(const AxisPosition& /*q*/) const {}
  /// Before a feed block from `from` to `to`: commands that take up the reversal play of the axes
  /// whose direction reverses (the tool stands still), so that the block itself runs without lag;
  /// nullopt when there is nothing to take up (machines without reversal).
  virtual std::optional<AxisPosition> take_up(const AxisPosition& /*from*/, const AxisPosition& /*to*/) const {
    return std::nullopt;
  }
  /// The tool tip (W) an RTCP program writes for `cl` solved as q (the control inverts it nominally).
  virtual Vec3d programmed_tip(const ClPoint& cl, const AxisPosition& /*q*/) const { return cl.tip_mm; }
};

/// The nominal machine.
class NominalSolver final : public MotionSolver {
 public:
  NominalSolver(const Machine& machine, const Setup& setup) : machine_(machine), setup_(setup) {}
  IkOutcome solve_quiet(const ClPoint& cl, const AxisPosition& previous, SolveFigures*) const override {
    return ncpost::solve(machine_, cl, setup_, previous);
  }
  bool concurrent() const override { return true; }
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
