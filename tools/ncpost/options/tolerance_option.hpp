// SPDX-License-Identifier: Apache-2.0
#pragma once
// `--tolerance KIND=UM,...` (identify, compare): one tolerance per figure kind (decision_rule.hpp)
// over the machine file's [tolerances] table, kind by kind.
#include <string>

#include "ncpost/compensation/decision_rule.hpp"

namespace ncpost::cli {

/// The machine file's tolerances with `option_text`'s over them; UsageError (exit 1) naming
/// --tolerance when the text is not KIND=UM,... with known kinds and positive values.
comp::Tolerances tolerances_from(const std::string& option_text, const std::string& machine_file);

}  // namespace ncpost::cli
