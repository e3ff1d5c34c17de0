// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/read/gcode/gcode_detect.hpp"

#include <cmath>
#include <sstream>

#include "ncpost/postproc/read/gcode/gcode_block.hpp"
#include "ncpost/postproc/read/line_source.hpp"

namespace ncpost::gcode {
namespace {

bool switches_rtcp_on(const Block& b) {
  for (const BlockKeyword& k : b.keywords)
    if (k.keyword == Keyword::traori) return true;
  for (const Word& w : b.words) {
    if (!(w.value >= 0.0 && w.value < 1e5)) continue;
    const long code10 = std::lround(w.value * 10.0);
    if (w.letter == 'G' && (code10 == 434 || code10 == 435 || code10 == 2340)) return true;
    if (w.letter == 'M' && (code10 == 4280 || code10 == 1280)) return true;
  }
  return false;
}

}  // namespace

bool looks_like_gcode(std::string_view head) {
  std::istringstream in{std::string(head)};
  LineSource source(in, "<head>", "a line of G-code");
  Block block;
  std::string_view line;
  int meaningful = 0;
  for (int lines = 0; lines < 200 && source.next(line); ++lines) {
    try {
      parse_block(line, block, "<head>", source.line_number());
    } catch (const InputError&) {
      if (source.last_line_terminated()) return false;
      break;  // a line cut off at the end of the head
    }
    for (const Word& w : block.words)
      if (w.letter == 'G' || w.letter == 'M' || w.letter == 'X' || w.letter == 'Y' || w.letter == 'Z') ++meaningful;
  }
  return meaningful > 0;
}

InputKind scan_input_kind(std::istream& in, const std::string& file_name) {
  LineSource source(in, file_name, "a line of G-code");
  Block block;
  std::string_view line;
  while (source.next(line)) {
    try {
      parse_block(line, block, file_name, source.line_number());
    } catch (const InputError&) {
      break;
    }
    if (switches_rtcp_on(block)) return InputKind::rtcp;
  }
  return InputKind::machine;
}

}  // namespace ncpost::gcode
