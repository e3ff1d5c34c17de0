// SPDX-License-Identifier: Apache-2.0
#pragma once
// One loader for a machine file of any kind (docs/formats.md "Machine definition", docs/trr-xy.md
// "Machine file"): the [machine] table's `kind` names one row of the registry of kinds
// (machines/src/load.cpp), whose parser reads the file's kinematics — a serial chain (Machine,
// machine_file.hpp) or the TRR-XY hybrid machine (trr::Machine, trr_xy_file.hpp). A file without
// a kind, or of a kind the registry has not, goes to the first row (serial), whose parser refuses
// an unknown kind naming the line. A new kind is a row, its parser and an alternative of
// MachineKinematics; the commands look its steps up by the kind's name (tools/ncpost
// commands/machine_kind.hpp). What the file says beyond the kinematics (serial, owner,
// tolerances) is the same for every kind: machine_record.hpp.
// Every error is an InputError naming the file, the line and what was expected.
#include <string>
#include <variant>
#include <vector>

#include "ncpost/kinematics/machine.hpp"
#include "ncpost/kinematics/trr_xy_geometry.hpp"
#include "ncpost/machines/input_error.hpp"

namespace ncpost::machines {

/// A machine's kinematics, of one of the registry's kinds.
using MachineKinematics = std::variant<Machine, trr::Machine>;

/// A machine file as loaded: its kind (the registry's name) and its kinematics.
struct LoadedMachine {
  std::string kind;  ///< "serial", "trr-xy"
  MachineKinematics kinematics;
};

/// The names of the registry's kinds, the default (a file without a kind) first.
std::vector<std::string> kinds();

/// The registry's kind of the machine file at `path` (its [machine] kind, the default when it has
/// none or one the registry has not). InputError when the file cannot be read or parsed.
std::string kind_of(const std::string& path);

/// The machine file at `path`, of any kind.
LoadedMachine load(const std::string& path);

/// The machine file at `path`, of the kind whose kinematics are T (Machine, trr::Machine): for a
/// kind's own steps, which the commands reach by the kind's name (std::bad_variant_access if the
/// file is of another kind: a programming error).
template <class T>
T load_as(const std::string& path) {
  return std::get<T>(load(path).kinematics);
}

}  // namespace ncpost::machines
