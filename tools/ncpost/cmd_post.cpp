#include "commands.hpp"

namespace ncpost::cli {

void add_post(CLI::App& app, Action& action) {
  add_not_built(app, action, "post", "Post-process CL data or G-code into an NC program", "2");
}

}  // namespace ncpost::cli
