// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/write/nc_text.hpp"

#include <algorithm>
#include <cctype>

namespace ncpost {
namespace {

/// Length of the UTF-8 sequence that starts with `lead` (1 for a stray continuation byte).
std::size_t utf8_length(unsigned char lead) {
  if (lead >= 0xF0 && lead < 0xF8) return 4;
  if (lead >= 0xE0) return lead < 0xF0 ? 3 : 1;
  if (lead >= 0xC2) return 2;
  return 1;
}

}  // namespace

std::string nc_comment_text(std::string_view text, const Dialect& dialect) {
  const CommentRules& rules = dialect.comment_rules;
  std::string out;
  out.reserve(std::min(text.size(), rules.max_chars + 3));
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x80) {  // one '?' per character (code point), whatever its bytes
      std::size_t n = utf8_length(c);
      std::size_t k = 1;
      while (k < n && i + k < text.size() && (static_cast<unsigned char>(text[i + k]) & 0xC0) == 0x80) ++k;
      out.push_back('?');
      i += k;
      continue;
    }
    char ch = c < 0x20 || c == 0x7F ? ' ' : static_cast<char>(c);
    if (const auto at = rules.replaced.find(ch); at != std::string::npos) ch = rules.replacements[at];
    out.push_back(ch);
    ++i;
  }
  if (out.size() > rules.max_chars) {  // keep both ends: a path's folder and its file name
    const std::size_t head = (rules.max_chars - 3) / 2;
    const std::size_t tail = rules.max_chars - 3 - head;
    out = out.substr(0, head) + "..." + out.substr(out.size() - tail);
  }
  return out;
}

std::string nc_program_name(std::string_view name, const Dialect& dialect) {
  const CommentRules& rules = dialect.comment_rules;
  std::string out;
  for (const char ch : name) {
    const auto c = static_cast<unsigned char>(ch);
    if (out.size() == rules.max_name_chars) break;
    if (c < 0x80 && (std::isalnum(c) || c == '_')) out.push_back(static_cast<char>(std::toupper(c)));
  }
  return out.empty() ? std::string("NCPOST") : out;
}

}  // namespace ncpost
