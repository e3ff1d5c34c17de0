// SPDX-License-Identifier: Apache-2.0
// G10 tool-offset blocks (see gcode_tool_offsets.hpp).
#include "read/gcode/gcode_tool_offsets.hpp"

#include <fmt/format.h>

#include <cmath>

#include "ncpost/machines/input_error.hpp"

namespace ncpost::gcode {
namespace {

using W = cl::ToolOffsetWrite;

/// Largest register (P) and value (mm) accepted.
constexpr double kMaxOffsetRegister = 1e6;
constexpr double kMaxValueMm = 1e5;

std::string_view meaning(W w) {
  switch (w) {
    case W::length:
      return "the tool length of register";
    case W::length_wear:
      return "the length wear of register";
    case W::radius:
      return "the cutter radius of register";
    case W::radius_wear:
      return "the radius wear of register";
    case W::diameter:
      return "the cutter diameter of register";
    case W::diameter_wear:
      return "the diameter wear of register";
    case W::tool_table:
      return "the tool table's entry of tool";
    case W::length_reading:
      return "the length, from where Z stands, of tool";
  }
  return "";
}

struct Site {
  const std::string& file;
  int line;
  std::string_view text;
  [[noreturn]] void fail(int column, const std::string& what) const {
    throw InputError({file, line, column}, what, std::string(text));
  }
};

}  // namespace

bool is_tool_offset_form(double l) { return l == 1.0 || l == 10.0 || l == 11.0 || l == 12.0 || l == 13.0; }

cl::ToolOffset read_tool_offset(const std::map<int, cl::ToolOffsetWrite>& writes, const ToolOffsetBlock& b,
                                const std::string& file, int line, std::string_view text) {
  const Site at{file, line, text};
  const auto kind = writes.find(b.l);
  if (kind == writes.end())
    at.fail(b.column, fmt::format("G10 L{} writes the tool table from within the program, and what L{} sets depends "
                                  "on the control (Fanuc L10 the length, L12 the radius; LinuxCNC L1 the tool "
                                  "table): post with the --dialect of the program's control (fanuc, haas, linuxcnc), "
                                  "whose [input] tool_offsets says",
                                  b.l, b.l));
  if (!b.p || b.p->value < 1.0 || b.p->value > kMaxOffsetRegister || b.p->value != std::floor(b.p->value))
    at.fail(b.p ? b.p->column : b.column, fmt::format("G10 L{} needs P, the register (tool) it sets: a whole number "
                                                      "from 1",
                                                      b.l));
  const int reg = static_cast<int>(b.p->value);
  const W w = kind->second;
  const std::string what = fmt::format("G10 L{} P{} sets {} {}", b.l, reg, meaning(w), reg);
  if (w == W::length_wear || w == W::radius_wear || w == W::diameter_wear)
    at.fail(b.column, what +
                          ", which adds to a value the program does not give: not supported; set the wear on the "
                          "control and remove the block");
  if (w == W::length_reading)
    at.fail(b.column, what + " (it depends on where the machine stands): not supported; set the length with G10 L1");
  if (b.incremental)
    at.fail(b.column, what + " under G91 (Fanuc adds the value, LinuxCNC sets it): write G90 before it");
  const bool table = w == W::tool_table;
  if (b.other || (!table && b.z))
    at.fail(b.other ? b.other_column : b.z->column,
            fmt::format("{}: {} is not supported there (expected {})", what, b.other ? b.other : 'Z',
                        table ? "P, Z the length, R the radius" : "P and R"));
  if (!b.r && !b.z) at.fail(b.column, what + " without a value (R" + (table ? " or Z" : "") + ")");
  cl::ToolOffset out;
  out.where = {line, b.column};
  out.register_number = reg;
  out.text = std::string(text);
  const auto mm = [&](const ToolOffsetWord& v, char letter) {
    const double value = v.value * b.mm_per_unit;
    if (!(std::abs(value) <= kMaxValueMm)) at.fail(v.column, fmt::format("{}: {} is out of range", what, letter));
    return value;
  };
  if (b.z) out.length_mm = mm(*b.z, 'Z');
  if (b.r && w == W::length) out.length_mm = mm(*b.r, 'R');
  if (b.r && (w == W::radius || w == W::tool_table)) out.radius_mm = mm(*b.r, 'R');
  if (b.r && w == W::diameter) out.radius_mm = mm(*b.r, 'R') / 2.0;
  if (out.radius_mm && *out.radius_mm < 0.0)
    at.fail(b.r->column, what + ": a negative radius (the other side's compensation) is not supported");
  return out;
}

}  // namespace ncpost::gcode
