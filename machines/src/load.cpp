// SPDX-License-Identifier: Apache-2.0
#include "ncpost/machines/load.hpp"

#include "ncpost/machines/machine_file.hpp"
#include "ncpost/machines/trr_xy_file.hpp"
#include "toml_reading.hpp"

namespace ncpost::machines {
namespace {

/// One kind of machine file: its name in [machine] kind and the parser of its kinematics.
struct Kind {
  const char* name;
  MachineKinematics (*parse)(const std::string& text, const std::string& file_name);
};

/// The registry; the first row is the default kind.
const Kind kKinds[] = {
    {"serial",
     [](const std::string& text, const std::string& file) -> MachineKinematics { return parse_machine(text, file); }},
    {"trr-xy",
     [](const std::string& text, const std::string& file) -> MachineKinematics {
       return parse_trr_xy_machine(text, file);
     }},
};

const Kind& kind_named(const std::string& name) {
  for (const Kind& k : kKinds)
    if (name == k.name) return k;
  return kKinds[0];
}

}  // namespace

std::vector<std::string> kinds() {
  std::vector<std::string> names;
  for (const Kind& k : kKinds) names.emplace_back(k.name);
  return names;
}

std::string kind_of(const std::string& path) { return kind_named(machine_file_kind(path)).name; }

LoadedMachine load(const std::string& path) {
  const Kind& kind = kind_named(machine_file_kind(path));
  return {kind.name, kind.parse(toml_reading::read_text(path), path)};
}

}  // namespace ncpost::machines
