#pragma once
// SPDX-License-Identifier: Apache-2.0
// Shipped machine files (machines/*.toml) and the tests' own (tests/data/machines/), read once per
// test program.
#include <map>
#include <string>

#include "ncpost/machines/machine_file.hpp"
#include "test_paths.hpp"

namespace ncpost::test {

/// The machine file at `path`, read on the first call (the map's elements stay where they are).
inline const Machine& machine_read_once(const std::string& path) {
  static std::map<std::string, Machine> read;
  auto it = read.find(path);
  if (it == read.end()) it = read.emplace(path, load_machine(path)).first;
  return it->second;
}

/// machines/ac-trunnion.toml: Z -600 .. 600 mm, A -120 .. 120 deg, C continuous.
inline const Machine& ac_trunnion() { return machine_read_once(source("machines/ac-trunnion.toml")); }

/// machines/vmcl600.toml: the three-axis VMC (X -300 .. 300 mm).
inline const Machine& vmcl600() { return machine_read_once(source("machines/vmcl600.toml")); }

/// machines/head-table-bc.toml: a B head about Y and a C table (X -800 .. 800, Z -700 .. 500 mm).
inline const Machine& head_table_bc() { return machine_read_once(source("machines/head-table-bc.toml")); }

/// tests/data/machines/ac-trunnion-references.toml: the AC trunnion with reference points (G28,
/// G53: X -400, Y 450, Z 550, A 0, C 0; G30: X 300, Y -200, Z 400, A -90).
inline const Machine& ac_trunnion_references() {
  return machine_read_once(data("machines/ac-trunnion-references.toml"));
}

}  // namespace ncpost::test
