// SPDX-License-Identifier: Apache-2.0
#pragma once
// The one-page summary of an identification (issue 25 item 5), written beside the full report
// (`identify --report R.html` also writes R-summary.html): the machine (name, serial, owner), the
// inputs with their SHA-256, the measurement conditions, the key figures with their expanded
// uncertainty U (k = 2) and ISO 14253-1 verdicts, the warnings, and a signature block (measured,
// evaluated, approved: name, date, signature). Self-contained HTML; print CSS sets an A4 page with
// the signature block kept whole, so that the page prints as one sheet.
#include <string>
#include <utility>
#include <vector>

namespace ncpost::comp {

struct SummaryFigure {
  std::string what;     ///< "ballbar_h250.csv: G (ISO 230-4)"
  std::string value;    ///< "19.03 ± 0.71 µm"
  std::string verdict;  ///< "PASS", "FAIL", "NOT PROVEN", or "" (no tolerance)
  std::string against;  ///< the tolerance, "G ≤ 10 µm", or ""
};

struct IdentificationSummary {
  std::string title;                                        ///< "Identification of ac-trunnion"
  std::vector<std::pair<std::string, std::string>> facts;   ///< machine, serial, owner, model, dates (text)
  std::vector<std::pair<std::string, std::string>> inputs;  ///< role, path (hashed when the page is made)
  std::vector<std::string> conditions;                      ///< one line per data file
  std::vector<SummaryFigure> figures;
  std::vector<std::string> warnings;  ///< what limits the figures (unseen errors, ...)
  std::string full_report;            ///< the full report's file name (linked)
};

std::string summary_page_html(const IdentificationSummary& summary);

/// Where the summary of the report `report_path` goes: "out/id.html" → "out/id-summary.html".
std::string summary_path(const std::string& report_path);

}  // namespace ncpost::comp
