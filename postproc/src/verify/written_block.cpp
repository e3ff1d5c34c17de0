// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/verify/written_block.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace ncpost {
namespace {

/// The block without its comment (parentheses, or from ';' on).
std::string without_comment(std::string_view text, Dialect::Comments style) {
  std::string out;
  int depth = 0;
  for (char c : text) {
    if (style == Dialect::Comments::semicolon && c == ';') break;
    if (style == Dialect::Comments::parentheses && c == '(')
      ++depth;
    else if (style == Dialect::Comments::parentheses && c == ')')
      depth = std::max(0, depth - 1);
    else if (depth == 0)
      out += c;
  }
  return out;
}

std::vector<std::string> tokens_of(const std::string& text) {
  std::vector<std::string> out;
  std::string t;
  for (char c : text) {
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
      if (!t.empty()) out.push_back(std::move(t));
      t.clear();
    } else {
      t += c;
    }
  }
  if (!t.empty()) out.push_back(std::move(t));
  return out;
}

std::optional<double> number_of(std::string_view s) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  double v = 0.0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ec != std::errc() || r.ptr != s.data() + s.size()) return std::nullopt;
  return v;
}

}  // namespace

WrittenBlockReader::WrittenBlockReader(const Dialect& dialect, std::string letters)
    : dialect_(dialect), letters_(std::move(letters)) {}

const WrittenState& WrittenBlockReader::read(std::string_view text) {
  std::vector<std::string> tokens = tokens_of(without_comment(text, dialect_.comments));
  std::size_t first = 0;
  if (dialect_.line_numbers && !tokens.empty()) {  // the block number ("N{n} ", "{n} ")
    const std::string& f = dialect_.numbers.format;
    const std::string prefix = f.substr(0, f.find("{n}"));
    const std::string_view t = tokens[0];
    if (t.substr(0, prefix.size()) == prefix && number_of(t.substr(prefix.size()))) first = 1;
  }
  // the control's language, not the dialect file's words: Klartext (L for every straight move)
  // or ISO G-code, whose G0 G1 G2 G3 G93 G94 G17-G19 mean what RS274 says whatever the file wrote
  const bool klartext = dialect_.motion.rapid == dialect_.motion.linear;
  bool straight = false, rapid_feed = false;
  auto fail = [&](const std::string& t) {
    throw std::runtime_error(fmt::format("the word '{}' of the written block '{}' is not a motion block's word of {}",
                                         t, text, klartext ? "Klartext" : "ISO G-code"));
  };
  for (std::size_t k = first; k < tokens.size(); ++k) {
    const std::string& t = tokens[k];
    if (klartext && t == "L") {
      straight = true;
      continue;
    }
    if (klartext && t == "FMAX") {
      rapid_feed = true;
      continue;
    }
    const auto v = number_of(std::string_view(t).substr(1));
    if (t.size() < 2 || !v) fail(t);
    const char letter = t[0];
    if (!klartext && letter == 'G') {
      const long code = std::lround(*v * 10.0);
      switch (code) {
        case 0:
          state_.motion = WrittenState::Motion::rapid;
          break;
        case 10:
          state_.motion = WrittenState::Motion::linear;
          break;
        case 20:
          state_.motion = WrittenState::Motion::clockwise, state_.centre_offset_mm = {};
          break;
        case 30:
          state_.motion = WrittenState::Motion::counter_clockwise, state_.centre_offset_mm = {};
          break;
        case 930:
          state_.inverse_time = true, state_.feed.reset();
          break;
        case 940:
          state_.inverse_time = false, state_.feed.reset();
          break;
        case 170:
        case 180:
        case 190:
          state_.plane = static_cast<int>(code / 10);
          break;
        default:
          fail(t);
      }
      continue;
    }
    if (letter == 'F') {
      state_.feed = *v;
      continue;
    }
    if (!klartext && (letter == 'I' || letter == 'J' || letter == 'K')) {
      state_.centre_offset_mm[static_cast<std::size_t>(letter - 'I')] = *v;
      continue;
    }
    if (const auto i = letters_.find(letter); i != std::string::npos) {
      state_.values[i] = *v;
      continue;
    }
    fail(t);
  }
  if (klartext && straight) state_.motion = rapid_feed ? WrittenState::Motion::rapid : WrittenState::Motion::linear;
  return state_;
}

}  // namespace ncpost
