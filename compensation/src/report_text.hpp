// SPDX-License-Identifier: Apache-2.0
#pragma once
// Text helpers of the identification reports (identify_report, diagnose_report, laser_report).
// Internal to the compensation library.
#include <string>

namespace ncpost::comp::report {

/// The last component of a path ("data/ballbar.csv" -> "ballbar.csv").
inline std::string base_name(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

/// Text escaped for HTML content (<, >, &).
inline std::string escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '<') o += "&lt;";
    else if (c == '>') o += "&gt;";
    else if (c == '&') o += "&amp;";
    else o += c;
  }
  return o;
}

}  // namespace ncpost::comp::report
