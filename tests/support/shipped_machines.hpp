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

}  // namespace ncpost::test
