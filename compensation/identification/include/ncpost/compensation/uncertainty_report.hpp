// SPDX-License-Identifier: Apache-2.0
#pragma once
// The uncertainty budgets and the ISO 14253-1 verdicts in the HTML reports (issue 25 item 4):
// a figure as "v ± U", its verdict against a tolerance (decision_rule.hpp), and its budget as a
// table (uncertainty_budget.hpp). Shared by the identification, diagnosis and laser reports.
#include <optional>
#include <string>

#include "ncpost/compensation/decision_rule.hpp"
#include "ncpost/compensation/uncertainty_budget.hpp"

namespace ncpost::comp {

/// "12.34 ± 0.71" (µm, U with k = 2), with "(U lacks instrument)" when the budget is incomplete.
std::string value_with_U(double value_um, const UncertaintyBudget& budget);

/// A table cell with the verdict of `value_um` ± U against `tolerance_um` ("" without a tolerance).
std::string verdict_cell(double value_um, const UncertaintyBudget& budget, std::optional<double> tolerance_um);

/// The budget as a small table: source, u (µm), note; then u_c and U (k = 2).
std::string budget_table_html(const std::string& figure, const UncertaintyBudget& budget);

/// The paragraph that states the decision rule (once per report).
std::string decision_rule_note_html();

}  // namespace ncpost::comp
