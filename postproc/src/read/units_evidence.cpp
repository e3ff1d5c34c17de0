// SPDX-License-Identifier: Apache-2.0
#include "read/units_evidence.hpp"

#include <array>
#include <cctype>
#include <vector>

namespace ncpost::gcode {
namespace {

bool is_number_char(char c) { return std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '/'; }

/// "0.5", ".500", "1/2": a number (digits with a point or a fraction bar).
bool is_number(std::string_view s) {
  bool digit = false;
  for (char c : s) {
    if (!is_number_char(c)) return false;
    digit = digit || std::isdigit(static_cast<unsigned char>(c));
  }
  return digit;
}

/// `token` ends with a number directly followed by `unit` (".500IN", "10MM", "D10MM").
bool number_then(std::string_view token, std::string_view unit) {
  if (token.size() <= unit.size() || token.substr(token.size() - unit.size()) != unit) return false;
  const char before = token[token.size() - unit.size() - 1];
  return std::isdigit(static_cast<unsigned char>(before)) ||
         (before == '.' && is_number(token.substr(0, token.size() - unit.size())));
}

constexpr std::array<std::string_view, 9> kInchWords{"INCH", "INCHES", "IPM", "IPR", "SFM",
                                                     "UNC",  "UNF",    "NPT", "NPTF"};
constexpr std::array<std::string_view, 4> kMetricWords{"MM", "METRIC", "SMM", "MILLIMETER"};

}  // namespace

void UnitsEvidence::scan_comment(std::string_view text, int line) {
  std::vector<std::string> tokens;
  std::string t;
  for (char c : text) {
    const char u = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (std::isalnum(static_cast<unsigned char>(u)) || u == '.' || u == '/' || u == '"') {
      t += u;
    } else if (!t.empty()) {
      tokens.push_back(std::move(t));
      t.clear();
    }
  }
  if (!t.empty()) tokens.push_back(std::move(t));
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    std::string_view s = tokens[i];
    while (!s.empty() && s.back() == '.') s.remove_suffix(1);  // "IN." at the end of a sentence
    const bool after_number = i > 0 && is_number(tokens[i - 1]);
    bool inch = number_then(s, "IN") || number_then(s, "\"") || (after_number && (s == "IN" || s == "\""));
    for (std::string_view w : kInchWords) inch = inch || s == w;
    bool metric = number_then(s, "MM") || (after_number && s == "MM");
    for (std::string_view w : kMetricWords) metric = metric || s == w;
    if (metric) ++metric_words_;
    if (inch && inch_words_++ == 0) {
      first_inch_line_ = line;
      first_inch_word_ = tokens[i];
    }
  }
}

}  // namespace ncpost::gcode
