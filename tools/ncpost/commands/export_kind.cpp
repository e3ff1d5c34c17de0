// SPDX-License-Identifier: Apache-2.0
// Which entry of export's per-kind table a run takes (kind_steps.hpp export_kind).
#include "kind_steps.hpp"
#include "ncpost/compensation/model_json.hpp"
#include "ncpost/kinematics/trr_xy_geometry.hpp"

namespace ncpost::cli {

MachineKind export_kind(const ExportArgs& args) {
  if (!args.machine.empty()) return machine_kind(args.machine);
  comp::ModelFile model;
  try {
    model = comp::read_model_json(args.model, nullptr);
  } catch (const InputError&) {
    return MachineKind::serial;  // the serial steps say what is wrong with the file, as they always did
  }
  const auto& names = model.parameters.names();
  if (names.empty()) return MachineKind::serial;
  for (const std::string& n : names)
    if (trr::Errors::index_of(n) < 0) return MachineKind::serial;
  return MachineKind::trr_xy;
}

}  // namespace ncpost::cli
