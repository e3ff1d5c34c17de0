// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/export_linuxcnc.hpp"
#include "ncpost/kinematics/units.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>

#include "ncpost/compensation/export_nodes.hpp"

namespace ncpost::comp {

namespace {

/// Decimals of the file: nominals, and trims of a linear / rotary axis.
constexpr int kNominalDecimals = 6;
constexpr int kLinearTrimDecimals = 7;
constexpr int kRotaryTrimDecimals = 9;

double rounded(double v, int decimals) {
  const double scale = std::pow(10.0, decimals);
  return std::round(v * scale) / scale;
}

/// compute_screw_comp: the trim of the rows (file units) at nominal n (file units), moving forward
/// or in reverse, linear between the nominals, the end rows' trims held beyond them.
double trim_at(const std::vector<std::array<double, 3>>& rows, double n, bool reverse) {
  const std::size_t c = reverse ? 2 : 1;
  if (n <= rows.front()[0]) return rows.front()[c];
  for (std::size_t i = 1; i < rows.size(); ++i)
    if (n < rows[i][0])
      return rows[i - 1][c] + (rows[i][c] - rows[i - 1][c]) * (n - rows[i - 1][0]) / (rows[i][0] - rows[i - 1][0]);
  return rows.back()[c];
}

}  // namespace

LinuxcncCompTable linuxcnc_comp_table(const MachineModel& model, char letter) {
  LinuxcncCompTable table;
  table.axis = describe_axis_export(model, letter);
  const AxisExport& a = table.axis;
  const double unit = a.rotary ? kDegPerRad : 1.0;  // file units per model unit
  const int trim_decimals = a.rotary ? kRotaryTrimDecimals : kLinearTrimDecimals;
  // each row's trim exactly at the nominal the file prints
  for (double n : commanded_nodes(model, a, kLinuxcncMaxRows, std::pow(10.0, -kNominalDecimals) / unit)) {
    const double forward_trim = axis_correction(model, a.axis_index, n, false);
    const double reverse_trim = axis_correction(model, a.axis_index, n, true);
    table.rows.push_back({rounded(n * unit, kNominalDecimals), rounded(forward_trim * unit, trim_decimals),
                          rounded(reverse_trim * unit, trim_decimals)});
  }
  table.landing = check_landing(
      model, a, [&](double n, bool falling) { return n + trim_at(table.rows, n * unit, falling) / unit; }, true);
  return table;
}

std::vector<std::string> export_notes(const AxisExport& a, const std::string& other_axes_hint) {
  std::vector<std::string> notes;
  std::map<std::string, int> held;
  std::vector<std::string> order;
  for (const std::string& name : a.held) {
    const std::string key =
        name.find(":t:") != std::string::npos ? name.substr(0, name.find(":t:")) + ":t" : effect_of(name);
    if (held[key]++ == 0) order.push_back(key);
  }
  std::string held_text;
  for (const std::string& key : order) {
    if (!held_text.empty()) held_text += ", ";
    held_text += key;
    if (key.size() > 2 && key.substr(key.size() - 2) == ":t") held_text += fmt::format(" ({} nodes)", held[key]);
  }
  notes.push_back(fmt::format("Held: {}", held_text));
  if (a.left_out.empty()) {
    notes.push_back(fmt::format("Left out: nothing of the model acting on {}", a.letter));
  } else {
    notes.push_back(
        fmt::format("Left out (NOT compensated by this file): {} term(s) acting on {}:", a.left_out.size(), a.letter));
    for (const std::string& s : a.left_out) notes.push_back("  " + s);
  }
  for (const std::string& s : a.held_beyond) notes.push_back("Beyond the measured travel: " + s);
  if (a.other_axis_terms > 0)
    notes.push_back(
        fmt::format("Not in this file: {} term(s) of the other axes ({})", a.other_axis_terms, other_axes_hint));
  return notes;
}

std::vector<std::string> linuxcnc_comp_lines(const LinuxcncCompTable& table) {
  const int trim_decimals = table.axis.rotary ? kRotaryTrimDecimals : kLinearTrimDecimals;
  std::vector<std::string> lines;
  for (const auto& r : table.rows)
    lines.push_back(
        fmt::format("{:.{}f} {:.{}f} {:.{}f}", r[0], kNominalDecimals, r[1], trim_decimals, r[2], trim_decimals));
  return lines;
}

std::string format_linuxcnc_comp(const LinuxcncCompTable& table, const MachineModel& model,
                                 const ExportSource& source) {
  const AxisExport& a = table.axis;
  const char* unit = a.rotary ? "deg" : "mm";
  std::string out;
  for (const std::string& line : linuxcnc_comp_lines(table)) out += line + "\n";
  auto note = [&out](const std::string& s) { out += "# " + s + "\n"; };
  out += "\n";
  note(fmt::format("ncpost {} export --format linuxcnc --axis {}: LinuxCNC compensation file of axis {}",
                   source.version, a.letter, a.letter));
  note(fmt::format("model '{}' (machine '{}'{})", source.model_path, model.machine().name,
                   source.machine_path.empty() ? "" : ", file '" + source.machine_path + "'"));
  note(fmt::format("INI: [JOINT_n] of the joint that drives {} (LinuxCNC 2.8 and later; [AXIS_n] in 2.7):", a.letter));
  note("       COMP_FILE = <this file>");
  note("       COMP_FILE_TYPE = 1");
  note(fmt::format("Rows: nominal (commanded) position, forward trim, reverse trim, in {} ({} rows, at most 256).",
                   a.rotary ? "degrees" : "mm (LINEAR_UNITS = mm)", table.rows.size()));
  note("COMP_FILE_TYPE 1: a trim is the offset LinuxCNC adds to the commanded position while the joint moves");
  note("  in the positive (forward) or negative (reverse) direction, interpolated linearly between the nominals,");
  note("  the first and last rows' trims held beyond them.");
  note(fmt::format("Sign: trim = -(the model's positioning error of {}), solved so that the axis actually lands",
                   a.letter));
  note(fmt::format(
      "  on the commanded position: a model error of +0.010 {} at {} = 100 {} gives a trim of about -0.010 {}.", unit,
      a.letter, unit, unit));
  note("These notes follow the rows because LinuxCNC stops reading the file at its first line that is not");
  note("  three numbers: do not move them to the top.");
  if (a.reversal != 0.0)
    note(fmt::format(
        "Reversal {:.6g} {} is in the reverse column: with a COMP_FILE LinuxCNC ignores BACKLASH (leave it 0).",
        a.rotary ? a.reversal * kDegPerRad : a.reversal, unit));
  note(fmt::format("Travel covered: {:.6f} to {:.6f} {} ({})", a.travel_min * (a.rotary ? kDegPerRad : 1.0),
                   a.travel_max * (a.rotary ? kDegPerRad : 1.0), unit,
                   a.continuous ? "one turn of a continuous axis: set [AXIS_" + std::string(1, a.letter) +
                                      "]WRAPPED_ROTARY = 1 so that the joint stays in it"
                                : (model.machine().axes[static_cast<std::size_t>(a.axis_index)].limits
                                       ? "the machine's limits"
                                       : "the model's table; its end values hold beyond it")));
  note(landing_note(a, table.landing, "LinuxCNC"));
  for (const std::string& s : export_notes(a, "export them with --axis, and --format machine for location errors"))
    note(s);
  return out;
}

}  // namespace ncpost::comp
