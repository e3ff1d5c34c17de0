// SPDX-License-Identifier: Apache-2.0
#include <fmt/format.h>

#include "commands.hpp"

namespace ncpost::cli {

void add_not_built(CLI::App& app, Action& action, const std::string& name, const std::string& description,
                   const std::string& issue) {
  CLI::App* sub = app.add_subcommand(name, description + " (not built yet)");
  sub->allow_extras();
  sub->callback([&action, name, issue] {
    action = [name, issue] {
      fmt::print(stderr, "ncpost {}: not built yet (planned in issue {})\n", name, issue);
      return 1;
    };
  });
}

}  // namespace ncpost::cli
