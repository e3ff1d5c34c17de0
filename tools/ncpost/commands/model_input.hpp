// SPDX-License-Identifier: Apache-2.0
#pragma once
// A model JSON for a command (post, preview, simulate): read, checked against the machine
// (machine name, axes, plausible values; compensation/README.md "Model checks"), and with
// --force the overridden checks printed as warnings.
#include <string>

#include <CLI/CLI.hpp>

#include "ncpost/compensation/model_json.hpp"

namespace ncpost::cli {

/// Adds `--force` (accept a model of another machine or with implausible values) to `sub`.
void add_model_force_option(CLI::App& sub, bool& force);

/// The model of `path` for `machine`; InputError on a failed check unless `force` (then warnings on stderr).
comp::ModelFile read_model_for(const std::string& path, const Machine& machine, bool force);

}  // namespace ncpost::cli
