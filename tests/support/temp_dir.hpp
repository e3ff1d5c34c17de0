// SPDX-License-Identifier: Apache-2.0
#pragma once
// A temporary folder of its own for a test that writes files, and writing a text file there.
// Every folder made here is removed when the test process ends (ctest runs each test case in a
// process of its own), so a test run leaves nothing behind in /tmp.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

namespace ncpost::test {

/// The folders this process made; removed, with their contents, when the process exits.
class TempDirs {
 public:
  TempDirs() = default;
  TempDirs(const TempDirs&) = delete;
  TempDirs& operator=(const TempDirs&) = delete;
  ~TempDirs() {
    for (const std::string& dir : dirs_) {
      std::error_code ignored;
      std::filesystem::remove_all(dir, ignored);
    }
  }
  void add(std::string dir) { dirs_.push_back(std::move(dir)); }

 private:
  std::vector<std::string> dirs_;
};

inline TempDirs& temp_dirs_of_this_process() {
  static TempDirs dirs;
  return dirs;
}

/// A new folder /tmp/<prefix>_XXXXXX (created; "." if that fails), removed when the process ends.
inline std::string make_temp_dir(const std::string& prefix) {
  std::string pattern = "/tmp/" + prefix + "_XXXXXX";
  const char* dir = mkdtemp(pattern.data());
  if (!dir) return ".";
  temp_dirs_of_this_process().add(dir);
  return dir;
}

/// Writes `text` to `path`; returns `path`.
inline std::string write_text_file(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

}  // namespace ncpost::test
