// ncpost: CNC post-processor with error compensation for five-axis machine tools.
#include <fmt/format.h>

#include <cstdio>

#include "commands.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/version.hpp"

int main(int argc, char** argv) {
  CLI::App app{"ncpost: five-axis CNC post-processor with nonlinear-error and geometric-error compensation"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "ncpost " + ncpost::version());
  ncpost::cli::Action action;
  ncpost::cli::add_post(app, action);
  ncpost::cli::add_preview(app, action);
  ncpost::cli::add_identify(app, action);
  ncpost::cli::add_simulate(app, action);
  ncpost::cli::add_plan(app, action);
  ncpost::cli::add_sensitivity(app, action);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 1;
  }
  try {
    return action ? action() : 1;
  } catch (const ncpost::InputError& e) {
    fmt::print(stderr, "ncpost: error: {}\n", e.what());
    if (!e.source_line().empty()) {
      fmt::print(stderr, "  {}\n", e.source_line());
      if (e.where().column > 0) fmt::print(stderr, "  {:>{}}\n", "^", e.where().column);
    }
    return 2;
  } catch (const ncpost::cli::UsageError& e) {
    fmt::print(stderr, "ncpost: usage error: {}\n", e.what());
    return 1;
  } catch (const ncpost::Infeasible& e) {
    fmt::print(stderr, "ncpost: infeasible: {}\n", e.what());
    return 3;
  } catch (const std::exception& e) {
    fmt::print(stderr, "ncpost: internal error: {}\n", e.what());
    return 4;
  }
}
