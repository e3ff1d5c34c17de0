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

Leader find_leader(std::string_view head, bool complete, const std::string& file, std::string_view axis_letters) {
  HeadLines lines(head, complete);
  std::string_view line;
  Block block;
  int content_lines = 0, motion_line = 0, percent_line = 0;
  bool not_gcode = false, ended = false;
  int listing_line = 0, listing_column = 0;  // NX's "Information listing" header
  std::string listing_text;
  while (lines.next(line)) {
    if (is_percent_line(line)) {
      percent_line = lines.number();
      break;
    }
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string_view::npos) continue;
    if (content_lines++ == 0 && line.substr(first, kListing.size()) == kListing) {
      listing_line = lines.number();
      listing_column = static_cast<int>(first) + 1;
      listing_text = std::string(line);
    }
    try {
      parse_block(line, block, file, lines.number());
      if (!motion_line && has_motion_words(block, axis_letters)) motion_line = lines.number();
      ended = ended || ends_program(block);
    } catch (const InputError&) {
      // a macro statement may move (X#1), an o-word statement calls or loops over blocks that may:
      // counted as a motion, never skipped as a leader
      if (may_hold_macro(line) || read_o_word(line))
        motion_line = motion_line ? motion_line : lines.number();
      else
        not_gcode = true;
    }
  }
  if (listing_line && !percent_line)
    throw InputError({file, listing_line, listing_column},
                     "an NX 'Information listing' (the listing window of NX saved into a file) with no program "
                     "framed by '%' after it: what it holds is NX's listing, not a program as NX's post wrote it; "
                     "post the program file NX's post processor wrote, or the CL data",
                     listing_text);
  if (listing_line)
    return {percent_line - 1,
            fmt::format("{}:{}: an NX 'Information listing' header ({} line(s) before the opening '%' at line {}) is "
                        "skipped: the program NX's post wrote follows it",
                        file, listing_line, percent_line - 1, percent_line)};
  if (!percent_line || content_lines == 0) return {};
  if (not_gcode || !motion_line)
    return {percent_line - 1,
            fmt::format("{}:1: {} line(s) before the opening '%' at line {} are a leader ({}), skipped as the "
                        "control skips what precedes the first '%'",
                        file, percent_line - 1, percent_line, not_gcode ? "not G-code" : "no motion in them")};
  if (ended) return {};  // `... M30 / %`: the '%' closes the program
  // motions before the first '%': it closes the program unless more motions follow it
  int motion_after = 0;
  while (!motion_after && lines.next(line)) {
    if (is_percent_line(line)) break;
    try {
      parse_block(line, block, file, lines.number());
      if (has_motion_words(block, axis_letters)) motion_after = lines.number();
    } catch (const InputError&) {
      if (!may_hold_macro(line) && !read_o_word(line)) break;  // not G-code after the '%': text after the closing '%'
      motion_after = lines.number();
    }
  }
  if (!motion_after) return {};
  throw InputError({file, percent_line, 1},
                   fmt::format("motions stand both before this '%' (line {}) and after it (line {}): a control skips "
                               "what precedes the opening '%' (a leader), so the program would be only the part after "
                               "it; remove the lines before the '%' (a leader) or this '%' (a program that ends here)",
                               motion_line, motion_after));
}

}  // namespace ncpost::gcode
