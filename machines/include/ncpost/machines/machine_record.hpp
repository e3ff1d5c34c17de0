// SPDX-License-Identifier: Apache-2.0
#pragma once
// What a machine file says about the physical machine beyond its kinematics (issue 25 items 3
// and 4; docs/formats.md "Machine definition"): the optional `serial` and `owner` strings of its
// [machine] table, shown in the identification reports beside the name, and an optional
// [tolerances] table, one acceptance tolerance (µm) per figure kind — ISO 230-2 `A`, `B`, `E`,
// `M`, `R` and ISO 230-4 `G` — for the reports' pass/fail verdicts. Kept out of the kinematic
// Machine, which they do not change.
#include <map>
#include <string>

namespace ncpost {

struct MachineRecord {
  std::string serial;                           ///< the machine's serial number, empty if not given
  std::string owner;                            ///< who owns or runs it, empty if not given
  std::map<std::string, double> tolerances_um;  ///< [tolerances]: kind → µm
};

/// The record keys of a machine file (serial or TRR-XY); InputError at the key if `serial` or
/// `owner` is not a string, or a [tolerances] key is not one of A B E M R G or not a number > 0.
MachineRecord parse_machine_record(const std::string& text, const std::string& file_name);
MachineRecord load_machine_record(const std::string& path);

}  // namespace ncpost
