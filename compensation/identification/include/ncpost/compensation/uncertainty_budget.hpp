// SPDX-License-Identifier: Apache-2.0
#pragma once
// Expanded uncertainty (k = 2) of the reported figures with their budgets (issue 25 item 4;
// ISO 230-9 in its simplest form: uncorrelated contributions added in quadrature,
// u_c = √Σ u_i², U = 2 u_c). Contributions, standard uncertainties in µm:
//   instrument     from the file's `# instrument_uncertainty:` U_i (k = 2) of one reading: u = U_i / 2
//                  per reading; a figure that is the difference of two readings (G, A, E, M, B)
//                  takes √2 u; R (a spread of readings) none.
//   temperature    the 20 °C correction's own uncertainty over the length ℓ the figure spans
//                  (the bar length, a laser line's travel): u = 1000 ℓ √((ΔT u_α)² + (α u_T)²) µm
//                  (ℓ in mm, ΔT = T − 20 °C, u_T and u_α from `# temperature_uncertainty:` and
//                  `# expansion_uncertainty:`); G, B and R are differences at one length: none.
//   repeatability  where repeats exist: ISO 230-2 means over n runs, u = √2 s_max / √n (E, M, B, A),
//                  R from the estimated s, u = R / √(2 (n − 1)); a ballbar test repeated in several
//                  files: the standard deviation of their G.
//   fit            an identified parameter: its standard uncertainty from the fit (identify.hpp),
//                  which holds the random part of the instrument and the repeatability as far as
//                  the residual shows them.
// A contribution the data do not give is listed as missing (the budget is then incomplete and
// says so), never silently taken as 0.
#include <string>
#include <vector>

#include "ncpost/compensation/laser_iso230_2.hpp"
#include "ncpost/compensation/measurement.hpp"

namespace ncpost::comp {

struct BudgetLine {
  std::string source;  ///< "instrument", "temperature", "repeatability", "fit"
  double u_um = 0.0;   ///< standard uncertainty
  std::string note;    ///< where it comes from, or why it is 0 or missing
  bool given = true;   ///< false: the data do not give it (not included)
};

struct UncertaintyBudget {
  std::vector<BudgetLine> lines;
  double combined_um() const;                                 ///< √Σ u²
  double expanded_um() const { return 2.0 * combined_um(); }  ///< U, k = 2
  bool complete() const;
  /// The sources not given, "instrument, temperature"; empty when complete.
  std::string missing() const;
};

/// One reading's deviation (the verdict on the largest deviation of a file): instrument u and the
/// temperature correction over the set's length.
UncertaintyBudget reading_budget(const MeasurementSet& set);

/// ISO 230-4 circular deviation G of a ballbar file; `repeat_G_um`: G of every file of the same
/// test (this one included), empty or one value when it was not repeated.
UncertaintyBudget circularity_budget(const MeasurementSet& set, const std::vector<double>& repeat_G_um);

/// ISO 230-2 figure `figure` (A, B, E, M or R) of a positioning line.
UncertaintyBudget iso230_2_budget(const MeasurementSet& set, const Iso230Figures& figures, char figure);

/// The length (mm) the temperature contribution acts over: the bar length of a ballbar, the span
/// of the moving axis of a laser line, 0 for sphere probing.
double budget_length_mm(const MeasurementSet& set);

}  // namespace ncpost::comp
