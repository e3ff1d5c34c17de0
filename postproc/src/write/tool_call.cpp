// SPDX-License-Identifier: Apache-2.0
// Tool changes by number or by name, through the dialect and the tool table (tool_call.hpp).
#include "write/tool_call.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace ncpost::detail {
namespace {

bool names(const std::vector<std::string>& blocks, const char* placeholder) {
  return std::any_of(blocks.begin(), blocks.end(),
                     [&](const std::string& b) { return b.find(placeholder) != std::string::npos; });
}

/// A name the dialect can write between its quotes: printable, no quote of its own, no brace (the
/// writer's placeholders).
bool writable(const std::string& name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return u >= 0x20 && u != 0x7f && c != '"' && c != '{' && c != '}';
  });
}

std::string table_hint(const std::string& name, const ToolTable* table) {
  return table ? fmt::format("add \"{}\" = <number> to [tools] in {}", name, table->file)
               : fmt::format(
                     "give its number in a tool table (--tool-table FILE with [tools] \"{}\" = <number>; "
                     "docs/formats.md, Tool tables)",
                     name);
}

/// A named tool without a number: every word the dialect writes around the call must do without one.
void check_no_number_needed(const std::string& name, const Dialect& d, const ToolTable* table,
                            const SourcePosition& where) {
  for (const auto* list : {&d.tool_length_on, &d.rtcp_on, &d.rtcp_off})
    if (names(*list, "{tool}") || names(*list, "{length}"))
      throw InputError(where, fmt::format("tool \"{}\" is called by name, but the {} dialect's tool length or RTCP "
                                          "words name its number ({{tool}}, {{length}}): {}",
                                          name, d.name, table_hint(name, table)));
}

}  // namespace

ToolCall tool_call_of(const cl::ToolChange& t, const Dialect& d, const ToolTable* table, const SourcePosition& where) {
  ToolCall c;
  c.length_mm = t.length_mm;
  c.length_from = "the CL data";
  if (t.name.empty()) {
    c.number = t.number;
    c.blocks = d.tool_call;
    c.label = fmt::format("T{}", t.number);
    return c;
  }
  c.label = fmt::format("tool \"{}\"", t.name);
  const ToolTableEntry* entry = nullptr;
  if (table)
    if (auto it = table->by_name.find(t.name); it != table->by_name.end()) entry = &it->second;
  if (entry) {
    c.number = entry->number;
    if (!c.length_mm && entry->length_mm) {
      c.length_mm = entry->length_mm;
      c.length_from = fmt::format("the tool table {}", table->file);
    }
  }
  if (d.tool_call_by_name.empty()) {
    if (!entry)
      throw InputError(where, fmt::format("tool \"{}\" is called by name, and the {} dialect calls tools by number: {}",
                                          t.name, d.name, table_hint(t.name, table)));
    c.blocks = d.tool_call;
    return c;
  }
  if (!writable(t.name))
    throw InputError(
        where, fmt::format("tool \"{}\": a name with a quote, a brace or a control character cannot be written in "
                           "the {} dialect's tool call",
                           t.name, d.name));
  if (!entry) check_no_number_needed(t.name, d, table, where);
  for (const std::string& b : d.tool_call_by_name) c.blocks.push_back(with_value(b, "{tool_name}", t.name));
  return c;
}

}  // namespace ncpost::detail
