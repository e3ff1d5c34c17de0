// SPDX-License-Identifier: Apache-2.0
#pragma once
// Before and after as two (or more) measurements (issue 25 item 5; docs/cli.md `compare`): the same
// test in every session, figure by figure with U (k = 2), the ISO 14253-1 verdict of each figure
// that has a tolerance, and the change from the first session to the last.
//
// The change Δ = v_last − v_first of two independent sessions has U_Δ = √(U_first² + U_last²)
// (uncorrelated, ISO 230-9 / GUM). It is called proven only when |Δ| > U_Δ; "better" is closer to 0
// (|v_last| < |v_first|), as every ISO 230 figure is one-sided and a parameter is an error.
// A session whose figures lack a U cannot prove a change: "not proven (no U)".
//
// Dates: with every session dated (`# date:`), the trend runs over the days since the first; a
// session dated before the one given ahead of it is refused (the order is what "before" and
// "after" mean). Without dates the trend runs over the session number, and the report says so.
#include <optional>
#include <string>
#include <vector>

#include "ncpost/compensation/compare_session.hpp"
#include "ncpost/compensation/decision_rule.hpp"

namespace ncpost::comp {

/// One figure over the sessions (a figure a session lacks, e.g. G cw of a one-way run: nullopt).
struct FigureTrend {
  std::string name, kind, unit;
  std::vector<std::optional<double>> value;     ///< per session
  std::vector<double> expanded;                 ///< U per session (0: none)
  std::vector<std::optional<Verdict>> verdict;  ///< per session, with a tolerance and a U
  std::optional<double> tolerance;
  /// First and last session that have the figure; the change between them and its U.
  int first = -1, last = -1;
  double change = 0.0, change_U = 0.0;
  std::string outcome;  ///< "better (proven)", "worse (proven)", "no change proven", "not proven (no U)", ""
};

struct Comparison {
  std::vector<Session> sessions;
  std::vector<FigureTrend> figures;
  bool dated = false;       ///< every session has a date
  std::vector<double> day;  ///< per session: days since the first (dated), else 1, 2, 3, …
};

/// Days since 1970-01-01 of an ISO 8601 date as the files use it (measurement_conditions.hpp:
/// YYYY-MM-DD, optionally THH:MM[:SS] and Z or ±HH:MM; the offset is taken out), or nullopt.
std::optional<double> days_since_epoch(const std::string& iso_date);

/// The comparison of at least two sessions of one test; InputError naming the file when a session's
/// test differs from the first one's or its date precedes the one before it.
Comparison compare_sessions(const std::vector<Session>& sessions, const Tolerances& tolerances);

/// A figure's text outcome for Δ ± U_Δ (the rule above).
std::string change_outcome(double first, double last, double change_U);

}  // namespace ncpost::comp
