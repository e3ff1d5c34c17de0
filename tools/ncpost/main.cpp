// SPDX-License-Identifier: Apache-2.0
// ncpost: CNC post-processor with error compensation for five-axis machine tools.
#include "cli_main.hpp"

int main(int argc, char** argv) { return ncpost::cli::run(argc, argv); }
