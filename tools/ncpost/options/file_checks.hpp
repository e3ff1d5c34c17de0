// SPDX-License-Identifier: Apache-2.0
#pragma once
// Checks on the files of a command line, made before anything is computed or written: an output
// must not be one of the inputs nor another output (compared by device and inode, so links and
// other spellings of a path are caught), and must be writable (atomic_file.hpp).
#include <string>
#include <vector>

namespace ncpost::cli {

struct NamedPath {
  std::string option;  ///< "-o", "--report", "INPUT", ...
  std::string path;
};

/// UsageError (exit 1) when an output is an input or another output; FileError (exit 2) when an
/// output cannot be written. Empty paths and "-" are skipped.
void check_files(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs);

}  // namespace ncpost::cli
