#pragma once
// SPDX-License-Identifier: Apache-2.0
// The tests' own reading of what a SINUMERIK 840D sl does around CYCLE800 (sinumerik_mini.hpp uses
// it), independent of the product:
//   - CYCLE800 _FR=1: machine Z to the swivel data's retraction position, the machine file's
//     [axes.Z] swivel_retract (without it the position is not known);
//   - the rotary axes of the plane: the angles whose tool axis is the plane's Z (solved here with the
//     tests' forward kinematics), the _DIR branch: rotary axis 1 of the swivel data record (the head
//     axis nearest the bed where the machine has a head axis, else the table axis nearest the bed: Siemens'
//     kinematic types M, P and T) on the side _DIR names (0 allowed), the nearest to the angles before
//     among those (a continuous axis unwound to the nearest turn); a free axis (the plane's Z along it)
//     stays;
//   - the position after the swivel: the linear axes stand still, so the tool tip is where the machine
//     position puts it with the new angles, read in the new plane's frame.
// Lengths mm, angles deg.
#include <cctype>
#include <cmath>
#include <stdexcept>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "nc_executor.hpp"

namespace ncpost::test {

/// Rotary axis 1 of the swivel data record: the head axis nearest the bed, else the table axis nearest it.
inline char sin_rotary_axis_1(const ExecMachine& m) {
  return !m.tool_side.empty() ? m.tool_side.front().letter : m.workpiece_side.front().letter;
}

/// The rotary axis whose turn is the last one applied to the tool axis seen in W (its component along
/// that axis does not change when it turns): the table axis farthest from the bed, else the head axis
/// nearest it.
inline const ExecAxis& sin_last_turn(const ExecMachine& m) {
  return !m.workpiece_side.empty() ? m.workpiece_side.back() : m.tool_side.front();
}

/// Every pair of angles of a two-rotary machine whose tool axis in W is `normal` (within the limits
/// given by the machine file's top of travel, symmetric; none: any angle), `current` for a free axis.
inline std::vector<std::map<char, double>> sin_plane_angles(const ExecMachine& m, const ExecJob& job, const V3& normal,
                                                            const std::map<char, double>& current) {
  std::vector<std::map<char, double>> out;
  if (m.rotary_letters.size() != 2) return out;
  const ExecAxis& last = sin_last_turn(m);
  const char other = m.rotary_letters[0] == last.letter ? m.rotary_letters[1] : m.rotary_letters[0];
  const auto axis_at = [&](double other_deg, double last_deg) {
    return forward(m, job, V3::Zero(), {{other, other_deg}, {last.letter, last_deg}}).axis_W;
  };
  const double keep = current.count(last.letter) ? current.at(last.letter) : 0.0;
  // the component along the last axis depends on the other angle only: its roots, 0.5 deg apart, then bisected
  const auto g = [&](double deg) { return axis_at(deg, 0.0).dot(last.direction) - normal.dot(last.direction); };
  std::vector<double> roots;
  for (double a = -180.0; a < 180.0; a += 0.5) {
    double lo = a, hi = a + 0.5;
    if (std::abs(g(lo)) < 1e-13) {
      roots.push_back(lo);
      continue;
    }
    if ((g(lo) > 0) == (g(hi) > 0)) continue;
    for (int k = 0; k < 60; ++k) {
      const double mid = 0.5 * (lo + hi);
      ((g(lo) > 0) == (g(mid) > 0) ? lo : hi) = mid;
    }
    roots.push_back(0.5 * (lo + hi));
  }
  for (double a : roots) {
    const V3 t = axis_at(a, 0.0);
    const V3 tp = t - t.dot(last.direction) * last.direction, np = normal - normal.dot(last.direction) * last.direction;
    std::vector<double> lasts;
    if (tp.norm() < 1e-9 || np.norm() < 1e-9) {
      lasts.push_back(keep);  // the tool axis along the last axis: its angle is free
    } else {
      const double phi = std::atan2(tp.cross(np).dot(last.direction), tp.dot(np)) * 180.0 / M_PI;
      lasts = {phi, -phi};
    }
    for (double b : lasts)
      if ((axis_at(a, b) - normal).norm() < 1e-9) out.push_back({{other, a}, {last.letter, b}});
  }
  return out;
}

/// The control's choice among sin_plane_angles (the _DIR branch; see the header).
inline std::optional<std::map<char, double>> sin_control_angles(const ExecMachine& m, const ExecJob& job,
                                                                const V3& normal, int dir,
                                                                const std::map<char, double>& current) {
  const char axis1 = sin_rotary_axis_1(m);
  std::optional<std::map<char, double>> best;
  double best_cost = 1e300;
  for (std::map<char, double> c : sin_plane_angles(m, job, normal, current)) {
    double cost = 0.0;
    bool inside = true;
    for (auto& [letter, deg] : c) {
      const ExecAxis& a = m.all_axes.at(letter);
      const double now = current.count(letter) ? current.at(letter) : 0.0;
      if (!a.limit_max) deg = now + std::remainder(deg - now, 360.0);
      inside = inside && (!a.limit_max || std::abs(deg) <= *a.limit_max + 1e-9);
      cost += std::abs(deg - now);
    }
    const double ref = c.at(axis1);
    if (dir != 0 && std::abs(ref) > 1e-9 && (ref > 0) != (dir > 0)) cost += 1e6;  // the other branch: last resort
    if (inside && cost < best_cost) best = c, best_cost = cost;
  }
  return best;
}

/// CYCLE800 (`plane`: its frame Trans(_X0) R Trans(_X1); none: CYCLE800() or a bare CYCLE800, the reset),
/// with the tool tip before it at `tip_W`: the rotary angles (sin_control_angles for the plane's Z,
/// _DIR `dir`) and the words X Y Z where the tool stands in the new frame (the linear axes stand still;
/// _FR `fr` = 1 first takes machine Z to its swivel_retract, without which the words are left as they
/// are: not known). After the reset the words are machine axes again (without TRAORI).
inline void sin_cycle800(const ExecMachine& m, const ExecJob& job, const std::optional<Rt>& plane, int fr, int dir,
                         const V3& tip_W, const V3& shift, bool traori, std::map<char, double>& words) {
  std::map<char, double> rot;
  for (char c : m.rotary_letters) rot[c] = words[c];
  V3 machine = machine_xyz_for_tip(m, job, tip_W, rot);
  const auto set_xyz = [&](const V3& p) { words['X'] = p.x(), words['Y'] = p.y(), words['Z'] = p.z(); };
  if (!plane) {
    if (!traori) set_xyz(machine - shift);
    return;
  }
  bool known = true;
  if (fr == 1) {
    const std::optional<double> retract = m.all_axes.count('Z') ? m.all_axes.at('Z').swivel_retract : std::nullopt;
    if (retract)
      machine.z() = *retract;
    else
      known = false;  // the retraction position is the control's: where the tool stands is not known
  }
  const std::optional<std::map<char, double>> angles = sin_control_angles(m, job, plane->R * V3::UnitZ(), dir, rot);
  if (!angles) return;
  for (const auto& [c, deg] : *angles) words[c] = deg, rot[c] = deg;
  if (known) set_xyz(plane->inverse() * forward(m, job, machine, rot).tip_W - shift);
}

}  // namespace ncpost::test
