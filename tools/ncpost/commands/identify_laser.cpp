// SPDX-License-Identifier: Apache-2.0
#include "identify_laser.hpp"

#include <fmt/format.h>

#include "commands.hpp"
#include "ncpost/compensation/identify_summary.hpp"
#include "ncpost/compensation/laser_identify.hpp"
#include "ncpost/compensation/laser_report.hpp"
#include "ncpost/compensation/model_json.hpp"

namespace ncpost::cli {

IdentifyOutput identify_laser(const Machine& m, const std::vector<comp::MeasurementSet>& sets,
                              const std::string& report, bool options_ignored,
                              const comp::IdentifyReportInputs& report_inputs) {
  if (options_ignored)
    fmt::print(
        "notice: laser data: --params, --fixed and --loss do not apply (the model is the error tables of the measured "
        "axes, squareness and reversal)\n");
  const comp::LaserIdentifyResult r = comp::identify_laser(m, sets);
  fmt::print("{}", comp::laser_text_report(m, r));
  if (!r.ok) throw Infeasible("laser identification: " + r.message);
  IdentifyOutput out;
  out.model_json = comp::format_model_json(comp::laser_model_file(m, r));
  if (!report.empty()) {
    out.report_html = comp::laser_html_report(m, r, sets, report_inputs);
    out.summary_html = comp::summary_page_html(comp::laser_identification_summary(m, sets, r, report_inputs, report));
  }
  return out;
}

}  // namespace ncpost::cli
