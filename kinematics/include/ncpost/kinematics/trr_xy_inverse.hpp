// SPDX-License-Identifier: Apache-2.0
#pragma once
// Inverse kinematics of the TRR-XY machine (docs/trr-xy.md "Inverse kinematics"): a CL point p
// with tool axis u (in W; the table only translates, so u is also the axis in M) →
// X, Y (table) and U, V, W (sliders of chains a, b, c).
//
// Nominal machine: the plate's tilt is fixed by u and its height by the TCP height
// (TCP_z = workpiece_origin_z + p_z); the 3-PRS parasitic motions — plate x, y and the spin ψ
// about u, with R_p = Rot(e_z × u, ∠(e_z, u))·Rot(e_z, ψ) — follow from the three pin-plane
// constraints S_i·t_i = 0 (Newton on three unknowns). Each slider then follows from its link
// length, taking the root with the pin joint above the ball joint. The table takes up the
// parasitic translation: (X, Y) = (workpiece_origin + p − TCP_M)_xy.
//
// Machine with errors (`--model`, or a calibrated machine file): Newton on the three slider commands so that the actual
// tool axis (forward kinematics with errors, relative to the actual home) is u and the actual TCP height is right,
// starting from the nominal solution; X, Y as above from the actual TCP. Lengths in mm, angles in rad.
#include <optional>
#include <string>

#include "ncpost/kinematics/trr_xy_forward.hpp"

namespace ncpost::trr {

struct InverseOutcome {
  std::optional<Command> command;
  Rigidd machine_T_plate;  ///< the (actual) plate pose: a warm start for forward solves
  std::string failure;     ///< why the point is out of reach (link angle, limits, no convergence)
  bool ok() const { return command.has_value(); }
};

/// Nominal plate pose (with its parasitic x, y, spin) for the unit tool axis `axis` and the TCP
/// height `tcp_z_mm` in M; nullopt with `why` if the pin-plane constraints have no solution.
std::optional<Rigidd> nominal_plate_for(const Geometry& g, const Vec3d& axis, double tcp_z_mm, std::string* why);

/// Slider commands that give the nominal machine this plate pose; nullopt with `why` where a
/// link cannot reach its screw line.
std::optional<Vec3d> nominal_sliders_for(const Geometry& g, const Rigidd& machine_T_plate, std::string* why);

/// Commands that put the tool tip on `cl` (in W) on the machine `k` (nominal or with errors).
/// With `check_limits`, commands outside the X, Y, U, V, W limits are a failure.
InverseOutcome inverse(const Kinematics& k, const ClPoint& cl, const Vec3d& workpiece_origin_mm,
                       bool check_limits = true);

/// Empty if the commands are within the machine's axis limits, else which word is not.
std::string limits_failure(const Machine& m, const Command& c);

}  // namespace ncpost::trr
