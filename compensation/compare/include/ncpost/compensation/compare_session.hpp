// SPDX-License-Identifier: Apache-2.0
#pragma once
// One session of a before/after comparison (issue 25 item 5; docs/cli.md `compare`): the figures
// one measurement file or one identified model gives, each with its expanded uncertainty U (k = 2)
// where the data give one, the session's date (`# date:` of a data file) and a description of the
// test that must be the same in every session compared.
//
//   ballbar file     ISO 230-4 G of the whole path, G of each direction where the file runs both
//                    (`G ccw`, `G cw`) and the circular hysteresis H (report/circularity.hpp); U from
//                    circularity_budget (uncertainty_budget.hpp; H takes G's budget: a difference of
//                    two readings at one length)
//   laser file       ISO 230-2 A, B, E, M, R of a bidirectional positioning line (laser_iso230_2.hpp),
//                    U from iso230_2_budget
//   model (JSON)     every identified parameter in µm or µrad, U = 2 u from the fit's standard
//                    uncertainty; the residual of the machine without errors (rms, max), no U
// Values in µm (lengths) or µrad (angles).
#include <optional>
#include <string>
#include <vector>

#include "ncpost/compensation/measurement.hpp"
#include "ncpost/compensation/model_json.hpp"
#include "ncpost/compensation/uncertainty_budget.hpp"

namespace ncpost::comp {

struct SessionFigure {
  std::string name;  ///< "G", "G ccw", "H", "A", …, or a parameter name ("EY0A")
  std::string kind;  ///< the tolerance kind it is judged by (decision_rule.hpp), "" for none
  std::string unit;  ///< "µm" or "µrad"
  double value = 0.0;
  std::optional<UncertaintyBudget> budget;  ///< none: the data give no uncertainty for it
  /// U (k = 2), 0 without a budget.
  double expanded() const { return budget ? budget->expanded_um() : 0.0; }
};

struct Session {
  std::string file;
  std::string date;  ///< as written in `# date:`, "" when the file gives none
  std::string test;  ///< what was measured and how; sessions compared must agree on it
  std::vector<SessionFigure> figures;
};

/// The figures of a ballbar file or of a laser positioning file; InputError naming the file for a
/// sphere file, a laser straightness line, or a set the figures cannot be computed from.
Session session_from_set(const Machine& machine, const MeasurementSet& set);

/// The parameters and the fit residual of an identified model read for `machine`.
Session session_from_model(const Machine& machine, const ModelFile& model, const std::string& file);

}  // namespace ncpost::comp
