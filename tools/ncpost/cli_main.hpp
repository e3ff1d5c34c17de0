// SPDX-License-Identifier: Apache-2.0
#pragma once
// The ncpost command line as a function: parses argv, runs the chosen subcommand and returns the
// exit code (README "Exit codes"): 0 done, 1 usage, 2 bad input or a file that cannot be read or
// written, 3 infeasible, 4 internal fault (a bug). Messages go to stderr.
namespace ncpost::cli {

int run(int argc, char** argv);

}  // namespace ncpost::cli
