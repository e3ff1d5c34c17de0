// SPDX-License-Identifier: Apache-2.0
#include "model_input.hpp"

#include <fmt/format.h>

#include <cstdio>

namespace ncpost::cli {

void add_model_force_option(CLI::App& sub, bool& force) {
  sub.add_flag("--force", force,
               "apply a model JSON that names another machine (or none), other axes or implausible values "
               "(compensation/README.md \"Model checks\"); each overridden check is printed as a warning");
}

comp::ModelFile read_model_for(const std::string& path, const Machine& machine, bool force) {
  comp::ModelReadOptions o;
  o.force = force;
  comp::ModelFile f = comp::read_model_json(path, &machine, o);
  for (const auto& w : f.warnings) fmt::print(stderr, "ncpost: warning: {} (applied: --force)\n", w);
  return f;
}

}  // namespace ncpost::cli
