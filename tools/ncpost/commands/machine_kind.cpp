// SPDX-License-Identifier: Apache-2.0
#include "machine_kind.hpp"

#include "ncpost/machines/trr_xy_file.hpp"

namespace ncpost::cli {

MachineKind machine_kind(const std::string& path) {
  return machine_file_kind(path) == kind_name(MachineKind::trr_xy) ? MachineKind::trr_xy : MachineKind::serial;
}

const char* kind_name(MachineKind kind) { return kind == MachineKind::trr_xy ? "trr-xy" : "serial"; }

}  // namespace ncpost::cli
