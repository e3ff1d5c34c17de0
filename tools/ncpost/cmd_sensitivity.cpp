#include "commands.hpp"

namespace ncpost::cli {

void add_sensitivity(CLI::App& app, Action& action) {
  add_not_built(app, action, "sensitivity", "Sensitivity maps of the TRR-XY machine", "8");
}

}  // namespace ncpost::cli
