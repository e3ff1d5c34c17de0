// SPDX-License-Identifier: Apache-2.0
#pragma once
// What a control's one-axis compensation table can hold of an error model (issue 17, `ncpost
// export`): the positioning error of one axis along itself, per direction of motion, as the
// model's own forward kinematics give it (docs/conventions.md "Geometric errors"):
//   linear axis j:  e(q) = component along the axis of (actual − nominal) tool tip in W, with only
//                   j moved to q, tool length 0 (the reference point: angular error motions then
//                   move nothing) — EXX(q) − EXX(0) for X, tables, polynomials and the reversal;
//   rotary axis j:  e(q) = the angle (rad) by which the body it carries turns beyond q about its
//                   direction — ECC(q) − ECC(0) for a C axis about ±Z, and the reversal.
// Moving down (falling commands) the dead band adds the reversal b (actual = command + b).
// Everything else acting on the axis (straightness, roll/pitch/yaw, radial and tilt motions,
// location errors, squareness) is "left out": listed for the caller to print and to write into
// the exported file. Units: mm / rad inside, as everywhere.
#include <stdexcept>
#include <string>
#include <vector>

#include "ncpost/compensation/machine_model.hpp"

namespace ncpost::comp {

/// Why an export cannot be made, and which input is at fault (the model, or the machine file).
struct ExportRefusal : std::invalid_argument {
  enum class Source { model, machine };
  ExportRefusal(Source s, const std::string& what) : std::invalid_argument(what), source(s) {}
  Source source;
};

/// One axis of a model, as the exporters see it.
struct AxisExport {
  int axis_index = -1;
  char letter = '?';
  bool rotary = false;
  double travel_min = 0.0;  ///< mm or rad: the range the table covers
  double travel_max = 0.0;
  bool continuous = false;      ///< a rotary axis without limits: the table covers one turn, 0 to 2π
  bool piecewise_linear = true;  ///< the error is linear between `model_nodes` (tables and reversal only)
  std::vector<double> model_nodes;  ///< the model's own table nodes of the positioning error (mm), sorted
  double reversal = 0.0;            ///< dead band b (mm or rad), 0 without one
  bool has_positioning = false;     ///< some positioning term (not only the reversal)
  std::vector<std::string> held;      ///< parameter names the table holds
  std::vector<std::string> left_out;  ///< "NAME (why)" for every term acting on the axis it cannot hold
  int other_axis_terms = 0;           ///< machine effects of the other axes (a table of nodes counts once)
};

/// Describes axis `letter` of the model. Throws ExportRefusal with the reason when the
/// machine has no such axis, or the model has no positioning error and no reversal for it (nothing
/// to export), or a linear axis whose error is not a table needs limits the machine file lacks.
AxisExport describe_axis_export(const MachineModel& model, char letter);

/// The positioning error e(q) of the axis (mm or rad), moving up (`falling` false) or down.
double axis_positioning_error(const MachineModel& model, int axis_index, double q, bool falling);

/// The correction t to add to the command n so that the axis actually lands on n:
/// (n + t) + e(n + t) = n, solved by fixed-point iteration (e changes slowly).
double axis_correction(const MachineModel& model, int axis_index, double nominal, bool falling);

/// Nodes covering [travel_min, travel_max]: the model's table nodes, the travel ends and, where the
/// error is not piecewise linear in those, an even grid; at most `max_nodes`, ascending.
std::vector<double> export_nodes(const AxisExport& axis, int max_nodes);

}  // namespace ncpost::comp
