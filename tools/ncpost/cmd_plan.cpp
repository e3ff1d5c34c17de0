#include "commands.hpp"

namespace ncpost::cli {

void add_plan(CLI::App& app, Action& action) {
  add_not_built(app, action, "plan", "Write measurement plans and the NC programs that run them", "5");
}

}  // namespace ncpost::cli
