// SPDX-License-Identifier: Apache-2.0
#pragma once
// A temporary folder of its own for a test that writes files, and writing a text file there.
#include <cstdlib>
#include <fstream>
#include <string>

namespace ncpost::test {

/// A new folder /tmp/<prefix>_XXXXXX (created; "." if that fails).
inline std::string make_temp_dir(const std::string& prefix) {
  std::string pattern = "/tmp/" + prefix + "_XXXXXX";
  const char* dir = mkdtemp(pattern.data());
  return dir ? std::string(dir) : std::string(".");
}

/// Writes `text` to `path`; returns `path`.
inline std::string write_text_file(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

}  // namespace ncpost::test
