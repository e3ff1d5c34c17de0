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

/// The index of the first word of a block's tokens: 1 after a block number ("N{n} ", "{n} ").
std::size_t first_word(const std::vector<std::string>& tokens, const Dialect& dialect) {
  if (!dialect.line_numbers || tokens.empty()) return 0;
  const std::string& f = dialect.numbers.format;
  const std::string prefix = f.substr(0, f.find("{n}"));
  const std::string_view t = tokens[0];
  return t.substr(0, prefix.size()) == prefix && number_of(t.substr(prefix.size())) ? 1 : 0;
}

/// A G word of ISO G-code (its number times ten: G93 is 930) applied to `state` as RS274 means it;
/// false for a G word that is not a motion block's.
bool apply_g_word(long code, WrittenState& state) {
  switch (code) {
    case 0:
      state.motion = WrittenState::Motion::rapid;
      return true;
    case 10:
      state.motion = WrittenState::Motion::linear;
      return true;
    case 20:
      state.motion = WrittenState::Motion::clockwise, state.centre_offset_mm = {};
      return true;
    case 30:
      state.motion = WrittenState::Motion::counter_clockwise, state.centre_offset_mm = {};
      return true;
    case 930:
      state.inverse_time = true, state.feed.reset();
      return true;
    case 940:
      state.inverse_time = false, state.feed.reset();
      return true;
    case 170:
    case 180:
    case 190:
      state.plane = static_cast<int>(code / 10);
      return true;
    default:
      return false;
  }
}

}  // namespace

WrittenBlockReader::WrittenBlockReader(const Dialect& dialect, std::string letters)
    : dialect_(dialect), letters_(std::move(letters)) {}

const WrittenState& WrittenBlockReader::read(std::string_view text) {
  std::vector<std::string> tokens = tokens_of(without_comment(text, dialect_.comments));
  const std::size_t first = first_word(tokens, dialect_);
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
      if (!apply_g_word(std::lround(*v * 10.0), state_)) fail(t);
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
