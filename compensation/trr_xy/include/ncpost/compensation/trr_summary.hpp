// SPDX-License-Identifier: Apache-2.0
#pragma once
// The report of a TRR-XY identification from sphere probing (trr_identify.hpp) and its one-page
// summary (summary_page.hpp, issue 25 item 5), as `identify --report R.html` writes them (R.html
// and R-summary.html), like the serial machines' ones:
//   full report  the inputs with SHA-256, the probed points, the residual before and after, every
//                one of the 30 parameters with its standard uncertainty u and U = 2u (µm, µrad) or
//                "not determined" (a share in the null space: minimum-norm value, no u), and the
//                directions the data cannot see;
//   summary      machine, inputs, the conditions each data file states (`# date:`, `# temperature:`,
//                `# instrument:`, `# serial:`, `# operator:`), the residual, the 12 determined
//                parameters largest against their U (value ± U), the rest and the null space as limits,
//                and the signature block.
#include <string>
#include <vector>

#include "ncpost/compensation/summary_page.hpp"
#include "ncpost/compensation/trr_identify.hpp"
#include "ncpost/compensation/trr_probing_csv.hpp"

namespace ncpost::trr {

/// Where the inputs came from and where the outputs go (paths as given; the pages hash the inputs).
struct TrrReportInputs {
  std::string machine_file, model_file, report_path;
  std::vector<std::string> data_files;
  std::vector<ProbingData> data;  ///< the same order (their `#` keys give the conditions)
};

comp::IdentificationSummary trr_identification_summary(const Machine& machine, const IdentifyResult& result,
                                                       const TrrReportInputs& inputs);

std::string trr_identify_report_html(const Machine& machine, const IdentifyResult& result,
                                     const TrrReportInputs& inputs);

}  // namespace ncpost::trr
