// SPDX-License-Identifier: Apache-2.0
#pragma once
// The per-thread working data of a kinematic model (kinematic_model.hpp), after the Model/Data
// split of Pinocchio: the model is immutable, and everything that changes while a program is
// posted (where the axes stand, the last solution's error, the figures) is here, owned by the
// caller and passed explicitly. Units: mm, rad; poses in W.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>

#include "ncpost/kinematics/machine.hpp"
#include "ncpost/kinematics/pose.hpp"

namespace ncpost {

/// What solving one CL point measured, recorded by the caller in its SolverData (ActualSolver: the
/// tip error of the uncompensated commands and the residual of the compensated ones, mm; < 0: none).
struct SolveFigures {
  double uncompensated_tip_mm = -1.0;
  double residual_mm = -1.0;
};

/// Largest and RMS of a stream of errors (mm).
struct ErrorStats {
  double max_mm = 0.0;
  double sum_sq_mm2 = 0.0;
  std::size_t count = 0;
  void add(double e_mm) {
    max_mm = std::max(max_mm, e_mm);
    sum_sq_mm2 += e_mm * e_mm;
    ++count;
  }
  /// Adds the errors of another stream (a worker's figures merged by its caller).
  void merge(const ErrorStats& other) {
    max_mm = std::max(max_mm, other.max_mm);
    sum_sq_mm2 += other.sum_sq_mm2;
    count += other.count;
  }
  double rms_mm() const { return count ? std::sqrt(sum_sq_mm2 / static_cast<double>(count)) : 0.0; }
};

/// The working data of a kinematic model: everything that changes while a program is posted, owned by the
/// caller and passed explicitly (the solver itself is immutable). One per thread: the post owns one,
/// each read-ahead worker its own. Solvers without state leave it untouched.
struct SolverData {
  /// Where the axes stand after the emitted program (models with reversal; nullopt before any block).
  std::optional<AxisPosition> stands;
  /// The same on the machine the program is re-executed on (ExecutedOn, `--verify-on`).
  std::optional<AxisPosition> executing_stands;
  /// Cache: the machine error (actual − nominal tip and axis, W) at the last solution on this
  /// thread, the prediction for the next CL point; `owner` is the solver it belongs to.
  struct LastError {
    const void* owner = nullptr;
    AxisPosition q;
    ToolPoseT<double> error;
  } last_error;
  /// Figures of the CL points whose commands were used (record()).
  ErrorStats uncompensated;      ///< tip error of the uncompensated commands (mm)
  double max_residual_mm = 0.0;  ///< largest remaining tip error of the compensated IK (mm)

  /// Records the figures of a solve whose commands the post uses.
  void record(const SolveFigures& figures) {
    if (figures.uncompensated_tip_mm >= 0.0) uncompensated.add(figures.uncompensated_tip_mm);
    if (figures.residual_mm >= 0.0) max_residual_mm = std::max(max_residual_mm, figures.residual_mm);
  }
  /// Adds another data object's figures (a worker's, merged by the caller).
  void merge_figures(const SolverData& other) {
    uncompensated.merge(other.uncompensated);
    max_residual_mm = std::max(max_residual_mm, other.max_residual_mm);
  }
};

}  // namespace ncpost
