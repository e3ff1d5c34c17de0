// SPDX-License-Identifier: Apache-2.0
#include "ncpost/machines/input_error.hpp"

namespace ncpost {

// Appended piece by piece: GCC 12 warns (-Wstringop-overflow, a false positive) on the inlined
// `":" + std::to_string(n)` of the header version in every unit that throws an InputError.
std::string InputError::format(const SourcePosition& w, const std::string& what) {
  std::string s = w.file;
  if (w.line > 0) s.append(":").append(std::to_string(w.line));
  if (w.column > 0) s.append(":").append(std::to_string(w.column));
  return s.append(": ").append(what);
}

}  // namespace ncpost
