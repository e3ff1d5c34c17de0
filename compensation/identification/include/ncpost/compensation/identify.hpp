// SPDX-License-Identifier: Apache-2.0
#pragma once
// Identification of error parameters from measurements (docs/cli.md `identify`; seeds 000, 002):
// nonlinear least squares (the fitting core, fit/damped_least_squares.hpp: Gauss–Newton steps,
// damped by Levenberg–Marquardt when one fails to decrease the cost) on the residuals of
// residuals.hpp, Jacobians by automatic differentiation through the templated chain.
//
// 1. The Jacobian at the prior values (0 unless `fixed` gives one) is analysed for
//    identifiability (fit/rank.hpp); parameters the data cannot separate are pinned at
//    their prior value and reported with their null-space direction — no invented values.
// 2. The kept parameters are fitted; the rank is checked again at the solution.
// 3. Uncertainty: standard deviations from s²·(JᵀJ)⁻¹ of the kept parameters, s² the residual
//    variance (Σr²/(m − n)); with a robust loss the weighted (IRLS) matrices are used; with set
//    weights (noise differing between sets), r and J are the weighted ones.
// Units: parameters mm / rad, residuals mm (reports in µm / µrad).
#include <optional>
#include <string>
#include <vector>

#include "ncpost/compensation/error_parameters.hpp"
#include "ncpost/compensation/fit/rank.hpp"
#include "ncpost/compensation/fit/robust_loss.hpp"
#include "ncpost/compensation/measurement.hpp"
#include "ncpost/compensation/model_json.hpp"

namespace ncpost::comp {

struct IdentifyOptions {
  Loss loss = Loss::squared;
  double loss_scale_um = 3.0;  ///< where the robust loss leaves the quadratic (µm)
  int max_iterations = 100;
  double rank_tolerance = 1e-3;  ///< fit/rank.hpp
  ErrorParameters fixed;         ///< known values (e.g. measured separately): held, not fitted
  /// Weighted least squares: one weight per measurement set (1/σ of its noise, any common
  /// scale); empty = all equal. Residual statistics stay unweighted (µm).
  std::vector<double> set_weights;
  /// Where the fit of each named parameter starts (e.g. a previous fit of a model it extends);
  /// others start at their prior. The prior (0 or `fixed`) stays what the rank analysis and a
  /// pinned parameter use: only the path to the minimum changes, not the minimum.
  ErrorParameters start;

  /// Empty if valid, else what is wrong.
  std::string validate() const;
};

/// Statistics of the residual of one measurement file (µm).
struct FileResidual {
  std::string file;
  MeasurementType type = MeasurementType::ballbar;
  std::size_t values = 0;
  double rms_nominal_um = 0.0, max_nominal_um = 0.0;  ///< no errors (prior values)
  double rms_after_um = 0.0, max_after_um = 0.0;      ///< identified model
};

struct IdentifyResult {
  bool converged = false;
  std::string message;
  int iterations = 0;
  std::vector<std::string> candidates;  ///< the parameters asked for, priority order
  ErrorParameters parameters;           ///< fitted values of the kept parameters (+ fixed ones)
  ErrorParameters uncertainty;          ///< standard deviations of the fitted ones
  Eigen::MatrixXd covariance;           ///< of the fitted ones, in the order of `uncertainty`
  Identifiability identifiability;
  RankAnalysis rank;  ///< at the solution, columns = candidates
  std::vector<FileResidual> files;
  double rms_nominal_um = 0.0, max_nominal_um = 0.0, rms_after_um = 0.0, max_after_um = 0.0;
  std::vector<std::vector<double>> fitted;   ///< predictions of every set by the identified model
  std::vector<std::vector<double>> nominal;  ///< predictions by the prior model
};

/// The basic model: location errors of every rotary axis (offsets and tilts perpendicular to
/// the axis first, zero-position errors last: in a coupling the zero error is the one pinned).
std::vector<std::string> basic_parameters(const Machine& machine);

/// Identifies `candidates` from the sets. Throws std::invalid_argument for a bad name.
IdentifyResult identify(const Machine& machine, const std::vector<MeasurementSet>& sets,
                        const std::vector<std::string>& candidates, const IdentifyOptions& options = {});

/// The model file of a result (parameters, uncertainty, identifiability, fit).
ModelFile to_model_file(const Machine& machine, const IdentifyResult& result);

}  // namespace ncpost::comp
