// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/conditions_report.hpp"

#include <fmt/format.h>

#include "ncpost/compensation/thermal_correction.hpp"

namespace ncpost::comp {
namespace {

using report::escape;

std::string or_dash(const std::string& s) { return s.empty() ? "—" : s; }

std::string temperature_text(const MeasurementConditions& c) {
  return c.temperature_c ? fmt::format("{:g} °C", *c.temperature_c) : "not given";
}

std::string expansion_text(const MeasurementConditions& c) {
  return c.expansion_per_k ? fmt::format("{:g} /K", *c.expansion_per_k) : "not given";
}

}  // namespace

void add_condition_rows(report::Provenance& p, const IdentifyReportInputs& in,
                        const std::vector<MeasurementSet>& sets) {
  if (!in.machine_record.serial.empty()) p.extra.push_back({"machine serial", escape(in.machine_record.serial)});
  if (!in.machine_record.owner.empty()) p.extra.push_back({"machine owner", escape(in.machine_record.owner)});
  std::string dates;
  for (const auto& s : sets)
    dates += fmt::format("{}{}: {}", dates.empty() ? "" : "; ", report::base_name(s.file),
                         s.conditions.date.empty() ? "date not given" : s.conditions.date);
  if (!sets.empty()) p.extra.push_back({"measured", escape(dates)});
}

std::string correction_text(const MeasurementSet& s) {
  const MeasurementConditions& c = s.conditions;
  if (s.corrected_to_20c)
    return fmt::format("{} / {:.7f} = 1 + α (T − 20 °C); largest change {:.2f} µm",
                       s.type == MeasurementType::ballbar ? "L" : "laser length", c.expansion_factor(),
                       s.thermal_correction_max_um);
  if (!has_lengths_to_correct(s))
    return s.type == MeasurementType::sphere
               ? "none needed: the probe reads through the machine's own scales, which expand with it"
               : "none needed: a straightness line (a uniform expansion is zeroed with the run)";
  if (!c.temperature_c) return "not corrected: no temperature given";
  if (!c.expansion_per_k) return "not corrected: no material_expansion given";
  return "not corrected";
}

std::string conditions_html(const std::vector<MeasurementSet>& sets) {
  bool any = false;
  for (const auto& s : sets) any = any || s.conditions.any() || !s.notices.empty();
  if (!any)
    return "<p class=\"note\">The data files give no measurement conditions (temperature, expansion, instrument, "
           "operator, date: docs/formats.md \"Measurement conditions\"): lengths are taken as measured at 20 °C.</p>";
  std::string h =
      "<h2 id=\"conditions\">Measurement conditions</h2><p class=\"note\">From each data file's header "
      "(<code># temperature:</code> °C, <code># material_expansion:</code> 1/K, <code># instrument:</code>, "
      "<code># serial:</code>, <code># operator:</code>, <code># date:</code>). Lengths are corrected to the "
      "ISO 1 reference temperature 20 °C where the file gives both the temperature and the coefficient: "
      "ℓ<sub>20</sub> = ℓ<sub>T</sub> / (1 + α (T − 20 °C)) (docs/formats.md).</p>"
      "<table><tr><th class=n>file</th><th class=n>type</th><th class=n>date</th><th>temperature</th>"
      "<th>expansion α</th><th class=n>correction to 20 °C</th><th class=n>instrument</th><th class=n>serial</th>"
      "<th class=n>operator</th></tr>";
  for (const auto& s : sets) {
    const MeasurementConditions& c = s.conditions;
    h += fmt::format(
        "<tr><td class=n>{}</td><td class=n>{}</td><td class=n>{}</td><td>{}</td><td>{}</td><td class=n>{}</td>"
        "<td class=n>{}</td><td class=n>{}</td><td class=n>{}</td></tr>",
        escape(report::base_name(s.file)), to_string(s.type), escape(or_dash(c.date)), temperature_text(c),
        expansion_text(c), escape(correction_text(s)), escape(or_dash(c.instrument)), escape(or_dash(c.serial)),
        escape(or_dash(c.operator_name)));
  }
  h += "</table>";
  for (const auto& w : temperature_warnings(sets)) h += "<p class=\"fail\">Warning: " + escape(w) + "</p>";
  std::string notices;
  for (const auto& s : sets)
    for (const auto& n : s.notices) notices += "<li>" + escape(n) + "</li>";
  if (!notices.empty()) h += "<p class=\"note\">Notices of the file reader:</p><ul class=\"note\">" + notices + "</ul>";
  return h;
}

std::string conditions_text(const std::vector<MeasurementSet>& sets) {
  std::string o =
      "measurement conditions (lengths corrected to 20 °C where temperature and material_expansion are given):\n";
  for (const auto& s : sets) {
    const MeasurementConditions& c = s.conditions;
    o += fmt::format("  {:<24} {}; {}; α {}; {}", report::base_name(s.file), or_dash(c.date), temperature_text(c),
                     expansion_text(c), correction_text(s));
    if (!c.instrument.empty() || !c.serial.empty())
      o += fmt::format("; instrument {} {}", or_dash(c.instrument), c.serial);
    if (!c.operator_name.empty()) o += "; operator " + c.operator_name;
    o += "\n";
  }
  for (const auto& w : temperature_warnings(sets)) o += "  WARNING: " + w + "\n";
  return o;
}

}  // namespace ncpost::comp
