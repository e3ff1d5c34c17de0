// SPDX-License-Identifier: Apache-2.0
#include "read/gcode/gcode_oword.hpp"
#include "read/char_scan.hpp"

#include <array>
#include <cctype>

namespace ncpost::gcode {
namespace {

using K = OWord::Keyword;

struct Named {
  std::string_view name;
  K keyword;
};
constexpr std::array<Named, 15> kKeywords{{{"sub", K::sub},
                                           {"endsub", K::endsub},
                                           {"return", K::return_},
                                           {"call", K::call},
                                           {"if", K::if_},
                                           {"elseif", K::elseif},
                                           {"else", K::else_},
                                           {"endif", K::endif},
                                           {"while", K::while_},
                                           {"endwhile", K::endwhile},
                                           {"do", K::do_},
                                           {"repeat", K::repeat},
                                           {"endrepeat", K::endrepeat},
                                           {"break", K::break_},
                                           {"continue", K::continue_}}};

char lower(char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); }
bool is_blank(char c) { return c == ' ' || c == '\t'; }

/// Past a leading '/' and N number.
std::size_t statement_start(std::string_view line) {
  std::size_t at = 0;
  skip_blanks(line, at);
  if (at < line.size() && line[at] == '/') ++at;
  skip_blanks(line, at);
  if (at < line.size() && lower(line[at]) == 'n') {
    std::size_t p = at + 1;
    skip_blanks(line, p);
    const std::size_t digits = p;
    while (p < line.size() && is_digit(line[p])) ++p;
    if (p > digits) {
      at = p;
      skip_blanks(line, at);
    }
  }
  return at;
}

/// The label at `at` (at the 'o'), normalized; `at` moves past it. "" when none.
std::string read_label(std::string_view line, std::size_t& at) {
  std::size_t p = at + 1;
  std::string label = "o";
  if (p < line.size() && line[p] == '<') {
    const std::size_t close = line.find('>', p);
    if (close == std::string_view::npos) return {};
    label += '<';
    for (std::size_t i = p + 1; i < close; ++i)
      if (!is_blank(line[i])) label += lower(line[i]);
    label += '>';
    at = close + 1;
    return label;
  }
  while (p < line.size() && is_digit(line[p])) label += line[p++];
  if (label.size() == 1) return {};
  at = p;
  return label;
}

}  // namespace

std::optional<OWord> read_o_word(std::string_view line) {
  std::size_t at = statement_start(line);
  if (at >= line.size() || lower(line[at]) != 'o') return std::nullopt;
  OWord w;
  w.column = static_cast<int>(at) + 1;
  w.label = read_label(line, at);
  if (w.label.empty()) return std::nullopt;
  skip_blanks(line, at);
  std::string word;
  std::size_t end = at;
  while (end < line.size() && is_alpha(line[end])) word += lower(line[end++]);
  for (const Named& n : kKeywords)
    if (word == n.name) {
      w.keyword = n.keyword;
      w.argument_at = end;
      return w;
    }
  return std::nullopt;
}

std::string_view keyword_name(OWord::Keyword k) {
  for (const Named& n : kKeywords)
    if (n.keyword == k) return n.name;
  return "?";
}

}  // namespace ncpost::gcode
