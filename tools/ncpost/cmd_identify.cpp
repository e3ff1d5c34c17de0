#include "commands.hpp"

namespace ncpost::cli {

void add_identify(CLI::App& app, Action& action) {
  add_not_built(app, action, "identify", "Identify geometric errors from measurements", "5");
}

}  // namespace ncpost::cli
