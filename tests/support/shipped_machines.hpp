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

/// machines/head-table-bc.toml: a B head about Y and a C table (X -800 .. 800, Z -700 .. 500 mm).
inline const Machine& head_table_bc() {
  static const Machine m = load_machine(source("machines/head-table-bc.toml"));
  return m;
}

/// tests/data/machines/ac-trunnion-references.toml: the AC trunnion with reference points (G28,
/// G53: X -400, Y 450, Z 550, A 0, C 0; G30: X 300, Y -200, Z 400, A -90).
inline const Machine& ac_trunnion_references() {
  static const Machine m = load_machine(data("machines/ac-trunnion-references.toml"));
  return m;
}

}  // namespace ncpost::test
