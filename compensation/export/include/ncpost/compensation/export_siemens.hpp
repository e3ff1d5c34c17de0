// SPDX-License-Identifier: Apache-2.0
#pragma once
// SINUMERIK leadscrew / measuring-system error compensation (LEC) table of one axis
// ($AA_ENC_COMP, SINUMERIK 840D sl Function Manual "Extended Functions", K3 Compensations,
// "Interpolatory compensation"): an NC program (%_N_AX_EEC_INI) setting
//   $AA_ENC_COMP[0,N,AX]   the compensation value of interpolation point N (mm, degrees)
//   $AA_ENC_COMP_STEP[0,AX], $AA_ENC_COMP_MIN[0,AX], $AA_ENC_COMP_MAX[0,AX]   equidistant points
//   $AA_ENC_COMP_IS_MODULO[0,AX]  1 for a modulo (continuous rotary) axis
// How the control applies it (same manual): "the axis-specific position actual value" is modified
// by the compensation value, interpolated linearly between the points (the first and last values
// active beyond them), and "a positive compensation value causes the corresponding machine axis to
// move in the negative direction". The position loop brings m + c(m) to the command n, m the
// measured position; the tool is then at m + e(m), e the model's positioning error
// (export_axis_table.hpp): so c = e at every point — the value is the error itself, +0.010 mm for
// an axis that goes 10 µm too far. The table is one for both directions: the reversal is left
// out (listed; the control's backlash compensation MD32450 is the place for it).
#include <string>
#include <vector>

#include "ncpost/compensation/export_axis_table.hpp"
#include "ncpost/compensation/export_linuxcnc.hpp"
#include "ncpost/compensation/landing_check.hpp"

namespace ncpost::comp {

struct SiemensLecTable {
  AxisExport axis;
  std::string axis_name;  ///< the machine axis in the variables, e.g. "X1"
  double min = 0.0;       ///< mm or degrees
  double step = 0.0;
  std::vector<double> values;  ///< mm or degrees, point N at min + N·step
  bool nodes_on_grid = true;   ///< every node of the model's tables is a point
  LandingCheck landing;        ///< the table applied as SINUMERIK applies it, against the model (moving up)
};

/// Points for the table (SINUMERIK's own limit is a machine datum, MD38000 MM_ENC_COMP_MAX_POINTS).
inline constexpr int kSiemensMaxPoints = 2000;

/// The table of axis `letter`; std::invalid_argument as describe_axis_export, or when the model has
/// only a reversal for the axis (nothing this table can hold).
SiemensLecTable siemens_lec_table(const MachineModel& model, char letter);

/// The assignments the control executes ($AA_ENC_COMP..., no comments).
std::vector<std::string> siemens_lec_lines(const SiemensLecTable& table);

std::string format_siemens_lec(const SiemensLecTable& table, const MachineModel& model, const ExportSource& source);

}  // namespace ncpost::comp
