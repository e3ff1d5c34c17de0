// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/export_siemens.hpp"
#include "ncpost/kinematics/units.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "ncpost/compensation/export_nodes.hpp"

namespace ncpost::comp {

namespace {

/// Decimals of the values: mm, degrees.
constexpr int kLinearDecimals = 7;
constexpr int kRotaryDecimals = 9;

double as_printed(double v, bool rotary) {
  const double scale = std::pow(10.0, rotary ? kRotaryDecimals : kLinearDecimals);
  return std::round(v * scale) / scale;
}

/// The LEC value (model units) at measured position m (model units): linear between the points,
/// the first and last values held beyond them, round the turn on a modulo axis.
double lec_value(const SiemensLecTable& t, double m, double unit) {
  if (t.step <= 0.0) return t.values.front() / unit;
  const double x = m * unit;
  double k = (x - t.min) / t.step;
  const double points = static_cast<double>(t.values.size());
  if (t.axis.continuous) k = std::fmod(std::fmod(k, points - 1.0) + (points - 1.0), points - 1.0);
  if (k <= 0.0) return t.values.front() / unit;
  if (k >= points - 1.0) return t.values.back() / unit;
  const auto i = static_cast<std::size_t>(k);
  return (t.values[i] + (k - static_cast<double>(i)) * (t.values[i + 1] - t.values[i])) / unit;
}

/// The position loop settles at the measured m with m + c(m) = n (fixed point: c changes slowly).
double settled_position(const SiemensLecTable& t, double n, double unit) {
  double m = n;
  for (int k = 0; k < 100; ++k) {
    const double next = n - lec_value(t, m, unit);
    if (std::abs(next - m) < 1e-14) return next;
    m = next;
  }
  return m;
}

}  // namespace

SiemensLecTable siemens_lec_table(const MachineModel& model, char letter) {
  SiemensLecTable table;
  table.axis = describe_axis_export(model, letter);
  AxisExport& a = table.axis;
  if (!a.has_positioning)
    throw ExportRefusal(
        ExportRefusal::Source::model,
        fmt::format(
            "the model has only a reversal of {}: a SINUMERIK LEC table is one for both directions and cannot hold it "
            "(export it with --format linuxcnc, or enter it as the control's backlash, MD32450)",
            letter));
  if (a.reversal != 0.0) {
    const double b = a.rotary ? a.reversal * kDegPerRad : a.reversal;
    a.left_out.push_back(
        fmt::format("reversal:{} ({:.6g} {}: the LEC table is one for both directions; enter it as "
                    "the control's backlash compensation, MD32450 $MA_BACKLASH)",
                    letter, b, a.rotary ? "deg" : "mm"));
    a.held.erase(std::remove(a.held.begin(), a.held.end(), "reversal:" + std::string(1, letter)), a.held.end());
  }
  table.axis_name = std::string(1, letter) + "1";
  const double unit = a.rotary ? kDegPerRad : 1.0;
  const EquidistantPoints grid = equidistant_points(a, kSiemensMaxPoints);
  table.min = grid.min * unit;
  table.step = grid.step * unit;
  table.nodes_on_grid = grid.nodes_on_grid;
  for (int k = 0; k < grid.count; ++k)
    table.values.push_back(
        as_printed(axis_positioning_error(model, a.axis_index, grid.min + k * grid.step, false) * unit, a.rotary));
  // the reversal is left out (listed): the check moving up, where the table is all of the model
  table.landing = check_landing(
      model, a, [&](double n, bool) { return settled_position(table, n, unit); }, false);
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
  note(fmt::format("Needs MD32700 $MA_ENC_COMP_ENABLE[0] = 1 and MD38000 $MA_MM_ENC_COMP_MAX_POINTS >= {}.",
                   table.values.size()));
  note(fmt::format("Values: the model's positioning error of {} at each point, in {}: SINUMERIK adds it to the",
                   a.letter, a.rotary ? "degrees" : "mm"));
  note("  measured actual position, so a positive value moves the axis in the negative direction: an axis that");
  note(fmt::format("  goes 0.010 {} too far at a point has +0.010 there and lands on the commanded position.", unit));
  if (!table.nodes_on_grid)
    note(
        "The model's table nodes do not lie on one grid of at most 2000 points: between them the points do not follow "
        "its kinks exactly (see the round trip below).");
  note(landing_note(a, table.landing, "SINUMERIK"));
  if (a.continuous) note("One turn, 0 to 360 deg, modulo: the first and last values are the same position.");
  for (const std::string& s : export_notes(a, "export them with --axis, and --format machine for location errors"))
    note(s);
  out += "CHANDATA(1)\n";
  for (const std::string& line : siemens_lec_lines(table)) out += line + "\n";
  out += "M17\n";
  return out;
}

std::vector<std::string> siemens_lec_lines(const SiemensLecTable& table) {
  const std::string& ax = table.axis_name;
  const int value_decimals = table.axis.rotary ? kRotaryDecimals : kLinearDecimals;
  std::vector<std::string> lines;
  for (std::size_t n = 0; n < table.values.size(); ++n)
    lines.push_back(fmt::format("$AA_ENC_COMP[0,{},{}]={:.{}f}", n, ax, table.values[n], value_decimals));
  const double max = table.min + table.step * static_cast<double>(table.values.size() - 1);
  lines.push_back(fmt::format("$AA_ENC_COMP_STEP[0,{}]={:.9f}", ax, table.step));
  lines.push_back(fmt::format("$AA_ENC_COMP_MIN[0,{}]={:.9f}", ax, table.min));
  lines.push_back(fmt::format("$AA_ENC_COMP_MAX[0,{}]={:.9f}", ax, max));
  lines.push_back(fmt::format("$AA_ENC_COMP_IS_MODULO[0,{}]={}", ax, table.axis.continuous ? 1 : 0));
  return lines;
}

}  // namespace ncpost::comp
