// SPDX-License-Identifier: Apache-2.0
#include "ncpost/machines/input_error.hpp"

#include "ncpost/machines/formatters.hpp"

namespace ncpost {

std::string InputError::format(const SourcePosition& w, const std::string& what) {
  return fmt::format("{}: {}", w, what);  // (out of line: no fmt in the header)
}

}  // namespace ncpost
