// SPDX-License-Identifier: Apache-2.0
#pragma once
// The location errors of a table-table machine as the entries of a Heidenhain TNC kinematics
// description that KinematicsOpt (touch probe cycle 451) adjusts: the position of each rotary
// axis (the transformations before its MachAxis entry) and its orientation (issue 25 item 2;
// `ncpost export --format heidenhain`). A table for the user to enter, not a file the control reads.
//
// The description is a chain of entries read from the machine base towards the table (KEY, AXIS,
// COORD): `Trans X|Y|Z v` shifts the following entries by v mm, `Trans A|B|C v` turns them by v
// degrees right-handed about X|Y|Z, `MachAxis A|B|C` turns them by the axis's command about X|Y|Z.
// For a table-table machine with rotary axis 1 (nearer the bed) and axis 2 (carried by 1), with p1,
// p2 a point of each actual line and R1, R2 the turns taking the nominal axis direction to the
// actual one (a turn about the first and then the second axis perpendicular to it, cyclic order:
// for C about X then Y; for A about Y then Z; for B about Z then X):
//   Trans p1 · R1 · MachAxis 1 · R1⁻¹ · Trans (p2 − p1) · R2 · MachAxis 2 · R2⁻¹ · Trans (−p2)
// which is M_T_table(q1, q2) = Trans(p1) Rot(d1, q1) Trans(−p1) Trans(p2) Rot(d2, q2) Trans(−p2),
// the actual lines of the model (export_machine.hpp corrected_machine), tilts included; the last
// entry makes the table frame the machine frame at home (the preset holds the workpiece). The
// linear axes keep their own entries and are not listed. Lengths in mm in ncpost's machine frame M,
// angles in degrees. The rotary axes must turn the table about ±X, ±Y or ±Z (the machine file's
// nominal directions); otherwise ExportRefusal. An axis along −X, −Y or −Z (e.g. the Haas UMC-750's
// B along −Y, C along −Z) is the MachAxis turned half a turn by its first orientation entry (nominal
// 180°; the CHANGE column is the difference from it).
// KinematicsOpt measures a line's position perpendicular to it (not along it) and its orientation:
// the entries are marked so. Functions of position (tables, harmonics, coupled terms), squareness and
// reversal are not held and are listed with their effect (kinematics_left_out.hpp).
#include <string>
#include <vector>

#include "ncpost/compensation/export_linuxcnc.hpp"
#include "ncpost/compensation/kinematics_left_out.hpp"

namespace ncpost::comp {

struct HeidenhainEntry {
  std::string key;       ///< "MachBase", "Trans", "MachAxis"
  char axis = ' ';       ///< X Y Z (mm) or A B C (deg; for MachAxis the machine axis)
  double coord = 0.0;    ///< mm or degrees
  double nominal = 0.0;  ///< the entry on the nominal machine
  std::string role;      ///< "position of A (perpendicular: KinematicsOpt)", ...
};

struct HeidenhainKinematics {
  char axis1 = '?', axis2 = '?';
  std::vector<HeidenhainEntry> entries;
  std::vector<std::string> held;
  LeftOut left_out;
};

/// The entries of `model`'s machine. Throws ExportRefusal when it is not a table-table machine with
/// rotary axes along ±X, ±Y or ±Z, or the model has no location error.
HeidenhainKinematics heidenhain_kinematics(const MachineModel& model);

/// The table as text: `;` notes (convention, held, left out with effects), then one line per entry
/// `NR KEY AXIS COORD NOMINAL CHANGE ROLE` (change in µm or µrad).
std::string format_heidenhain(const HeidenhainKinematics& k, const MachineModel& model, const ExportSource& source);

}  // namespace ncpost::comp
