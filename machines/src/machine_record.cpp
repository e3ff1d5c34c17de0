// SPDX-License-Identifier: Apache-2.0
#include "ncpost/machines/machine_record.hpp"

#include <cmath>

#include "toml_reading.hpp"

namespace ncpost {
namespace {

std::string string_key(const std::string& file, const toml::table& machine, const char* key) {
  const toml::node* n = machine.get(key);
  if (!n) return {};
  if (!n->is_string())
    throw InputError(toml_reading::at(file, n->source()), fmt::format("[machine] {}: expected a string", key));
  return *n->value<std::string>();
}

}  // namespace

MachineRecord parse_machine_record(const std::string& text, const std::string& file_name) {
  const toml::table root = toml_reading::parse_toml(text, file_name);
  MachineRecord r;
  if (const toml::table* mt = root["machine"].as_table()) {
    r.serial = string_key(file_name, *mt, "serial");
    r.owner = string_key(file_name, *mt, "owner");
  }
  if (const toml::node* t = root.get("tolerances"); t && !t->is_table())
    throw InputError(toml_reading::at(file_name, t->source()),
                     "tolerances: expected a table [tolerances] (G = 10, A = 8, ...)");
  if (const toml::table* tt = root["tolerances"].as_table()) {
    toml_reading::reject_unknown_keys(file_name, *tt, {"A", "B", "E", "M", "R", "G"}, "tolerances");
    for (const auto& [key, node] : *tt) {
      const auto v = node.value<double>();
      if (!v || !(*v > 0.0) || !std::isfinite(*v))
        throw InputError(toml_reading::at(file_name, node.source()),
                         fmt::format("[tolerances] {}: expected a number of µm greater than 0", key.str()));
      r.tolerances_um[std::string(key.str())] = *v;
    }
  }
  return r;
}

MachineRecord load_machine_record(const std::string& path) {
  return parse_machine_record(toml_reading::read_text(path), path);
}

}  // namespace ncpost
