// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/export_cycle800.hpp"

#include <fmt/format.h>

#include <cmath>

#include "ncpost/compensation/export_axis_table.hpp"
#include "ncpost/compensation/export_machine.hpp"

namespace ncpost::comp {

namespace {

bool is_cycle800_location(const ParameterSpec& s) { return s.kind == ParameterKind::location; }

std::string why_cycle800_leaves_out(const ParameterSpec& s) {
  if (s.kind == ParameterKind::coupled) return "location changing with another axis: the record holds constants";
  if (s.kind == ParameterKind::squareness) return "squareness: the record assumes orthogonal linear axes";
  if (s.kind == ParameterKind::reversal) return "reversal: the axis's backlash compensation (MD32450)";
  return "error motion of an axis: an LEC table of that axis (--format siemens) holds its positioning part";
}

std::string number(double x, int decimals) {
  return fmt::format("{:.{}f}", std::abs(x) < 0.5 * std::pow(10.0, -decimals) ? 0.0 : x, decimals);
}

}  // namespace

Cycle800Record cycle800_record(const MachineModel& model) {
  const Machine& m = model.machine();
  const TableTableAxes axes = table_table_axes(m, "--format siemens-cycle800 (kinematic type P)");
  const MachineExport corrected = corrected_machine(model);  // refuses a model without location errors
  const Axis& a1 = corrected.corrected.axes[static_cast<std::size_t>(axes.first)];
  const Axis& a2 = corrected.corrected.axes[static_cast<std::size_t>(axes.second)];
  Cycle800Record r;
  r.axis1 = a1.letter;
  r.axis2 = a2.letter;
  r.l2_mm = a1.pivot_mm;
  r.v1 = a1.direction.normalized();
  r.l3_mm = a2.pivot_mm - a1.pivot_mm;
  r.v2 = a2.direction.normalized();
  r.l4_mm = -(r.l2_mm + r.l3_mm);
  r.held = corrected.applied;
  r.left_out = left_out_of(model, is_cycle800_location, why_cycle800_leaves_out);
  return r;
}

std::string format_cycle800(const Cycle800Record& r, const MachineModel& model, const ExportSource& source) {
  const Machine& m = model.machine();
  std::vector<std::string> notes{
      fmt::format("ncpost {} export --format siemens-cycle800: the location errors of model '{}'", source.version,
                  source.model_path),
      fmt::format("(machine '{}', {}) as the CYCLE800 swivel data record [1], kinematic type P (swivel table).", m.name,
                  source.machine_path.empty() ? std::string("no file") : "'" + source.machine_path + "'"),
      "Change [1] to the record's number. Chain: M_T_table = Trans(l2) Rot(v1,a1) Trans(l3) Rot(v2,a2) Trans(l4),",
      fmt::format("rotary axis 1 = {} (nearer the bed, carries axis 2 = {}); l2: machine reference point to a point "
                  "of axis 1,",
                  r.axis1, r.axis2),
      "l3: from there to a point of axis 2, l4 = -(l2 + l3); l1 = 0 (no head). Lengths in mm, rotary axes at 0.",
      "v1, v2: unit vectors about which a positive command turns the TABLE right-handed (a table axis turning in",
      "the tool's ISO sense has the vector of the machine axis reversed, e.g. v = 0,0,-1 for such a C).",
      "Machine reference point = ncpost's machine frame M (the tool tip with X Y Z at 0): if the control's",
      "differs, add the offset to l2 and subtract it from l4. These are whole values: set the fine offsets",
      "$TC_CARR41.. (written by CYCLE996) to 0 with them.",
      fmt::format("Held: {} (pivots and directions of the actual lines, tilts included)", fmt::join(r.held, ", "))};
  for (const std::string& line : left_out_lines(r.left_out)) notes.push_back(line);
  std::string out;
  for (const std::string& n : notes) out += "; " + n + "\n";
  const auto vector = [&](int first, const Vec3d& v, int decimals) {
    for (int i = 0; i < 3; ++i) out += fmt::format("$TC_CARR{}[1]={}\n", first + i, number(v[i], decimals));
  };
  vector(1, r.l1_mm, 6);   // l1
  vector(4, r.l2_mm, 6);   // l2
  vector(7, r.v1, 12);     // v1
  vector(10, r.v2, 12);    // v2
  vector(15, r.l3_mm, 6);  // l3
  vector(18, r.l4_mm, 6);  // l4
  out += fmt::format("$TC_CARR21[1]={}\n$TC_CARR22[1]={}\n$TC_CARR23[1]=\"P\"\n", r.axis1, r.axis2);
  out += "M30\n";
  return out;
}

}  // namespace ncpost::comp
