// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/trr_summary.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ncpost/report/html_page.hpp"

namespace ncpost::trr {
namespace {

/// Parameters in the summary (the page stays one sheet); the rest are in the full report.
constexpr std::size_t kParametersShown = 12;

/// µm or µrad per mm or rad, and the unit.
double unit_scale(int k) { return Errors::is_angle(k) ? 1e6 : 1e3; }
const char* unit_of(int k) { return Errors::is_angle(k) ? "µrad" : "µm"; }

/// A file's `# key:` value, or `missing`.
std::string key_or(const ProbingData& d, const std::string& key, const std::string& missing) {
  const auto it = d.metadata.find(key);
  return it == d.metadata.end() || it->second.empty() ? missing : it->second;
}

/// One file's conditions in words, from its `#` keys (docs/formats.md "Measurement conditions").
std::string conditions_of(const ProbingData& d) {
  const std::string t = key_or(d, "temperature", "");
  const std::string serial = key_or(d, "serial", "");
  return fmt::format("measured {}; {}; instrument {}{}; operator {}; {} probed points",
                     key_or(d, "date", "(date not given)"), t.empty() ? "temperature not given" : t + " °C",
                     key_or(d, "instrument", "not given"), serial.empty() ? "" : " (serial " + serial + ")",
                     key_or(d, "operator", "not given"), d.rows.size());
}

std::string residual_text(const IdentifyResult& r) {
  return fmt::format("machine without errors {:.2f} / {:.2f} µm; with the model {:.3f} / {:.3f} µm", r.rms_before_um,
                     r.max_before_um, r.rms_after_um, r.max_after_um);
}

/// "0.125 dzs_a − 0.991 dzs_b": one direction the data cannot see.
std::string direction_text(const std::vector<std::pair<std::string, double>>& direction) {
  std::string s;
  for (const auto& [name, w] : direction)
    if (std::abs(w) >= 0.05) s += fmt::format("{}{:.3f} {}", s.empty() ? "" : " + ", w, name);
  return s.empty() ? "(no weight above 0.05)" : s;
}

}  // namespace

comp::IdentificationSummary trr_identification_summary(const Machine& m, const IdentifyResult& r,
                                                       const TrrReportInputs& in) {
  comp::IdentificationSummary s;
  s.title = "Identification of " + m.name + " (TRR-XY, sphere probing)";
  s.facts.push_back({"machine", m.name});
  if (!in.model_file.empty()) s.facts.push_back({"model written", report::base_name(in.model_file)});
  s.facts.push_back({"identifiability", fmt::format("rank {} of {} parameters ({} iterations)", r.identifiability.rank,
                                                    r.identifiability.parameters, r.iterations)});
  s.facts.push_back({"residual (rms / max)", residual_text(r)});
  if (!in.machine_file.empty()) s.inputs.push_back({"machine file", in.machine_file});
  for (std::size_t i = 0; i < in.data_files.size(); ++i) {
    s.inputs.push_back({"data", in.data_files[i]});
    if (i < in.data.size())
      s.conditions.push_back(report::base_name(in.data_files[i]) + ": " + conditions_of(in.data[i]));
  }
  // the determined parameters, largest against their U first
  std::vector<int> order;
  for (int k = 0; k < kParameterCount; ++k)
    if (r.uncertainty.size() > static_cast<std::size_t>(k) && r.uncertainty[static_cast<std::size_t>(k)] > 0.0)
      order.push_back(k);
  auto ratio = [&](int k) { return std::abs(r.errors[k]) / r.uncertainty[static_cast<std::size_t>(k)]; };
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return ratio(a) > ratio(b); });
  for (std::size_t i = 0; i < order.size() && i < kParametersShown; ++i) {
    const int k = order[i];
    s.figures.push_back({"parameter " + Errors::name(k),
                         fmt::format("{:.3f} ± {:.3f} {}", r.errors[k] * unit_scale(k),
                                     2.0 * r.uncertainty[static_cast<std::size_t>(k)] * unit_scale(k), unit_of(k)),
                         "", ""});
  }
  if (order.size() > kParametersShown)
    s.warnings.push_back(
        fmt::format("{} further determined parameters in the full report", order.size() - kParametersShown));
  const int undetermined = kParameterCount - static_cast<int>(order.size());
  if (undetermined > 0)
    s.warnings.push_back(
        fmt::format("{} parameters not determined by these data (a share in a direction they cannot "
                    "see: minimum-norm values, no uncertainty); those directions:",
                    undetermined));
  for (const auto& d : r.identifiability.null_space) s.warnings.push_back("not seen: " + direction_text(d));
  s.full_report = in.report_path;
  return s;
}

std::string trr_identify_report_html(const Machine& m, const IdentifyResult& r, const TrrReportInputs& in) {
  report::Provenance p;
  p.title = "Identification of " + m.name + " (TRR-XY, sphere probing)";
  p.machine = m.name;
  p.model = in.model_file;
  if (!in.machine_file.empty()) p.inputs.push_back({"machine", in.machine_file});
  for (const auto& f : in.data_files) p.inputs.push_back({"measurement", f});
  std::string h = report::page_start(p);
  h += fmt::format("<p>Residual (rms / max): {}. Rank {} of {}.</p>", report::escape(residual_text(r)),
                   r.identifiability.rank, r.identifiability.parameters);
  h += "<h2>Conditions</h2><ul>";
  for (std::size_t i = 0; i < in.data_files.size() && i < in.data.size(); ++i)
    h += "<li>" + report::escape(report::base_name(in.data_files[i]) + ": " + conditions_of(in.data[i])) + "</li>";
  h += "</ul><h2>Parameters</h2><table><tr><th class=n>parameter</th><th>value</th><th>u</th><th>U (k = 2)</th>"
       "<th class=n>unit</th></tr>";
  for (int k = 0; k < kParameterCount; ++k) {
    const double u =
        r.uncertainty.size() > static_cast<std::size_t>(k) ? r.uncertainty[static_cast<std::size_t>(k)] : -1.0;
    if (u < 0.0)
      h += fmt::format(
          "<tr><td class=n>{}</td><td>{:.3f}</td><td colspan=\"2\">not determined (a share in the null "
          "space: minimum-norm value)</td><td class=n>{}</td></tr>",
          Errors::name(k), r.errors[k] * unit_scale(k), unit_of(k));
    else
      h += fmt::format("<tr><td class=n>{}</td><td>{:.3f}</td><td>{:.3f}</td><td>{:.3f}</td><td class=n>{}</td></tr>",
                       Errors::name(k), r.errors[k] * unit_scale(k), u * unit_scale(k), 2.0 * u * unit_scale(k),
                       unit_of(k));
  }
  h += "</table><h2>What the data cannot see</h2><ul>";
  for (const auto& d : r.identifiability.null_space) h += "<li>" + report::escape(direction_text(d)) + "</li>";
  if (r.identifiability.null_space.empty()) h += "<li>nothing: every parameter is determined</li>";
  return h + "</ul>" + report::page_end();
}

}  // namespace ncpost::trr
