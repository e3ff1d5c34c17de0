// SPDX-License-Identifier: Apache-2.0
// The whole ncpost command line (main.cpp calls it; the command-line fuzz target too).
// Exit codes (README "Exit codes"): 0 done, 1 usage, 2 bad input or a file that cannot be read or
// written, 3 infeasible, 4 internal fault (a bug: please report it), 128+N stopped by signal N.
#include <fmt/format.h>

#include <cstdio>
#include <new>

#include "cli_main.hpp"
#include "commands.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/postproc/write/temp_files.hpp"
#include "ncpost/postproc/verify/verify.hpp"
#include "ncpost/version.hpp"
#include "option_spelling.hpp"
#include "terminal_text.hpp"

namespace {

void print_error(const std::string& what) {
  fmt::print(stderr, "ncpost: error: {}\n", ncpost::cli::terminal_text(what));
}

}  // namespace

int ncpost::cli::run(int argc, char** argv) {
  using ncpost::cli::terminal_text;
  CLI::App app{"ncpost: five-axis CNC post-processor with nonlinear-error and geometric-error compensation"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "ncpost " + ncpost::version());
  app.footer(
      "Exit codes: 0 done, 1 usage, 2 bad input or file, 3 infeasible, 4 internal fault (README \"Exit codes\").");
  ncpost::cli::Action action;
  ncpost::cli::add_post(app, action);
  ncpost::cli::add_preview(app, action);
  ncpost::cli::add_identify(app, action);
  ncpost::cli::add_simulate(app, action);
  ncpost::cli::add_plan(app, action);
  ncpost::cli::add_sensitivity(app, action);
  ncpost::cli::add_export(app, action);
  ncpost::cli::add_compare(app, action);
  if (const std::string misspelt = ncpost::cli::misspelt_option(app, argc, argv); !misspelt.empty()) {
    print_error(misspelt);
    return 1;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    print_error(e.what());
    fmt::print(stderr, "Run with --help for more information.\n");
    return 1;
  }
  try {
    return action ? action() : 1;
  } catch (const ncpost::InputError& e) {
    print_error(e.what());
    if (!e.source_line().empty()) {
      fmt::print(stderr, "  {}\n", terminal_text(e.source_line()));
      if (e.where().column > 0)
        fmt::print(stderr, "  {:>{}}\n", "^", ncpost::cli::terminal_column(e.source_line(), e.where().column));
    }
    return 2;
  } catch (const ncpost::FileError& e) {
    print_error(e.what());
    return 2;
  } catch (const ncpost::cli::UsageError& e) {
    print_error(e.what());
    return 1;
  } catch (const ncpost::Infeasible& e) {
    fmt::print(stderr, "ncpost: infeasible: {}\n", terminal_text(e.what()));
    return 3;
  } catch (const ncpost::VerifyFailed& e) {
    fmt::print(stderr, "ncpost: verify failed: {}\n", terminal_text(e.what()));
    return 5;
  } catch (const std::bad_alloc&) {
    print_error("out of memory (internal fault, exit 4: the input may be too large for this machine)");
    return 4;
  } catch (const std::exception& e) {
    fmt::print(stderr, "ncpost: internal error: {} (a fault in ncpost, please report it with the command line)\n",
               terminal_text(e.what()));
    return 4;
  }
}
