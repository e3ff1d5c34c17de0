#include "commands.hpp"

namespace ncpost::cli {

void add_simulate(CLI::App& app, Action& action) {
  add_not_built(app, action, "simulate", "Simulate a measurement plan on a machine with errors", "5");
}

}  // namespace ncpost::cli
