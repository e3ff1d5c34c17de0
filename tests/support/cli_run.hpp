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

/// What one `ncpost post` run left: its exit code, the written program ("" when none) and its log.
struct PostRun {
  int exit_code = -1;
  std::string program;  ///< the written program ("" when none)
  std::string log;      ///< stdout and stderr
};

/// `ncpost post ARGS -o OUT INPUT > LOG 2>&1`; the exit code, the program at OUT and the log.
inline PostRun run_post(const std::string& args, const std::string& input, const std::string& out,
                        const std::string& log) {
  PostRun r;
  r.exit_code = run_ncpost("post " + args + " -o " + out + " " + input, log);
  r.program = read_text_file(out);
  r.log = read_text_file(log);
  return r;
}

}  // namespace ncpost::test
