// SPDX-License-Identifier: Apache-2.0
#include "read/gcode/gcode_framing.hpp"
#include "read/gcode/gcode_oword.hpp"

#include <fmt/format.h>

#include <cmath>

#include "ncpost/machines/input_error.hpp"
#include "ncpost/postproc/read/gcode/gcode_macro.hpp"
#include "read/char_scan.hpp"

namespace ncpost::gcode {
namespace {

bool is_g(const Word& w, double code) { return w.letter == 'G' && std::abs(w.value - code) < 1e-6; }

/// M2 or M30 in the block.
bool ends_program(const Block& b) {
  for (const Word& w : b.words)
    if (w.letter == 'M' && (w.value == 2.0 || w.value == 30.0)) return true;
  return false;
}

/// The lines of `head` one by one (LF, CRLF or CR ends), the last one only when `complete`.
class HeadLines {
 public:
  HeadLines(std::string_view head, bool complete) : head_(head), complete_(complete) {}
  bool next(std::string_view& line) {
    if (at_ >= head_.size()) return false;
    const std::size_t end = head_.find_first_of("\r\n", at_);
    if (end == std::string_view::npos) {
      if (!complete_) return false;
      line = head_.substr(at_);
      at_ = head_.size();
    } else {
      line = head_.substr(at_, end - at_);
      at_ = end + ((head_[end] == '\r' && end + 1 < head_.size() && head_[end + 1] == '\n') ? 2 : 1);
    }
    if (++number_ == 1 && line.substr(0, 3) == "\xEF\xBB\xBF") line.remove_prefix(3);
    return true;
  }
  int number() const { return number_; }
  bool exhausted() const { return at_ >= head_.size(); }

 private:
  std::string_view head_;
  bool complete_;
  std::size_t at_ = 0;
  int number_ = 0;
};

constexpr std::string_view kListing = "Information listing";

}  // namespace

bool has_motion_words(const Block& block, std::string_view axis_letters) {
  for (const Word& w : block.words)
    if (is_g(w, 4.0) || is_g(w, 10.0)) return false;
  for (const Word& w : block.words)
    if (axis_letters.find(w.letter) != std::string_view::npos) return true;
  return false;
}

namespace {

/// What the lines before the first '%' hold.
struct BeforePercent {
  int content_lines = 0, motion_line = 0, percent_line = 0;
  bool not_gcode = false, ended = false;
  int listing_line = 0, listing_column = 0;  ///< NX's "Information listing" header
  std::string listing_text;
};

BeforePercent scan_to_percent(HeadLines& lines, const std::string& file, std::string_view axis_letters) {
  BeforePercent h;
  std::string_view line;
  Block block;
  while (lines.next(line)) {
    if (is_percent_line(line)) {
      h.percent_line = lines.number();
      break;
    }
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string_view::npos) continue;
    if (h.content_lines++ == 0 && line.substr(first, kListing.size()) == kListing) {
      h.listing_line = lines.number();
      h.listing_column = static_cast<int>(first) + 1;
      h.listing_text = std::string(line);
    }
    try {
      parse_block(line, block, file, lines.number());
      if (!h.motion_line && has_motion_words(block, axis_letters)) h.motion_line = lines.number();
      h.ended = h.ended || ends_program(block);
    } catch (const InputError&) {
      // a macro statement may move (X#1), an o-word statement calls or loops over blocks that may:
      // counted as a motion, never skipped as a leader
      if (may_hold_macro(line) || read_o_word(line))
        h.motion_line = h.motion_line ? h.motion_line : lines.number();
      else
        h.not_gcode = true;
    }
  }
  return h;
}

/// The first line with a motion after the '%' before the next '%' (0: none, or text that is no G-code).
int motion_after_percent(HeadLines& lines, const std::string& file, std::string_view axis_letters) {
  std::string_view line;
  Block block;
  while (lines.next(line)) {
    if (is_percent_line(line)) return 0;
    try {
      parse_block(line, block, file, lines.number());
      if (has_motion_words(block, axis_letters)) return lines.number();
    } catch (const InputError&) {
      if (!may_hold_macro(line) && !read_o_word(line))
        return 0;  // not G-code after the '%': text after the closing '%'
      return lines.number();
    }
  }
  return 0;
}

}  // namespace

Leader find_leader(std::string_view head, bool complete, const std::string& file, std::string_view axis_letters) {
  HeadLines lines(head, complete);
  const BeforePercent h = scan_to_percent(lines, file, axis_letters);
  if (h.listing_line && !h.percent_line)
    throw InputError({file, h.listing_line, h.listing_column},
                     "an NX 'Information listing' (the listing window of NX saved into a file) with no program "
                     "framed by '%' after it: what it holds is NX's listing, not a program as NX's post wrote it; "
                     "post the program file NX's post processor wrote, or the CL data",
                     h.listing_text);
  if (h.listing_line)
    return {h.percent_line - 1,
            fmt::format("{}:{}: an NX 'Information listing' header ({} line(s) before the opening '%' at line {}) is "
                        "skipped: the program NX's post wrote follows it",
                        file, h.listing_line, h.percent_line - 1, h.percent_line)};
  if (!h.percent_line || h.content_lines == 0) return {};
  if (h.not_gcode || !h.motion_line)
    return {h.percent_line - 1,
            fmt::format("{}:1: {} line(s) before the opening '%' at line {} are a leader ({}), skipped as the "
                        "control skips what precedes the first '%'",
                        file, h.percent_line - 1, h.percent_line, h.not_gcode ? "not G-code" : "no motion in them")};
  if (h.ended) return {};  // `... M30 / %`: the '%' closes the program
  // motions before the first '%': it closes the program unless more motions follow it
  const int motion_after = motion_after_percent(lines, file, axis_letters);
  if (!motion_after) return {};
  throw InputError({file, h.percent_line, 1},
                   fmt::format("motions stand both before this '%' (line {}) and after it (line {}): a control skips "
                               "what precedes the opening '%' (a leader), so the program would be only the part after "
                               "it; remove the lines before the '%' (a leader) or this '%' (a program that ends here)",
                               h.motion_line, motion_after));
}

}  // namespace ncpost::gcode
