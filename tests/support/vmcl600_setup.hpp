// SPDX-License-Identifier: Apache-2.0
#pragma once
// The set-up of the three-axis VMCL600 tests (machines/vmcl600.toml, samples/measurements/vmcl600):
// the workpiece origin 450 mm below the spindle's home, a 150 mm tool.
#include "ncpost/kinematics/machine.hpp"

namespace ncpost::test {

inline Setup vmcl600_setup() {
  Setup s;
  s.workpiece_origin_mm = Vec3d(0, 0, -450);
  s.tool_length_mm = 150;
  return s;
}

}  // namespace ncpost::test
