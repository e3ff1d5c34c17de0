// SPDX-License-Identifier: Apache-2.0
#pragma once
// Loading machine definitions (TOML, docs/formats.md "Machine definition") with validation.
// Every error is an InputError naming the file, the line and what was expected.
#include <string>

#include "ncpost/kinematics/machine.hpp"
#include "ncpost/machines/input_error.hpp"

namespace ncpost {

/// Parses a machine file's text; `file_name` is used in messages.
Machine parse_machine(const std::string& text, const std::string& file_name);

/// Reads and parses a machine file.
Machine load_machine(const std::string& path);

/// Parses a chain such as "w C' A' Y' b X Z t" into the machine's side lists; `axes` must
/// already hold every axis. Throws InputError(where, ...) on an inconsistent chain.
void assign_chain(Machine& m, const std::string& chain, const SourcePosition& where);

}  // namespace ncpost
