// SPDX-License-Identifier: Apache-2.0
// Coordinates written without a decimal point (see gcode_integer_words.hpp).
#include "ncpost/postproc/read/gcode/gcode_integer_words.hpp"

#include <fmt/format.h>

#include <cmath>

#include "read/char_scan.hpp"

namespace ncpost::gcode {
namespace {

/// IS-B, the least input increment of most Fanuc mills: 0.001 mm and deg, 0.0001 in.
constexpr double kIncrementMmOrDeg = 0.001;
constexpr double kIncrementInch = 0.0001;

bool is_angle(char letter) { return letter == 'A' || letter == 'B' || letter == 'C'; }

}  // namespace

double in_least_increments(double units_value, char letter, bool inch) {
  return units_value * (inch && !is_angle(letter) ? kIncrementInch : kIncrementMmOrDeg);
}

std::string written_word(std::string_view line, const Word& word) {
  std::size_t at = static_cast<std::size_t>(word.column);  // just after the letter (1-based column)
  while (at < line.size() && (line[at] == ' ' || line[at] == '\t')) ++at;
  std::size_t end = at;
  while (end < line.size() && (is_digit(line[end]) || line[end] == '.' || line[end] == '-' || line[end] == '+')) ++end;
  return std::string(1, word.letter) + std::string(line.substr(at, end - at));
}

std::optional<IntegerWordEvidence::Refusal> IntegerWordEvidence::note(const Block& block, std::string_view line,
                                                                      const std::string& file, int line_number,
                                                                      bool dwell) {
  for (const Word& w : block.words) {
    if (kIntegerWordLetters.find(w.letter) == std::string_view::npos || (dwell && w.letter == 'X')) continue;
    const bool with_point = w.has_point && w.value == std::floor(w.value) && !block.computed;
    const bool without_point = !w.has_point && w.value != 0.0;
    if (with_point && !with_point_.line) with_point_ = {written_word(line, w), file, line_number};
    if (without_point && !without_point_.line) without_point_ = {written_word(line, w), file, line_number};
    if (!(with_point && without_point_.line) && !(without_point && with_point_.line)) continue;
    const Seen& other = with_point ? without_point_ : with_point_;
    const std::string& bare = without_point_.word;
    const double units = std::stod(bare.substr(1));
    return Refusal{
        w.column,
        fmt::format("{} {}, and {} at {}:{} {}: a Fanuc with parameter DPI = 0 reads {} as {:g} least input "
                    "increments ({:g} {}), LinuxCNC, grbl, Haas and a Fanuc with DPI = 1 as {:g} {}; say which with "
                    "--integer-words increments or --integer-words units, or write the number with a decimal point",
                    written_word(line, w),
                    with_point ? "is a whole number written with a decimal point" : "has no decimal point", other.word,
                    other.file, other.line, with_point ? "has none" : "is a whole number written with one", bare, units,
                    in_least_increments(units, bare[0], false), is_angle(bare[0]) ? "deg" : "mm under G21", units,
                    is_angle(bare[0]) ? "deg" : "mm or in")};
  }
  return std::nullopt;
}

}  // namespace ncpost::gcode
