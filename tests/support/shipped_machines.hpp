#pragma once
// SPDX-License-Identifier: Apache-2.0
// Shipped machine files (machines/*.toml) read once per test program.
#include "ncpost/machines/machine_file.hpp"
#include "test_paths.hpp"

namespace ncpost::test {

/// machines/ac-trunnion.toml: Z -600 .. 600 mm, A -120 .. 120 deg, C continuous.
inline const Machine& ac_trunnion() {
  static const Machine m = load_machine(source("machines/ac-trunnion.toml"));
  return m;
}

/// machines/vmcl600.toml: the three-axis VMC (X -300 .. 300 mm).
inline const Machine& vmcl600() {
  static const Machine m = load_machine(source("machines/vmcl600.toml"));
  return m;
}

}  // namespace ncpost::test
