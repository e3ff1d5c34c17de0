// SPDX-License-Identifier: Apache-2.0
// Tools in the post (poster.hpp): tool changes with RTCP off and on around them, the tool's length
// (the control's register or the solved kinematics) and the length registers of G43 H.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "write/tool_call.hpp"
#include "post/poster.hpp"

namespace ncpost::detail {

/// Every tool runs with its own length: RTCP off around the change, the tool call, then the
/// length (or RTCP with the length) of the new tool (the dialect's words).
/// A tool called by name keeps it where the dialect calls tools by name, else takes its number
/// from the tool table (tool_call.hpp).
void Poster::on(const cl::ToolChange& change) {
  const Dialect& d = writer_.dialect();
  const ToolCall call = tool_call_of(change, d, options_.tool_table.get(),
                                     SourcePosition{input_, change.where.line, change.where.column});
  cl::ToolChange t = change;
  t.number = call.number.value_or(0);
  t.length_mm = call.length_mm;
  if (t.length_mm) check_tool_length(t, call);
  close_plane();
  last_rapid_.reset();
  last_was_feed_ = false;
  std::vector<std::string> blocks;
  auto add = [&](const std::vector<std::string>& list) {
    for (const auto& b : list) blocks.push_back(with_tool(b, tool_, length_register()));
  };
  if (rtcp_on_) add(d.rtcp_off);
  tool_ = t.number;
  tool_numbered_ = call.number.has_value();
  length_register_ = t.number;
  add(call.blocks);
  if (options_.rtcp)
    add(d.rtcp_on);
  else if (options_.tool_length_on_change)
    add(d.tool_length_on);
  rtcp_on_ = options_.rtcp;
  writer_.tool_change(blocks);
  if (t.length_mm)
    writer_.comment(fmt::format(
        "{} length {:.4f} mm from {}: {}", call.label, *t.length_mm, call.length_from,
        length_in_kinematics() ? "the axes are solved for it" : "the control's length register applies it"));
}

/// True when the axis positions the post writes depend on the tool length: a rotary axis on the
/// tool side (a head) and no RTCP (with RTCP the control places the tip with its own length).
bool Poster::length_in_kinematics() const {
  if (options_.rtcp) return false;
  return std::any_of(machine_.axes.begin(), machine_.axes.end(),
                     [](const Axis& a) { return a.is_rotary() && a.side == Side::tool; });
}

/// LOADTL/n,LENGTH,l: on a machine whose axis positions depend on the tool length the post solves
/// for one length (--tool-length); a tool of another length would cut off by the difference.
void Poster::check_tool_length(const cl::ToolChange& t, const ToolCall& call) const {
  if (!length_in_kinematics() || !options_.tool_length_mm) return;
  if (std::abs(*t.length_mm - *options_.tool_length_mm) <= 5e-4) return;
  throw InputError(
      SourcePosition{input_, t.where.line, t.where.column},
      fmt::format("{} is {:.4f} mm long ({}), but the axes of {} are solved for a tool "
                  "length of {:.4f} mm (--tool-length): on this machine the axis positions depend on the "
                  "tool length (rotary axes in the head), and the tool would cut {:.4f} mm off the path. "
                  "Post with --tool-length {:.4f} (one run per tool length), or with --rtcp (the "
                  "control applies each tool's length)",
                  call.length_from == "the CL data" ? fmt::format("LOADTL: tool {}", t.number) : call.label,
                  *t.length_mm, call.length_from == "the CL data" ? "LENGTH" : call.length_from, machine_.name,
                  *options_.tool_length_mm, std::abs(*t.length_mm - *options_.tool_length_mm), *t.length_mm));
}

/// G43 H<n> of G-code input: the length of register n, written where it is not the one in force
/// (the tool's own after its change), with the dialect's length words naming the register
/// ("{length}"); a dialect whose tool call sets the length (Sinumerik D, Heidenhain TOOL CALL)
/// cannot write another register: refused rather than cut with the wrong length.
void Poster::on(const cl::LengthOffset& l) {
  if (length_register_ == l.register_number) return;
  if (!options_.rtcp && !options_.tool_length_on_change) return;  // (TRR-XY: the machine's lengths)
  const Dialect& d = writer_.dialect();
  const std::vector<std::string>& words = options_.rtcp ? d.rtcp_on : d.tool_length_on;
  if (std::none_of(words.begin(), words.end(),
                   [](const std::string& b) { return b.find("{length}") != std::string::npos; }))
    throw InputError(SourcePosition{input_, l.where.line, l.where.column},
                     fmt::format("H{}: the tool length of register {} {}cannot be written in the {} dialect (its "
                                 "[tool] {} words name no register: {{length}}); program the tool's own register "
                                 "after its change, or post with a dialect that writes one (fanuc, haas)",
                                 l.register_number, l.register_number,
                                 length_register_ ? fmt::format("(the tool in the spindle is T{}) ", tool_) : "",
                                 d.name, options_.rtcp ? "rtcp_on" : "length_on"));
  close_plane();
  length_register_ = l.register_number;
  if (options_.rtcp && !rtcp_on_) return;  // written when RTCP goes on, before the first motion
  writer_.tool_blocks(words, tool_, length_register());
}

}  // namespace ncpost::detail
