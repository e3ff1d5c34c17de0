// SPDX-License-Identifier: Apache-2.0
#pragma once
// Editing test inputs: one change to a reviewed text (a machine file, a dialect file).
#include <catch2/catch.hpp>

#include <string>

namespace ncpost::test {

/// `text` with its first `from` replaced by `to` (REQUIREs that `from` occurs, so that a test
/// whose edit no longer applies fails instead of testing the unedited text).
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

}  // namespace ncpost::test
