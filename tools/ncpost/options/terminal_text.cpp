// SPDX-License-Identifier: Apache-2.0
#include "terminal_text.hpp"

#include <fmt/format.h>

namespace ncpost::cli {
namespace {

/// Length of the valid UTF-8 sequence at `s[i]` that is not a C1 control, or 0.
std::size_t printable_utf8(std::string_view s, std::size_t i) {
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[i + k]); };
  const unsigned char c = b(0);
  std::size_t n = c >= 0xC2 && c <= 0xDF ? 2 : c >= 0xE0 && c <= 0xEF ? 3 : c >= 0xF0 && c <= 0xF4 ? 4 : 0;
  if (n == 0 || i + n > s.size()) return 0;
  for (std::size_t k = 1; k < n; ++k)
    if ((b(k) & 0xC0) != 0x80) return 0;
  if (c == 0xC2 && b(1) < 0xA0) return 0;   // U+0080..U+009F: C1 controls
  if (c == 0xE0 && b(1) < 0xA0) return 0;   // overlong
  if (c == 0xED && b(1) >= 0xA0) return 0;  // surrogates
  if (c == 0xF0 && b(1) < 0x90) return 0;   // overlong
  if (c == 0xF4 && b(1) >= 0x90) return 0;  // beyond U+10FFFF
  return n;
}

/// Appends the shown form of the character at `s[i]`; returns its length in bytes.
std::size_t append_shown(std::string_view s, std::size_t i, std::string* out, int* width) {
  const auto c = static_cast<unsigned char>(s[i]);
  if (c >= 0x20 && c < 0x7F) {
    if (out) out->push_back(static_cast<char>(c));
    ++*width;
    return 1;
  }
  if (c >= 0x80) {
    if (const std::size_t n = printable_utf8(s, i)) {
      if (out) out->append(s.substr(i, n));
      ++*width;
      return n;
    }
  }
  const std::string e = c == '\n' ? "\\n" : c == '\r' ? "\\r" : c == '\t' ? "\\t" : fmt::format("\\x{:02X}", c);
  if (out) out->append(e);
  *width += static_cast<int>(e.size());
  return 1;
}

}  // namespace

std::string terminal_text(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  int width = 0;
  for (std::size_t i = 0; i < text.size();) i += append_shown(text, i, &out, &width);
  return out;
}

int terminal_column(std::string_view text, int byte_column) {
  int width = 0;
  std::size_t i = 0;
  const std::size_t end = byte_column > 0 ? static_cast<std::size_t>(byte_column - 1) : 0;
  while (i < end && i < text.size()) i += append_shown(text, i, nullptr, &width);
  return width + 1 + static_cast<int>(end > i ? end - i : 0);
}

}  // namespace ncpost::cli
