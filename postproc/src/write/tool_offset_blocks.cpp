// SPDX-License-Identifier: Apache-2.0
// Tool offsets of the input written again (see tool_offset_blocks.hpp).
#include "write/tool_offset_blocks.hpp"

#include <fmt/format.h>

#include <optional>

#include "ncpost/machines/input_error.hpp"

namespace ncpost::detail {

std::string tool_offset_block(const std::string& pattern, const cl::ToolOffset& t, const NcWriter& writer) {
  const auto value_of = [&](const std::string& placeholder) -> std::optional<double> {
    if (placeholder == "{length}") return t.length_mm;
    if (placeholder == "{radius}") return t.radius_mm;
    if (placeholder == "{diameter}" && t.radius_mm) return 2.0 * *t.radius_mm;
    return std::nullopt;
  };
  std::string out;
  bool any_value = false;
  std::size_t start = 0;
  while (start <= pattern.size()) {
    std::size_t end = pattern.find(' ', start);
    if (end == std::string::npos) end = pattern.size();
    std::string word = pattern.substr(start, end - start);
    start = end + 1;
    if (word.empty()) continue;
    const std::size_t open = word.find('{');
    if (open != std::string::npos) {
      const std::size_t close = word.find('}', open);
      const std::string placeholder = word.substr(open, close - open + 1);
      std::string text;
      if (placeholder == "{register}") {
        text = fmt::format("{}", t.register_number);
      } else if (const std::optional<double> v = value_of(placeholder)) {
        text = writer.word_value(0, *v);
        any_value = true;
      } else {
        continue;  // the value is not set: the word is left out
      }
      word.replace(open, close - open + 1, text);
    }
    out += (out.empty() ? "" : " ") + word;
  }
  return any_value ? out : std::string();
}

void write_tool_offset(NcWriter& writer, const cl::ToolOffset& t, const std::string& input) {
  const Dialect& d = writer.dialect();
  if (d.tool_set_offset.empty())
    throw InputError(SourcePosition{input, t.where.line, t.where.column},
                     fmt::format("the program sets a tool offset ({}), which the {} dialect cannot write (its [tool] "
                                 "has no set_offset): post with a dialect that writes it (fanuc, haas, linuxcnc), or "
                                 "remove the block and set the offset on the control",
                                 t.text, d.name));
  for (const std::string& pattern : d.tool_set_offset) {
    const std::string words = tool_offset_block(pattern, t, writer);
    if (!words.empty()) writer.block(words);
  }
}

}  // namespace ncpost::detail
