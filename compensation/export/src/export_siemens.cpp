// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/export_siemens.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ncpost::comp {

namespace {

constexpr double kDegPerRad = 57.295779513082320876798154814105;

/// The largest step that puts every node on one grid from the first, or 0 when there is none
/// within `max_points`.
double common_step(const std::vector<double>& nodes, int max_points) {
  if (nodes.size() < 2) return 0.0;
  double step = nodes[1] - nodes[0];
  for (std::size_t i = 2; i < nodes.size(); ++i) step = std::min(step, nodes[i] - nodes[i - 1]);
  const double span = nodes.back() - nodes.front();
  for (int divide = 1; divide <= 16; ++divide) {
    const double s = step / divide;
    if (span / s + 1 > max_points) break;
    const bool on_grid = std::all_of(nodes.begin(), nodes.end(), [&](double x) {
      const double k = (x - nodes.front()) / s;
      return std::abs(k - std::round(k)) < 1e-7;
    });
    if (on_grid) return s;
  }
  return 0.0;
}

}  // namespace

SiemensLecTable siemens_lec_table(const MachineModel& model, char letter) {
  SiemensLecTable table;
  table.axis = describe_axis_export(model, letter);
  AxisExport& a = table.axis;
  if (!a.has_positioning)
    throw ExportRefusal(ExportRefusal::Source::model, fmt::format(
        "the model has only a reversal of {}: a SINUMERIK LEC table is one for both directions and cannot hold it "
        "(export it with --format linuxcnc, or enter it as the control's backlash, MD32450)",
        letter));
  if (a.reversal != 0.0) {
    const double b = a.rotary ? a.reversal * kDegPerRad : a.reversal;
    a.left_out.push_back(fmt::format("reversal:{} ({:.6g} {}: the LEC table is one for both directions; enter it as "
                                     "the control's backlash compensation, MD32450 $MA_BACKLASH)",
                                     letter, b, a.rotary ? "deg" : "mm"));
    a.held.erase(std::remove(a.held.begin(), a.held.end(), "reversal:" + std::string(1, letter)), a.held.end());
  }
  table.axis_name = std::string(1, letter) + "1";
  const double unit = a.rotary ? kDegPerRad : 1.0;
  std::vector<double> nodes = export_nodes(a, kSiemensMaxPoints);
  double step = common_step(nodes, kSiemensMaxPoints);
  if (step <= 0.0 && nodes.size() >= 2) step = (nodes.back() - nodes.front()) / 1000.0;
  const int points = nodes.size() < 2 ? 1 : static_cast<int>(std::lround((nodes.back() - nodes.front()) / step)) + 1;
  table.min = nodes.front() * unit;
  table.step = step * unit;
  for (int k = 0; k < points; ++k)
    table.values.push_back(axis_positioning_error(model, a.axis_index, nodes.front() + k * step, false) * unit);
  // how far the table's linear interpolation is from the model between the points
  for (int k = 0; k + 1 < points; ++k)
    for (double f : {0.25, 0.5, 0.75}) {
      const double x = nodes.front() + (k + f) * step;
      const double interpolated = table.values[k] + f * (table.values[k + 1] - table.values[k]);
      table.interpolation_error = std::max(
          table.interpolation_error, std::abs(interpolated - axis_positioning_error(model, a.axis_index, x, false) * unit));
    }
  return table;
}

std::string format_siemens_lec(const SiemensLecTable& table, const MachineModel& model, const ExportSource& source) {
  const AxisExport& a = table.axis;
  const char* unit = a.rotary ? "deg" : "mm";
  const std::string& ax = table.axis_name;
  std::string out = "%_N_AX_EEC_INI\n";
  auto note = [&out](const std::string& s) { out += "; " + s + "\n"; };
  note(fmt::format("ncpost {} export --format siemens --axis {}: SINUMERIK LEC table ($AA_ENC_COMP) of axis {}",
                   source.version, a.letter, a.letter));
  note(fmt::format("model '{}' (machine '{}'{})", source.model_path, model.machine().name,
                   source.machine_path.empty() ? "" : ", file '" + source.machine_path + "'"));
  note(fmt::format("Machine axis {}: rename it to the axis of your control (MD10000 $MN_AXCONF_MACHAX_NAME_TAB).", ax));
  note(fmt::format("Needs MD32700 $MA_ENC_COMP_ENABLE[0] = 1 and MD38000 $MA_MM_ENC_COMP_MAX_POINTS >= {}.", table.values.size()));
  note(fmt::format("Values: the model's positioning error of {} at each point, in {}: SINUMERIK adds it to the", a.letter,
                   a.rotary ? "degrees" : "mm"));
  note("  measured actual position, so a positive value moves the axis in the negative direction: an axis that");
  note(fmt::format("  goes 0.010 {} too far at a point has +0.010 there and lands on the commanded position.", unit));
  note(fmt::format("Linear interpolation between the points departs from the model by at most {:.3g} {}.",
                   table.interpolation_error, unit));
  if (a.continuous) note("One turn, 0 to 360 deg, modulo: the first and last values are the same position.");
  for (const std::string& s : export_notes(a, "export them with --axis, and --format machine for location errors")) note(s);
  out += "CHANDATA(1)\n";
  for (const std::string& line : siemens_lec_lines(table)) out += line + "\n";
  out += "M17\n";
  return out;
}

std::vector<std::string> siemens_lec_lines(const SiemensLecTable& table) {
  const std::string& ax = table.axis_name;
  const int value_decimals = table.axis.rotary ? 9 : 7;
  std::vector<std::string> lines;
  for (std::size_t n = 0; n < table.values.size(); ++n)
    lines.push_back(fmt::format("$AA_ENC_COMP[0,{},{}]={:.{}f}", n, ax, table.values[n], value_decimals));
  const double max = table.min + table.step * static_cast<double>(table.values.size() - 1);
  lines.push_back(fmt::format("$AA_ENC_COMP_STEP[0,{}]={:.6f}", ax, table.step));
  lines.push_back(fmt::format("$AA_ENC_COMP_MIN[0,{}]={:.6f}", ax, table.min));
  lines.push_back(fmt::format("$AA_ENC_COMP_MAX[0,{}]={:.6f}", ax, max));
  lines.push_back(fmt::format("$AA_ENC_COMP_IS_MODULO[0,{}]={}", ax, table.axis.continuous ? 1 : 0));
  return lines;
}

}  // namespace ncpost::comp
