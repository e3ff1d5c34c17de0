// SPDX-License-Identifier: Apache-2.0
#pragma once
// The location errors of a table-table machine as LinuxCNC's xyzac-trt / xyzbc-trt kinematics
// parameters (issue 25 item 2; `ncpost export --format linuxcnc-trt`).
//
// LinuxCNC (src/emc/kinematics/trtfuncs.c, trtfuncs_math.h; man 9 kins) models a tilting table
// (A about X, or B about Y) carrying a rotary table C about Z, with HAL pins (all mm, in joint
// coordinates, which are ncpost's commands X Y Z: the tip in M with the table at home):
//   x-rot-point, y-rot-point, z-rot-point   a point of the C line
//   y-offset, z-offset (xyzac)               the A line passes through (·, y-rot-point + y-offset,
//                                            z-rot-point + z-offset)
//   x-offset, z-offset (xyzbc)               the B line passes through (x-rot-point + x-offset, ·,
//                                            z-rot-point + z-offset)
//   tool-offset                              the tool length (LinuxCNC nets it to the tool offset)
//   conventional-directions                  0 (default): a positive command turns the table
//                                            right-handed about +X/+Y and +Z (ncpost directions
//                                            [1,0,0]/[0,1,0] and [0,0,1]); 1: about -X/-Y and -Z
// The pivots of the model (the line offsets EY0A, EZ0A / EX0B, EZ0B and EX0C, EY0C, a point of each
// actual line: P + δ⊥) are written there exactly. The kinematics assume the A (B) line along X (Y),
// the C line along Z and zero positions at 0: the tilts (EB0A, EC0A, EA0C, EB0C, ...) and zero
// errors (EA0A, EC0C) cannot be held, nor any function of position; each is listed with its effect
// on the workpiece (kinematics_left_out.hpp). A zero error could go to the joint's HOME_OFFSET in
// the INI file instead; this export does not write INI files.
#include <string>
#include <vector>

#include "ncpost/compensation/export_linuxcnc.hpp"
#include "ncpost/compensation/kinematics_left_out.hpp"

namespace ncpost::comp {

struct TrtKinematics {
  std::string module;         ///< "xyzac-trt-kins" or "xyzbc-trt-kins"
  char tilt_letter = 'A';     ///< A or B
  bool conventional = false;  ///< conventional-directions
  double x_rot_point_mm = 0.0, y_rot_point_mm = 0.0, z_rot_point_mm = 0.0;
  double x_offset_mm = 0.0, y_offset_mm = 0.0, z_offset_mm = 0.0;  ///< the one the module ignores is 0
  std::vector<std::string> held;                                   ///< parameter names written into the pins
  LeftOut left_out;
};

/// The parameters of `model`'s machine with its line offsets. Throws ExportRefusal when the machine
/// is not an AC or BC table-table machine with the axis directions LinuxCNC's trt kinematics take,
/// or when the model has no location error.
TrtKinematics linuxcnc_trt_kinematics(const MachineModel& model);

/// The HAL file: `#` notes (sign convention, held, left out with effects) and `setp` lines.
std::string format_linuxcnc_trt(const TrtKinematics& k, const MachineModel& model, const ExportSource& source);

}  // namespace ncpost::comp
