// SPDX-License-Identifier: Apache-2.0
#pragma once
// The ISG kernel's leadscrew error compensation (LSEC, "SSFK") of one axis, as the axis compensation
// list (achskw*.lis) of Beckhoff TwinCAT 3 CNC (TF5200) and the other ISG-kernel controls reads it.
// Documentation: Beckhoff Information System, "TF5200 | TwinCAT 3 CNC, Axis compensation":
//   "Leadscrew error compensation"  https://infosys.beckhoff.com/content/1033/tf5200_axis_compensation/308683659.html
//   parameters P-COMP-00017 to P-COMP-00025 (kw.ssfk.*), "Example of a compensation value list"
//   https://infosys.beckhoff.com/content/1033/tf5200_axis_compensation_parameters/113439115.html
//   list header kopf.* (P-COMP-00001/2), comments `#` (list examples), activation P-AXIS-00175
//   lr_param.ssfk, start-up list zahl_kw / achs_kw[i] / achs_kw_log_ax_nr[i]
// (the same pages on isg-stuttgart.de, "ISG kernel" documentation).
//
// The list, bilateral with explicit interpolation points:
//   kopf.achs_nr N, kopf.log_achs_name X
//   kw.ssfk.unit 1 (0.1 µm; rotary axes 0.0001°), kw.ssfk.interval 0 (setpoints given), kw.ssfk.kw_startpos,
//   kw.ssfk.kw_nr_max (number of entries), kw.ssfk.bilateral 1, kw.ssfk.modulo (1: a continuous rotary axis)
//   kw.ssfk.table[i].setpoint / .pos / .neg   integers in 0.1 µm (0.0001°)
// How the control applies it (same pages): the position setpoint of the axis is changed in the
// position controller cycle by the compensation value of the direction of motion (pos moving
// positive, neg moving negative), interpolated linearly between the interpolation points in the
// axis position, the end values held beyond the table. The values are "absolute position errors":
// the documented example enters, at setpoint 19866.7 µm, measured 19856.5 µm moving positive and
// 19874.7 µm moving negative, pos = −102 and neg = +80 (×0.1 µm): value = measured − programmed
// position, so the control commands programmed − value. Here each value is, for that direction,
// the model's positioning error (export_axis_table.hpp) where the drive must stand for the axis to
// land on the setpoint, −t with (s + t) + e(s + t) = s: the control's s − value then lands exactly,
// and the value is the error at the setpoint to first order (+100 for an axis that goes 10 µm too
// far). The setpoints include the kinks of that value (export_nodes.hpp). The reversal is in the
// neg column (bilateral LSEC needs no separate backlash compensation, per the same page). The
// list's unit, 0.1 µm or 0.0001° (1.745 µrad), bounds how closely it can follow the model.
#include <cstdint>
#include <string>
#include <vector>

#include "ncpost/compensation/export_axis_table.hpp"
#include "ncpost/compensation/export_linuxcnc.hpp"
#include "ncpost/compensation/landing_check.hpp"

namespace ncpost::comp {

struct IsgLsecTable {
  AxisExport axis;
  int logical_axis = 0;  ///< kopf.achs_nr: the axis's place in the machine file (the user sets the control's)
  /// interpolation points and compensation values, in 0.1 µm (linear) or 0.0001° (rotary)
  std::vector<std::int64_t> setpoints, pos, neg;
  LandingCheck landing;  ///< the list applied as the ISG kernel applies it, against the model
};

/// Units of the list (kw.ssfk.unit = 1): 0.1 µm per count for lengths, 0.0001° per count for angles.
inline constexpr double kIsgCountsPerMm = 1e4;
inline constexpr double kIsgCountsPerDeg = 1e4;
/// Entries the control holds without raising P-COMP-00059 (kw.ssfk.max_points, default 1500).
inline constexpr int kIsgMaxPoints = 1500;

/// The table of axis `letter`; ExportRefusal as describe_axis_export.
IsgLsecTable isg_lsec_table(const MachineModel& model, char letter);

/// The lines the control reads: header and kw.ssfk.* (no comments).
std::vector<std::string> isg_lsec_lines(const IsgLsecTable& table);

/// The list file: `#` notes (source, activation, sign, what is held and left out), then the lines.
std::string format_isg_lsec(const IsgLsecTable& table, const MachineModel& model, const ExportSource& source);

}  // namespace ncpost::comp
