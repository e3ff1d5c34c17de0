// SPDX-License-Identifier: Apache-2.0
#pragma once
// Residual analysis (issue 6, docs/cli.md `identify`): fit the basic model, then add by forward
// selection the named effects (diagnose_candidates.hpp) the residual asks for, refit, and report
// before and after.
//
// One step:
//  1. Screening (linearised, cheap): the exact Jacobian (residuals.hpp, automatic
//     differentiation) of every candidate's parameters at the current solution is projected off
//     the span of the current model's fitted parameters. A column whose remaining part is below
//     `alias_tolerance` of itself (the sine of its angle to that span, as fit/rank.hpp)
//     is aliased: the candidate is not identifiable together with the model and is skipped. The
//     residual's projection on the remaining part is the drop in the sum of squares Σr² the
//     candidate would buy (exact for a linear model). Drift: lin, exp or both, the time
//     constant from a log-spaced grid (30 s … 4 × the data's time span) by that drop
//     (diagnose_screening.hpp). Candidates that add the same directions (within 10 ×
//     `alias_tolerance`) cannot be told apart by the data: they form one class, named by the
//     first in catalogue order, the others reported as `equivalent`.
//  2. Evidence: the best few by screened drop are refitted (identify.hpp, from scratch, with the
//     existing rank analysis), and each gets the partial F statistic
//        F = ((S0 − S1) / k) / (S1 / (m − p1))
//     S0, S1 the sums of squares before and after, k its parameters, p1 the fitted parameters,
//     m the values. The noise level is the one the data show (S1 / (m − p1)). A candidate is
//     accepted only if its p-value is below `significance` / (number of candidates tested)
//     (Bonferroni: the family-wise false-positive rate of a step stays below `significance`), if
//     the refit pins none of its parameters and none of the model's (rank check), and if its
//     size is physically plausible (diagnose_effect_size.hpp). The accepted one with the smallest
//     Bayesian information criterion m·ln(S1/m) + p1·ln(m) is added (for equal parameter counts
//     the smallest S1; it weighs a table's many nodes against a compact form's few).
//  3. After each addition the time constant of every drift in the model is chosen again by
//     refits (tau·2^(j/2), j = −2..2, moved on while the best is at an end, refined by a
//     parabola): the effects added later change it.
//     Repeat until no candidate is accepted or `max_effects` are in.
//  4. Sets differ in noise (a touch probe is noisier than a ballbar): the final model is refitted
//     by weighted least squares, each set weighted by 1/σ with σ its residual rms under the final
//     model (`weight_by_set_noise`); the basic model's fit stays as it was (the "before").
// Units: parameters mm / rad / s, residual statistics µm.
#include <functional>
#include <string>
#include <vector>

#include "ncpost/compensation/diagnose_candidates.hpp"
#include "ncpost/compensation/diagnose_effect_size.hpp"
#include "ncpost/compensation/diagnose_signature.hpp"
#include "ncpost/compensation/diagnose_structure.hpp"
#include "ncpost/compensation/identify.hpp"

namespace ncpost::comp {

struct DiagnoseOptions {
  IdentifyOptions identify;    ///< for every fit (loss, fixed values, rank tolerance)
  double significance = 1e-3;  ///< family-wise false-positive rate of one step
  int max_effects = 8;
  int refit_top = 3;                                 ///< candidates refitted per step (by screened drop)
  double alias_tolerance = 1e-3;                     ///< fit/rank.hpp's default
  PlausibleSizes plausible;                          ///< diagnose_effect_size.hpp
  bool weight_by_set_noise = true;                   ///< final refit weighted by each set's noise (see below)
  std::function<void(const std::string&)> progress;  ///< one line per step (optional)

  std::string validate() const;
};

/// An effect added to the model.
struct AddedEffect {
  Candidate candidate;
  std::vector<std::string> equivalent;  ///< effects the data cannot tell from it (same signature)
  ErrorParameters values;               ///< its fitted parameters (and held ones), mm / rad / s
  ErrorParameters uncertainty;          ///< 1σ of the fitted ones
  double size = 0.0;  ///< amplitude (harmonic √(cos² + sin²)), value, play, drift over the span (mm / rad)
  double size_sigma = 0.0;
  bool size_is_angle = false;
  double rms_before_um = 0.0, rms_after_um = 0.0, max_before_um = 0.0, max_after_um = 0.0;
  double f_statistic = 0.0;
  double bic = 0.0;  ///< m·ln(S1/m) + p1·ln(m) of the model with it (the choice among accepted ones)
  double p_value = 1.0;
  int tested = 0;  ///< candidates screened in its step
  /// Can the data tell it from the other fitted parameters (issue 17, e.g. EXC:h2 beside
  /// EAC:h2 / EBC:h2)? The sine of its columns to the span of all others in the final model
  /// (fit/rank.hpp's measure; 1 = independent, 0 = an alias), and the added effects
  /// whose columns correlate with its own above 0.9 (largest canonical correlation).
  double separation_sine = 1.0;
  std::vector<std::pair<std::string, double>> correlated;
  /// For a harmonic: how well the same order of the axis's other components not in the model
  /// (for EXC:h2 the tilts EAC:h2, EBC:h2, ...) reproduce its columns once the rest of the model is
  /// accounted for (the smallest canonical correlation: every direction of it); above 0.99 it is
  /// reported as an alias of them. `alias_of`: those that correlate with it above 0.5.
  double alias_correlation = 0.0;
  std::vector<std::string> alias_of;
  std::string separation;  ///< the verdict in words: "real: ..." or "an alias of ...: ..."
};

/// Why the best candidates of the last step were not added.
struct RejectedEffect {
  std::string effect;
  double rms_after_um = 0.0;
  double p_value = 1.0;
  std::string reason;
};

struct DiagnoseResult {
  IdentifyResult basic;                  ///< the basic model's fit
  IdentifyResult final_fit;              ///< with the added effects
  std::vector<std::string> final_names;  ///< fitted parameters of the final model, in order
  ErrorParameters held;                  ///< held parameters (drift tau) of the added effects
  std::vector<AddedEffect> added;
  std::vector<RejectedEffect> last_rejected;
  double noise_um = 0.0;             ///< noise estimated from the data (diagnose_signature.hpp)
  std::vector<double> set_noise_um;  ///< per set: residual rms of the final model (its weight 1/σ)
  ResidualSignature before, after;
  Eigen::VectorXd residual_before_mm, residual_after_mm;
  std::string stop_reason;
  /// Structure the final model leaves (diagnose_structure.hpp): what is not at the noise and no
  /// candidate explains, with its shape and the measurement that would resolve it.
  std::vector<ResidualStructure> unexplained;
  /// Effects the forward selection fitted but that are not attributed: with all of them in, the
  /// residual still had structure no candidate explains, and once that structure is absorbed they
  /// have no evidence of their own (diagnose_attribution.hpp); the model keeps the others.
  std::vector<std::string> not_attributed;

  std::vector<std::string> effects_added() const;
};

/// Runs the analysis starting from `basic_names` (the basic model plus any --params).
/// Throws std::invalid_argument for a bad name or invalid options.
DiagnoseResult diagnose(const Machine& machine, const std::vector<MeasurementSet>& sets,
                        const std::vector<std::string>& basic_names, const DiagnoseOptions& options = {});

/// The model file of the final model: parameters, uncertainty, identifiability, effects_added,
/// fit (before = basic model, after = final model) and, when structure is left that nothing
/// explains, `diagnosis.unexplained` (file, value, axis, shape, proposed measurement), with the
/// separation verdict of every added effect (`diagnosis.effects`).
ModelFile to_model_file(const Machine& machine, const DiagnoseResult& result);

}  // namespace ncpost::comp
