// SPDX-License-Identifier: Apache-2.0
#pragma once
// Running the ncpost executable from tests: the exit code, with stdout and stderr in a log file.
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>

#include "text_file.hpp"

namespace ncpost::test {

/// `ncpost ARGS > LOG 2>&1`; the exit code (-1 if it did not exit normally).
inline int run_ncpost(const std::string& args, const std::string& log) {
  const int rc = std::system((std::string(NCPOST_BINARY) + " " + args + " > " + log + " 2>&1").c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

}  // namespace ncpost::test
