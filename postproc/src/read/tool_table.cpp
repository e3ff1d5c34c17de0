// SPDX-License-Identifier: Apache-2.0
// Tool tables: TOML, [tools] name = number | { number, length, diameter } (tool_table.hpp).
#include "ncpost/postproc/read/tool_table.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "ncpost/machines/input_error.hpp"
#include "ncpost/machines/toml_input.hpp"

namespace ncpost {
namespace {

constexpr long long kMaxToolNumber = 999999999;  ///< as the readers' T words
constexpr double kMaxToolLengthMm = 2000.0;      ///< as --tool-length: beyond, a typing slip

using toml_input::at;

int number_of(const toml::node& n, const std::string& file, const std::string& name) {
  const std::optional<int64_t> v = n.value_exact<int64_t>();
  if (!v || *v < 0 || *v > kMaxToolNumber)
    throw InputError(
        at(file, n.source()),
        fmt::format("tool \"{}\": expected a tool number, a whole number from 0 to {}", name, kMaxToolNumber));
  return static_cast<int>(*v);
}

double length_of(const toml::node& n, const std::string& file, const std::string& name) {
  const std::optional<double> v = n.value<double>();
  if (!v || !std::isfinite(*v) || *v <= 0.0 || *v > kMaxToolLengthMm)
    throw InputError(at(file, n.source()),
                     fmt::format("tool \"{}\": expected a length in mm, > 0 and at most {:g}", name, kMaxToolLengthMm));
  return *v;
}

double diameter_of(const toml::node& n, const std::string& file, const std::string& name) {
  const std::optional<double> v = n.value<double>();
  if (!v || !std::isfinite(*v) || *v <= 0.0 || *v > kMaxToolLengthMm)
    throw InputError(at(file, n.source()), fmt::format("tool \"{}\": expected a diameter in mm, > 0 and at most {:g}",
                                                       name, kMaxToolLengthMm));
  return *v;
}

/// `name = 12` or `name = { number = 12, length = 154.0, diameter = 8.0 }`.
ToolTableEntry entry_of(const toml::node& n, const std::string& file, const std::string& name) {
  ToolTableEntry e;
  e.line = static_cast<int>(n.source().begin.line);
  const toml::table* t = n.as_table();
  if (!t) {
    e.number = number_of(n, file, name);
    return e;
  }
  for (const auto& [key, value] : *t)
    if (key.str() != "number" && key.str() != "length" && key.str() != "diameter")
      throw InputError(
          at(file, key.source()),
          fmt::format("tool \"{}\": unknown key '{}' (expected number, length, diameter)", name, key.str()));
  const toml::node* number = t->get("number");
  if (!number) throw InputError(at(file, n.source()), fmt::format("tool \"{}\": no number", name));
  e.number = number_of(*number, file, name);
  if (const toml::node* length = t->get("length")) e.length_mm = length_of(*length, file, name);
  if (const toml::node* diameter = t->get("diameter")) e.diameter_mm = diameter_of(*diameter, file, name);
  return e;
}

}  // namespace

ToolTable parse_tool_table(const std::string& text, const std::string& file) {
  const toml::table root = toml_input::parse_toml(text, file);
  for (const auto& [key, node] : root)
    if (key.str() != "tools")
      throw InputError(at(file, key.source()), fmt::format("unknown key '{}' (expected [tools])", key.str()));
  const toml::table* tools = root["tools"].as_table();
  if (!tools) throw InputError({file, 1, 0}, "expected a table [tools] of name = number");
  ToolTable out;
  out.file = file;
  std::map<int, std::string> name_of_number;
  for (const auto& [key, node] : *tools) {
    const std::string name(key.str());
    if (name.empty()) throw InputError(at(file, key.source()), "an empty tool name");
    const ToolTableEntry e = entry_of(node, file, name);
    if (auto [it, fresh] = name_of_number.emplace(e.number, name); !fresh)
      throw InputError(
          at(file, key.source()),
          fmt::format("tool \"{}\" has number {}, as \"{}\" has: a number calls one tool", name, e.number, it->second));
    out.by_name.emplace(name, e);
  }
  return out;
}

ToolTable load_tool_table(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path, 0, 0}, "cannot open the tool table for reading");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_tool_table(text.str(), path);
}

}  // namespace ncpost
