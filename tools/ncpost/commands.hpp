// SPDX-License-Identifier: Apache-2.0
#pragma once
// Subcommands of the ncpost executable, one per file. Each `add_*` registers its subcommand on
// the app and sets `action` to the function that runs it when it is chosen.
// Exit codes (docs/cli.md): 0 done, 1 usage, 2 bad input, 3 infeasible.
#include <CLI/CLI.hpp>

#include <functional>
#include <stdexcept>
#include <string>

#include "ncpost/machines/input_error.hpp"

namespace ncpost::cli {

using Action = std::function<int()>;

/// An expected failure that is not bad input (exit 3): see ncpost::Infeasible.
using Infeasible = ncpost::Infeasible;

/// A usage error found after parsing (conflicting options, bad option value): exit 1.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

void add_post(CLI::App& app, Action& action);
void add_preview(CLI::App& app, Action& action);
void add_identify(CLI::App& app, Action& action);
void add_simulate(CLI::App& app, Action& action);
void add_plan(CLI::App& app, Action& action);
void add_sensitivity(CLI::App& app, Action& action);
void add_export(CLI::App& app, Action& action);
void add_compare(CLI::App& app, Action& action);

/// For subcommands not built yet: registered with --help, and a clear message with exit 1.
void add_not_built(CLI::App& app, Action& action, const std::string& name, const std::string& description,
                   const std::string& issue);

}  // namespace ncpost::cli
