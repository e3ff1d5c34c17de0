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
// location errors, squareness, location errors that change with another axis) is "left out":
// listed for the caller to print and to write into the exported file. Units: mm / rad inside.
//
// One evaluation (issue 25): every export and the report's control entries take the axis's error
// from axis_positioning_error, the model's own chain with every family of the model at once
// (harmonics, tables, polynomials such as the scale error, the reversal); what they sample it at
// comes from AxisExport::model_nodes, the kinks of that function within the travel. Each export
// then checks its file as the control applies it against that same function (landing_check.hpp).
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
  bool continuous = false;       ///< a rotary axis without limits: the table covers one turn, 0 to 2π
  bool piecewise_linear = true;  ///< the error is linear between `model_nodes` (tables and reversal only)
  /// The kinks of the positioning error within the travel (mm or rad), ascending: the nodes of the
  /// axis's own tables, a rotary axis's (periodic) nodes at every turn that falls within the travel.
  std::vector<double> model_nodes;
  double reversal = 0.0;              ///< dead band b (mm or rad), 0 without one
  bool has_positioning = false;       ///< some positioning term (not only the reversal)
  std::vector<std::string> held;      ///< parameter names the table holds
  std::vector<std::string> left_out;  ///< "NAME (why)" for every term acting on the axis it cannot hold
  int other_axis_terms = 0;           ///< machine effects of the other axes (a table of nodes counts once)
  /// Where the travel reaches beyond a table's nodes (a linear axis): "EXX:t ..." saying that the
  /// end values are held there, not extrapolated (issue 25 item 4); for the file and stderr.
  std::vector<std::string> held_beyond;
};

/// Describes axis `letter` of the model. Throws ExportRefusal with the reason when the
/// machine has no such axis, or the model has no positioning error and no reversal for it (nothing
/// to export), or a linear axis whose error is not a table needs limits the machine file lacks.
AxisExport describe_axis_export(const MachineModel& model, char letter);

/// The positioning error e(q) of the axis (mm or rad), moving up (`falling` false) or down: the
/// whole model of the axis through its chain, every other axis at home. The one function every
/// export evaluates.
double axis_positioning_error(const MachineModel& model, int axis_index, double q, bool falling);

/// The correction t to add to the command n so that the axis actually lands on n:
/// (n + t) + e(n + t) = n, solved by fixed-point iteration (e changes slowly).
double axis_correction(const MachineModel& model, int axis_index, double nominal, bool falling);

}  // namespace ncpost::comp
