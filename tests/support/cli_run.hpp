// SPDX-License-Identifier: Apache-2.0
#pragma once
// Running the ncpost executable from tests: the exit code, with stdout and stderr in a log file.
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>

namespace ncpost::test {

/// `ncpost ARGS > LOG 2>&1`; the exit code (-1 if it did not exit normally).
inline int run_ncpost(const std::string& args, const std::string& log) {
  const int rc = std::system((std::string(NCPOST_BINARY) + " " + args + " > " + log + " 2>&1").c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

/// The whole text of a file ("" if it cannot be read).
inline std::string read_text_file(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

}  // namespace ncpost::test
