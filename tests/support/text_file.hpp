// SPDX-License-Identifier: Apache-2.0
#pragma once
// Reading a whole file in a test.
#include <fstream>
#include <sstream>
#include <string>

namespace ncpost::test {

/// The whole text of a file, bytes as they are ("" if it cannot be read).
inline std::string read_text_file(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

}  // namespace ncpost::test
