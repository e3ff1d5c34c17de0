// SPDX-License-Identifier: Apache-2.0
#pragma once
// Identification of the TRR-XY error parameters (docs/trr-xy.md, 30 parameters) from simulated
// sphere probing (docs/conventions.md "Measurements", sphere): at each probing pose (slider commands;
// the XY table is error free, so its commands do not matter) a probe of stylus length L — the
// probed point is fixed to the tool at (0, 0, −L) from the TCP at home, i.e. L mm further along
// −axis — reads the sphere centre deviation (dx, dy, dz) = −(P_true − P_nominal) in M (mm).
// Two stylus lengths make the tool orientation visible.
//
// The fit (the fitting core, fit/damped_least_squares.hpp): Gauss–Newton first (damped only when
// a step fails) with the Jacobian by central differences (0.01 mm, 1e-5 rad), columns
// scaled to unit norm; the step is the truncated-SVD (minimum norm) solution, so the directions
// the data cannot see stay at zero and are reported as the null space (singular values below
// `rank_tolerance` × the largest; null-space weights are in the column-scaled parameters, i.e.
// per unit of effect on the data, so that lengths and angles compare). Reference: Ceres covariance.h on rank-deficient
// Jacobians.
#include <vector>

#include "ncpost/compensation/model_json.hpp"
#include "ncpost/kinematics/trr_xy_inverse.hpp"

namespace ncpost::trr {

struct ProbeMeasurement {
  Vec3d slider_mm = Vec3d::Zero();
  double stylus_mm = 0.0;              ///< L
  Vec3d deviation_mm = Vec3d::Zero();  ///< sphere centre deviation (dx, dy, dz)
};

/// Probing poses: tool axes tilted 0, 10, 20, 30° toward 12 azimuths at three TCP heights
/// (−170, −260 and −350 mm in M), solved by the nominal inverse kinematics (unreachable ones left out).
std::vector<Vec3d> probing_poses(const Machine& m);
/// The same poses as full commands (the table centres the probed point over the origin of M).
std::vector<Command> probing_commands(const Machine& m);

/// The predicted deviation of one measurement on the machine `k` (see the header comment).
std::optional<Vec3d> predicted_deviation(const Kinematics& k, const Kinematics& nominal, const Vec3d& slider_mm,
                                         double stylus_mm);

/// Simulated data on the machine `truth`, with Gaussian noise (µm, per component).
std::vector<ProbeMeasurement> simulate_probing(const Kinematics& truth, const std::vector<Vec3d>& poses,
                                               const std::vector<double>& styli_mm, double noise_um, unsigned seed);

struct IdentifyOptions {
  int max_iterations = 10;
  double rank_tolerance = 1e-6;  ///< relative singular value under which a direction is not seen
};

struct IdentifyResult {
  Errors errors;
  comp::Identifiability identifiability;
  std::vector<double> singular_values;  ///< of the column-scaled Jacobian, largest first
  /// Standard deviation of each parameter (mm or rad) from the residual through the directions
  /// the data see (at the last iterate); −1 for a parameter with a share in the null space.
  std::vector<double> uncertainty;
  double rms_before_um = 0, max_before_um = 0;  ///< residual of the nominal machine
  double rms_after_um = 0, max_after_um = 0;    ///< residual of the fitted model
  int iterations = 0;
};

IdentifyResult identify(const Machine& m, const std::vector<ProbeMeasurement>& data, const IdentifyOptions& o = {});

}  // namespace ncpost::trr
