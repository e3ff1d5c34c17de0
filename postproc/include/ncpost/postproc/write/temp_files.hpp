// SPDX-License-Identifier: Apache-2.0
#pragma once
// Temporary files that must not outlive the run: the `.tmp.*` file of an output being written and
// the spool of an input read from a pipe. Registered paths are removed when the process is
// stopped by SIGINT, SIGTERM or SIGHUP (the handler then lets the signal end the process as it
// would have); a signal the process ignores (e.g. SIGHUP under nohup) stays ignored.
#include <stdexcept>
#include <string>

namespace ncpost {

/// Removes `path` on SIGINT/SIGTERM/SIGHUP until `forget_temp_file(path)`. Installs the handlers on
/// the first call. At most 64 paths at a time (std::runtime_error beyond).
void remember_temp_file(const std::string& path);
void forget_temp_file(const std::string& path);

/// Thrown for an output or temporary file that cannot be created or written (missing folder, no
/// permission, a device or FIFO at the path, disk full): a user's problem, exit 2, with the reason.
struct FileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace ncpost
