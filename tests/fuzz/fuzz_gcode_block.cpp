// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: the Spirit X3 block grammar alone (gcode::parse_block), line by line.
// Bad input must end in InputError; anything else (crash, other exception, sanitizer report,
// hang) is a finding.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "ncpost/postproc/read/gcode/gcode_block.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  static const std::string file = "fuzz.ngc";
  ncpost::gcode::Block block;
  std::size_t begin = 0;
  int line = 0;
  while (begin <= text.size()) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string_view::npos) end = text.size();
    try {
      ncpost::gcode::parse_block(text.substr(begin, end - begin), block, file, ++line);
      for (const auto& c : block.comments) (void)c.text.size();
    } catch (const ncpost::InputError& e) {
      if (e.where().column < 0 || e.where().column > static_cast<int>(end - begin) + 1) __builtin_trap();
    }
    begin = end + 1;
  }
  return 0;
}
