// SPDX-License-Identifier: Apache-2.0
// The compensation values of the identified model in the chosen control's own entries (`identify
// --control FORMAT`, control_entries.hpp): the lines `ncpost export` writes, per file, so that a user
// can type them in; what the format cannot hold; how to get the other formats.
#include <fmt/format.h>

#include <stdexcept>

#include "ncpost/compensation/identify_report.hpp"
#include "ncpost/report/html_page.hpp"

namespace ncpost::comp {

std::string control_entries_html(const Machine& m, const ErrorParameters& parameters, ControlFormat format) {
  using report::escape;
  const ControlFormatInfo& info = control_format_info(format);
  std::string h = fmt::format(
      "<h3 id=\"control-entries\">As entered in the control: {}</h3><p class=\"note\">{}. "
      "The lines below are those <code>ncpost export</code> writes from the model file (the "
      "file adds notes: source, sign convention, what it cannot hold). Other controls: "
      "<code>identify --control FORMAT</code> ({}), or <code>ncpost export --format "
      "FORMAT</code>.</p>",
      escape(info.title), escape(info.where), escape(control_format_names()));
  ControlEntries entries;
  try {
    const MachineModel model(m, parameters);
    entries = control_entries(model, format);
  } catch (const std::exception& e) {
    return h + "<p class=\"note\">No entries: " + escape(e.what()) + "</p>";
  }
  for (const ControlEntryFile& f : entries.files) {
    h += fmt::format(
        "<p><b>{}</b> (<code>ncpost export {} -o FILE MODEL.json</code>, {} line(s))</p><pre class=\"control\">",
        escape(f.heading), escape(f.export_arguments), f.lines.size());
    for (const std::string& line : f.lines) h += escape(line) + "\n";
    h += "</pre>";
  }
  if (!entries.not_held.empty()) {
    h += fmt::format("<p class=\"note\">Not in these entries ({}):</p><ul>", entries.not_held.size());
    for (const std::string& s : entries.not_held) h += "<li>" + escape(s) + "</li>";
    h += "</ul>";
  }
  return h;
}

}  // namespace ncpost::comp
