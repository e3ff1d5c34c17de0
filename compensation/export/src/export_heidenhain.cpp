// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/export_heidenhain.hpp"

#include <fmt/format.h>

#include <cmath>

#include "ncpost/compensation/export_axis_table.hpp"
#include "ncpost/compensation/export_machine.hpp"

namespace ncpost::comp {
namespace {

constexpr double kDeg = 180.0 / 3.14159265358979323846;

bool is_location(const ParameterSpec& s) { return s.kind == ParameterKind::location; }

std::string why_heidenhain_leaves_out(const ParameterSpec& s) {
  if (s.kind == ParameterKind::coupled) return "location changing with another axis: the description holds constants";
  if (s.kind == ParameterKind::squareness) return "squareness: the description assumes orthogonal linear axes";
  if (s.kind == ParameterKind::reversal) return "reversal: the axis's backlash compensation (machine parameters)";
  return "error motion of an axis: the control's axis error compensation, not the kinematics description";
}

/// The index k of X, Y, Z the axis A, B, C turns about nominally (along +e_k or −e_k: an axis
/// along −e_k is the +e_k axis turned half a turn by its orientation entries); ExportRefusal otherwise.
int nominal_about(const Axis& a, const Machine& m) {
  const int k = a.letter - 'A';
  if (k < 0 || k > 2 || !(a.direction.cwiseAbs() - Vec3d::Unit(k)).isZero(1e-12))
    throw ExportRefusal(ExportRefusal::Source::machine,
                        fmt::format("the Heidenhain entries are written for rotary axes A, B, C that turn the table "
                                    "about ±X, ±Y, ±Z; '{}' has {} along [{}]",
                                    m.name, a.letter, fmt::join(a.direction, ", ")));
  return k;
}

/// The turn about axis i (a) and then axis j (b), i = k+1, j = k+2 (cyclic), taking +e_k to d:
/// Rot_i(a) Rot_j(b) e_k = (…) with d[i] = sin b, d[j] = −sin a cos b, d[k] = cos a cos b.
/// For d near −e_k, a is near ±180°; it is taken on the side of `near_deg` (the nominal's), so
/// that a small tilt is a small change and never a whole turn.
struct Turn {
  int i = 0, j = 0;
  double a_rad = 0.0, b_rad = 0.0;
};
Turn turn_to(const Vec3d& d, int k, double near_rad = 0.0) {
  Turn t;
  t.i = (k + 1) % 3;
  t.j = (k + 2) % 3;
  t.b_rad = std::asin(d[t.i]);
  t.a_rad = std::atan2(-d[t.j], d[k]);
  constexpr double turn = 2.0 * 3.14159265358979323846;
  t.a_rad += turn * std::round((near_rad - t.a_rad) / turn);
  return t;
}

char linear_letter(int c) { return static_cast<char>('X' + c); }
char rotary_letter(int c) { return static_cast<char>('A' + c); }

/// Trans p, the turn, MachAxis, the turn undone: one rotary axis and the shift that leads to it.
void add_axis(std::vector<HeidenhainEntry>& out, char letter, int k, const Vec3d& shift_mm, const Vec3d& nominal_mm,
              const Turn& t, const Turn& nominal) {
  const std::string name(1, letter);
  for (int c = 0; c < 3; ++c)
    out.push_back({"Trans", linear_letter(c), shift_mm[c], nominal_mm[c],
                   c == k ? "position of " + name + " along its line (not measured)"
                          : "position of " + name + " (KinematicsOpt)"});
  const double a = t.a_rad * kDeg, b = t.b_rad * kDeg, na = nominal.a_rad * kDeg, nb = nominal.b_rad * kDeg;
  out.push_back({"Trans", rotary_letter(t.i), a, na, "orientation of " + name + " (KinematicsOpt)"});
  out.push_back({"Trans", rotary_letter(t.j), b, nb, "orientation of " + name + " (KinematicsOpt)"});
  out.push_back({"MachAxis", letter, 0.0, 0.0, "rotary axis " + name});
  out.push_back({"Trans", rotary_letter(t.j), -b, -nb, "orientation of " + name + " undone"});
  out.push_back({"Trans", rotary_letter(t.i), -a, -na, "orientation of " + name + " undone"});
}

std::string fixed9(double x) { return fmt::format("{:.9f}", std::abs(x) < 5e-10 ? 0.0 : x); }

}  // namespace

HeidenhainKinematics heidenhain_kinematics(const MachineModel& model) {
  const Machine& m = model.machine();
  const TableTableAxes axes = table_table_axes(m, "--format heidenhain");
  const Axis& n1 = m.axes[static_cast<std::size_t>(axes.first)];
  const Axis& n2 = m.axes[static_cast<std::size_t>(axes.second)];
  const int k1 = nominal_about(n1, m), k2 = nominal_about(n2, m);
  const MachineExport corrected = corrected_machine(model);  // refuses a model without location errors
  const Axis& a1 = corrected.corrected.axes[static_cast<std::size_t>(axes.first)];
  const Axis& a2 = corrected.corrected.axes[static_cast<std::size_t>(axes.second)];
  HeidenhainKinematics h;
  h.axis1 = a1.letter;
  h.axis2 = a2.letter;
  h.entries.push_back({"MachBase", ' ', 0.0, 0.0, "the machine base; the table side follows"});
  const Turn t1 = turn_to(n1.direction, k1), t2 = turn_to(n2.direction, k2);
  add_axis(h.entries, a1.letter, k1, a1.pivot_mm, n1.pivot_mm, turn_to(a1.direction.normalized(), k1, t1.a_rad), t1);
  add_axis(h.entries, a2.letter, k2, a2.pivot_mm - a1.pivot_mm, n2.pivot_mm - n1.pivot_mm,
           turn_to(a2.direction.normalized(), k2, t2.a_rad), t2);
  for (int c = 0; c < 3; ++c)
    h.entries.push_back({"Trans", linear_letter(c), -a2.pivot_mm[c], -n2.pivot_mm[c], "back to the table datum"});
  h.held = corrected.applied;
  h.left_out = left_out_of(model, is_location, why_heidenhain_leaves_out);
  return h;
}

std::string format_heidenhain(const HeidenhainKinematics& k, const MachineModel& model, const ExportSource& source) {
  const Machine& m = model.machine();
  std::vector<std::string> notes{
      fmt::format("ncpost {} export --format heidenhain: the location errors of model '{}'", source.version,
                  source.model_path),
      fmt::format("(machine '{}', {}) as the entries of a Heidenhain TNC kinematics description that KinematicsOpt",
                  m.name, source.machine_path.empty() ? std::string("no file") : "'" + source.machine_path + "'"),
      "(cycle 451) adjusts: the rotary axes' positions and orientations. A table to enter by hand (KinematicsDesign",
      "or the kinematics table), not a file the control reads. Entries from the machine base towards the table:",
      "Trans X|Y|Z shifts the following entries (mm), Trans A|B|C turns them right-handed about X|Y|Z (deg),",
      fmt::format("MachAxis turns them by the axis's command. Axis 1 = {} (nearer the bed) carries axis 2 = {}; the "
                  "linear axes keep their own entries.",
                  k.axis1, k.axis2),
      "Lengths in ncpost's machine frame M (the tool tip with X Y Z at 0 is its origin): if the control's datum",
      "differs, add the offset to the first position and subtract it from the last entry.",
      "CHANGE: the entry minus the nominal machine's, um (lengths) or urad (angles).",
      fmt::format("Held: {} (the actual lines, tilts included)", fmt::join(k.held, ", "))};
  for (const std::string& line : left_out_lines(k.left_out)) notes.push_back(line);
  std::string out;
  for (const std::string& n : notes) out += "; " + n + "\n";
  out += "NR  KEY       AXIS  COORD             NOMINAL           CHANGE        ROLE\n";
  for (std::size_t r = 0; r < k.entries.size(); ++r) {
    const HeidenhainEntry& e = k.entries[r];
    if (e.key == "MachBase" || e.key == "MachAxis") {
      out += fmt::format("{:<3} {:<9} {:<5} {:<17} {:<17} {:<13} {}\n", r, e.key, e.axis, "", "", "", e.role);
      continue;
    }
    const bool angle = e.axis >= 'A' && e.axis <= 'C';
    const double change = (e.coord - e.nominal) * (angle ? 1e6 / kDeg : 1e3);
    out += fmt::format("{:<3} {:<9} {:<5} {:<17} {:<17} {:<13} {}\n", r, e.key, e.axis, fixed9(e.coord),
                       fixed9(e.nominal), fmt::format("{:+.3f}", std::abs(change) < 5e-4 ? 0.0 : change), e.role);
  }
  return out;
}

}  // namespace ncpost::comp
