// SPDX-License-Identifier: Apache-2.0
#pragma once
// The location errors of a table-table machine as a SINUMERIK CYCLE800 swivel data record
// (orientable toolholder, kinematic type P) (issue 25 item 2; `ncpost export --format
// siemens-cycle800`).
//
// The record (SINUMERIK Operate commissioning manual, "Swiveling"; programming manual, system
// variables of orientable toolholders): offset vectors l1 $TC_CARR1..3, l2 $TC_CARR4..6, l3
// $TC_CARR15..17, l4 $TC_CARR18..20 (mm, X Y Z components in the machine axes, all taken with the
// rotary axes at 0), rotary axis vectors v1 $TC_CARR7..9 and v2 $TC_CARR10..12, axis names
// $TC_CARR21/22, kinematic type $TC_CARR23. For a swivel table (type P): l2 leads from the machine
// reference point to a point of rotary axis 1 (the one nearer the bed, which carries axis 2), l3
// from there to a point of rotary axis 2, l4 = -(l2 + l3) closes the chain; l1 (the head) is 0.
// The table stands at
//   M_T_table(θ1, θ2) = Trans(l2) · Rot(v1, θ1) · Trans(l3) · Rot(v2, θ2) · Trans(l4)
// and the rotary axis vector is the direction about which a positive command turns the table
// right-handed (Siemens: an axis moving the workpiece reverses the vector of the tool's sense),
// which is ncpost's axis direction.
//
// The actual lines of the model (export_machine.hpp corrected_machine: pivots P + δ⊥, directions
// Rot(ε⊥)·d, zero errors of axis 1 turning axis 2's line) are written exactly: v1 and v2 are free
// directions, so tilts are held. Functions of position (tables, harmonics, coupled terms),
// squareness and reversal are not, and are listed with their effect (kinematics_left_out.hpp).
#include <string>
#include <vector>

#include "ncpost/compensation/export_linuxcnc.hpp"
#include "ncpost/compensation/kinematics_left_out.hpp"

namespace ncpost::comp {

struct Cycle800Record {
  char axis1 = '?', axis2 = '?';  ///< rotary axis 1 (nearer the bed) and 2
  Vec3d l1_mm = Vec3d::Zero(), l2_mm = Vec3d::Zero(), l3_mm = Vec3d::Zero(), l4_mm = Vec3d::Zero();
  Vec3d v1 = Vec3d::UnitX(), v2 = Vec3d::UnitZ();  ///< unit
  std::vector<std::string> held;
  LeftOut left_out;
};

/// The record of `model`'s machine. Throws ExportRefusal when it is not a table-table machine or
/// the model has no location error.
Cycle800Record cycle800_record(const MachineModel& model);

/// The part program lines `$TC_CARRk[1]=value` with `;` notes (convention, held, left out).
std::string format_cycle800(const Cycle800Record& r, const MachineModel& model, const ExportSource& source);

}  // namespace ncpost::comp
