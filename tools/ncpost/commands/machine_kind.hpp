// SPDX-License-Identifier: Apache-2.0
#pragma once
// How every subcommand chooses what it does for the machine of --machine: the machine file's kind
// ([machine] kind, machine_file_kind in ncpost/machines/trr_xy_file.hpp) picks one entry of the
// command's table `ByKind<Steps>` (kind_steps.hpp), which holds only the steps that differ between
// kinds (load the machine and its model, solve, fit, plan). Everything else — option checks, file
// safety, atomic outputs, reports, messages — is the command's own code, the same for every kind.
#include <string>

namespace ncpost::cli {

enum class MachineKind { serial, trr_xy };

/// The kind of the machine file at `path`: trr_xy for kind = "trr-xy", else serial (whose loader
/// refuses an unknown kind naming the line). InputError when the file cannot be read or parsed.
MachineKind machine_kind(const std::string& path);

/// The name of the kind as in the machine file ("serial", "trr-xy").
const char* kind_name(MachineKind kind);

/// One entry per machine kind.
template <class Steps> struct ByKind {
  Steps serial;
  Steps trr_xy;
  const Steps& operator[](MachineKind kind) const { return kind == MachineKind::trr_xy ? trr_xy : serial; }
};

}  // namespace ncpost::cli
