// SPDX-License-Identifier: Apache-2.0
#pragma once
// Where an axis table samples the model's positioning error (export_axis_table.hpp), so that the
// control's linear interpolation between the points reproduces it (issue 25):
//   - a table of the measured position (SINUMERIK LEC: the value c(m) = e(m) at the measured
//     position m) is exact for a piecewise-linear error when every kink of e is a point:
//     equidistant points on a grid through the model's nodes (equidistant_points);
//   - a table of the commanded position (LinuxCNC trims, ISG values: t(n) with (n + t) + e(n + t) = n)
//     has its kinks where the drive passes a node x of e, at the commanded n = x + e(x), different
//     per direction of motion when there is a reversal: points there (commanded_nodes).
// Where the error is smooth (harmonics, polynomials) an even grid is added. Units: mm / rad.
#include <vector>

#include "ncpost/compensation/export_axis_table.hpp"

namespace ncpost::comp {

/// Commanded positions for a table of the commanded position, ascending, each a whole multiple of
/// `resolution` (the file's last digit, mm or rad), within the travel: the travel ends, every kink
/// x + e(x) of each direction, the nodes x themselves where there is room, and an even grid for a
/// smooth error; at most `max_nodes`, else ExportRefusal.
std::vector<double> commanded_nodes(const MachineModel& model, const AxisExport& axis, int max_nodes,
                                    double resolution);

/// Equidistant points min + k·step, k = 0..count−1, over the travel.
struct EquidistantPoints {
  double min = 0.0;
  double step = 0.0;
  int count = 0;
  bool nodes_on_grid = true;  ///< false when no grid within the limit has every node of the model on it
};

/// The coarsest grid through every node of the model (a smooth error: at least 1000 intervals, or
/// `max_points` − 1) with at most `max_points` points; when no such grid exists, 1000 intervals
/// (nodes_on_grid false).
EquidistantPoints equidistant_points(const AxisExport& axis, int max_points);

}  // namespace ncpost::comp
