// SPDX-License-Identifier: Apache-2.0
#pragma once
// Character and word scanning the readers share (G-code, Klartext, Sinumerik): ASCII only, whatever
// the locale; blanks are spaces and tabs. One definition for all the readers' files, which may be
// compiled in one unit (cmake/ncpost_helpers.cmake, ncpost_unity).
#include <cstddef>
#include <string>
#include <string_view>

namespace ncpost {

inline bool is_digit(char c) { return c >= '0' && c <= '9'; }
inline bool is_alpha(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
inline char upper(char c) { return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c; }

/// `s` in upper case (ASCII letters).
inline std::string upper_of(std::string_view s) {
  std::string u;
  u.reserve(s.size());
  for (const char c : s) u += upper(c);
  return u;
}

/// Moves `at` past the spaces and tabs of `s` from `at`.
inline void skip_blanks(std::string_view s, std::size_t& at) {
  while (at < s.size() && (s[at] == ' ' || s[at] == '\t')) ++at;
}

/// `s` without its leading and trailing spaces and tabs.
inline std::string trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return std::string(s);
}

/// True when the first character of `line` after spaces and tabs is '%' (a tape mark line).
inline bool is_percent_line(std::string_view line) {
  const auto first = line.find_first_not_of(" \t");
  return first != std::string_view::npos && line[first] == '%';
}

/// The letters at `at` (a function or operator name, at most 8), in upper case, not consumed.
inline std::string word_at(std::string_view s, std::size_t at) {
  std::string w;
  while (at < s.size() && is_alpha(s[at]) && w.size() < 8) w += upper(s[at++]);
  return w;
}

}  // namespace ncpost
