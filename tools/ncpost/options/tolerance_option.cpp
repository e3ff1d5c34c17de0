// SPDX-License-Identifier: Apache-2.0
#include "tolerance_option.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "commands.hpp"
#include "ncpost/machines/machine_record.hpp"

namespace ncpost::cli {

comp::Tolerances tolerances_from(const std::string& option_text, const std::string& machine_file) {
  comp::Tolerances given;
  try {
    given = comp::parse_tolerances(option_text);
  } catch (const std::invalid_argument& e) {
    throw UsageError(fmt::format("--tolerance: {}", e.what()));
  }
  comp::Tolerances out;
  out.by_kind_um = load_machine_record(machine_file).tolerances_um;
  for (const auto& [kind, um] : given.by_kind_um) out.by_kind_um[kind] = um;
  return out;
}

}  // namespace ncpost::cli
