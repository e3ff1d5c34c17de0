// SPDX-License-Identifier: Apache-2.0
#pragma once
// Misspelt options and subcommands: "unknown option --tolerence; did you mean --tolerance?"
// instead of the misspelt word being taken for a value or a file.
#include <CLI/CLI.hpp>

#include <string>

namespace ncpost::cli {

/// The first unknown subcommand or long option of argv, with the closest known name, as a message
/// ("" when every name is known). Looks at argv before parsing; stops at "--".
std::string misspelt_option(const CLI::App& app, int argc, const char* const* argv);

}  // namespace ncpost::cli
