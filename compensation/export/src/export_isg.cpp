// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/export_isg.hpp"
#include "ncpost/kinematics/units.hpp"

#include <fmt/format.h>

#include <cmath>

#include "ncpost/compensation/export_nodes.hpp"

namespace ncpost::comp {

namespace {

/// Counts of the list per model unit (mm or rad).
double counts_per_unit(const AxisExport& a) { return a.rotary ? kIsgCountsPerDeg * kDegPerRad : kIsgCountsPerMm; }

/// The list's value (counts) at setpoint x (counts) of column v: linear between the setpoints, the
/// end values held beyond them, round the turn on a modulo axis.
double list_value(const IsgLsecTable& t, const std::vector<std::int64_t>& v, double x) {
  const auto& s = t.setpoints;
  if (t.axis.continuous && s.size() >= 2) {
    const double span = static_cast<double>(s.back() - s.front());
    x = static_cast<double>(s.front()) + std::fmod(std::fmod(x - static_cast<double>(s.front()), span) + span, span);
  }
  if (x <= static_cast<double>(s.front())) return static_cast<double>(v.front());
  for (std::size_t i = 1; i < s.size(); ++i)
    if (x < static_cast<double>(s[i]))
      return static_cast<double>(v[i - 1]) + static_cast<double>(v[i] - v[i - 1]) *
                                                 (x - static_cast<double>(s[i - 1])) /
                                                 static_cast<double>(s[i] - s[i - 1]);
  return static_cast<double>(v.back());
}

}  // namespace

IsgLsecTable isg_lsec_table(const MachineModel& model, char letter) {
  IsgLsecTable table;
  table.axis = describe_axis_export(model, letter);
  const AxisExport& a = table.axis;
  table.logical_axis = a.axis_index + 1;
  const double per_unit = counts_per_unit(a);
  // setpoints on the list's grid of counts, each value there: the error the axis makes where the
  // drive must go for it to land on the setpoint (−t, t the correction): exact where the control
  // subtracts it, and the measured error to first order
  for (double q : commanded_nodes(model, a, kIsgMaxPoints, 1.0 / per_unit)) {
    table.setpoints.push_back(std::llround(q * per_unit));
    table.pos.push_back(std::llround(-axis_correction(model, a.axis_index, q, false) * per_unit));
    table.neg.push_back(std::llround(-axis_correction(model, a.axis_index, q, true) * per_unit));
  }
  table.landing = check_landing(
      model, a,
      [&](double n, bool falling) {
        return n - list_value(table, falling ? table.neg : table.pos, n * per_unit) / per_unit;
      },
      true);
  return table;
}

std::vector<std::string> isg_lsec_lines(const IsgLsecTable& t) {
  const AxisExport& a = t.axis;
  std::vector<std::string> lines;
  lines.push_back(fmt::format("kopf.achs_nr {}", t.logical_axis));
  lines.push_back(fmt::format("kopf.log_achs_name {}", a.letter));
  lines.push_back("kw.ssfk.unit 1");
  lines.push_back("kw.ssfk.interval 0");
  lines.push_back(fmt::format("kw.ssfk.kw_startpos {}", t.setpoints.empty() ? 0 : t.setpoints.front()));
  lines.push_back(fmt::format("kw.ssfk.kw_nr_max {}", t.setpoints.size()));
  lines.push_back("kw.ssfk.bilateral 1");
  lines.push_back(fmt::format("kw.ssfk.modulo {}", a.continuous ? 1 : 0));
  for (std::size_t i = 0; i < t.setpoints.size(); ++i)
    lines.push_back(fmt::format("kw.ssfk.table[{}].setpoint {}", i, t.setpoints[i]));
  for (std::size_t i = 0; i < t.pos.size(); ++i) lines.push_back(fmt::format("kw.ssfk.table[{}].pos {}", i, t.pos[i]));
  for (std::size_t i = 0; i < t.neg.size(); ++i) lines.push_back(fmt::format("kw.ssfk.table[{}].neg {}", i, t.neg[i]));
  return lines;
}

std::string format_isg_lsec(const IsgLsecTable& t, const MachineModel& model, const ExportSource& source) {
  const AxisExport& a = t.axis;
  const char* count = a.rotary ? "0.0001 deg" : "0.1 µm";
  std::string out;
  auto note = [&out](const std::string& s) { out += "# " + s + "\n"; };
  note(
      fmt::format("ncpost {} export --format isg --axis {}: ISG-kernel / Beckhoff TwinCAT CNC leadscrew error "
                  "compensation (kw.ssfk) of axis {}",
                  source.version, a.letter, a.letter));
  note(fmt::format("model '{}' (machine '{}'{})", source.model_path, model.machine().name,
                   source.machine_path.empty() ? "" : ", file '" + source.machine_path + "'"));
  note(
      "Format: Beckhoff Information System, TF5200 TwinCAT 3 CNC \"Axis compensation\", leadscrew error compensation,");
  note("  P-COMP-00017..00025 and \"Example of a compensation value list\":");
  note("  https://infosys.beckhoff.com/content/1033/tf5200_axis_compensation_parameters/113439115.html");
  note(fmt::format(
      "kopf.achs_nr {} is the axis's place in the ncpost machine file: set it to the logical axis number of {}",
      t.logical_axis, a.letter));
  note("  on your control (P-AXIS-00016). Activate with lr_param.ssfk 1 (P-AXIS-00175) in the axis parameter list and");
  note("  name this file in the start-up list (zahl_kw, achs_kw[i], achs_kw_log_ax_nr[i]).");
  note(fmt::format("Values in {} (kw.ssfk.unit 1), {} interpolation points (P-COMP-00059 max_points >= {}).", count,
                   t.setpoints.size(), t.setpoints.size()));
  note(fmt::format("Sign: each value is the model's positioning error of {} at the setpoint (measured minus programmed",
                   a.letter));
  note("  position, as in the documented example: -102 where the axis stopped 10.2 µm short); the control changes the");
  note(
      "  position setpoint by it, so that the axis lands on the programmed position. Each value is taken where the "
      "drive");
  note(
      "  must stand for the axis to land on the setpoint (the error at the setpoint to first order), so that the "
      "control's");
  note("  setpoint minus value lands exactly. pos: moving positive; neg: moving");
  note(fmt::format("  negative. An axis that goes 0.010 {} too far at a point has pos = +100 there.",
                   a.rotary ? "deg" : "mm"));
  if (a.reversal != 0.0)
    note(
        fmt::format("Reversal {:.6g} {} ({} counts) is in the neg column (bilateral LSEC): leave the separate backlash "
                    "compensation off.",
                    a.rotary ? a.reversal * kDegPerRad : a.reversal, a.rotary ? "deg" : "mm",
                    std::llround(a.reversal * counts_per_unit(a))));
  if (a.continuous)
    note("One turn, 0 to 360 deg, modulo (kw.ssfk.modulo 1): the first and last points are the same position.");
  note(
      fmt::format("Resolution: one count is {} ({}), so the list can be off the model by half a count on top of its "
                  "interpolation.",
                  count, a.rotary ? "1.745 µrad" : "0.1 µm"));
  note(landing_note(a, t.landing, "the ISG kernel"));
  for (const std::string& s : export_notes(a, "export them with --axis, and --format machine for location errors"))
    note(s);
  for (const std::string& line : isg_lsec_lines(t)) out += line + "\n";
  return out;
}

}  // namespace ncpost::comp
