#pragma once
// Atomic output (cli.md): the text goes to a temporary file beside the target, which is renamed
// into place only when complete, so a failed run never leaves partial output.
#include <string>

namespace ncpost::comp {

/// Writes `text` to `path` atomically; throws std::runtime_error naming the path on failure.
void write_file_atomic(const std::string& path, const std::string& text);

}  // namespace ncpost::comp
