#include "commands.hpp"

namespace ncpost::cli {

void add_preview(CLI::App& app, Action& action) {
  add_not_built(app, action, "preview", "Preview the nonlinear error of every block", "4");
}

}  // namespace ncpost::cli
