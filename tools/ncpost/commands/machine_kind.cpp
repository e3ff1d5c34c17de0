// SPDX-License-Identifier: Apache-2.0
#include "machine_kind.hpp"

#include "ncpost/compensation/model_json.hpp"
#include "ncpost/machines/load.hpp"

namespace ncpost::cli {
namespace {

/// The registry; the first row is the default kind.
const MachineKind kKinds[] = {
    {"serial", nullptr, load_serial_preview, plan_serial, simulate_serial, identify_serial, load_serial_post,
     export_serial},
    {"trr-xy", holds_trr_xy_parameters, load_trr_xy_preview, plan_trr_xy, simulate_trr_xy, identify_trr_xy,
     load_trr_xy_post, export_trr_xy},
};

const MachineKind& default_kind() { return kKinds[0]; }

}  // namespace

const MachineKind& machine_kind(const std::string& path) {
  const std::string name = machines::kind_of(path);
  for (const MachineKind& k : kKinds)
    if (name == k.name) return k;
  return default_kind();
}

const MachineKind& export_kind(const ExportArgs& args) {
  if (!args.machine.empty()) return machine_kind(args.machine);
  comp::ModelFile model;
  try {
    model = comp::read_model_json(args.model, nullptr);
  } catch (const InputError&) {
    return default_kind();  // its steps say what is wrong with the file, as they always did
  }
  const auto& names = model.parameters.names();
  if (names.empty()) return default_kind();
  for (const MachineKind& k : kKinds)
    if (k.holds_parameters && k.holds_parameters(names)) return k;
  return default_kind();
}

}  // namespace ncpost::cli
