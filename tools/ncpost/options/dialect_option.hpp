// SPDX-License-Identifier: Apache-2.0
#pragma once
// The --dialect option of the commands that write NC programs: a built-in dialect name or the path
// of a dialect file (postproc/dialect.hpp dialect_named).
#include <CLI/CLI.hpp>

namespace ncpost::cli {

/// Accepts a built-in dialect name, or a path (with a '/' or ending in .toml); else says what is expected.
CLI::Validator dialect_name_or_path();

}  // namespace ncpost::cli
