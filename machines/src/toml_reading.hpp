// SPDX-License-Identifier: Apache-2.0
#pragma once
// Reading machine files (TOML) with file:line:column errors: shared by the serial-machine loader
// (machine_file.cpp) and the TRR-XY loader (trr_xy_file.cpp). Internal to the machines library.
#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <toml++/toml.h>

#include "ncpost/kinematics/machine.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/machines/toml_input.hpp"

namespace ncpost::toml_reading {

using toml_input::at;
using toml_input::parse_toml;

/// InputError at the first key of `t` not in `known`, listing the expected keys.
inline void reject_unknown_keys(const std::string& file, const toml::table& t, const std::set<std::string>& known,
                                const std::string& section) {
  for (const auto& [key, node] : t) {
    if (!known.count(std::string(key.str()))) {
      std::string list;
      for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
      throw InputError(at(file, key.source()),
                       fmt::format("unknown key '{}' in [{}] (expected one of: {})", key.str(), section, list));
    }
  }
}

/// The whole machine file; InputError if it cannot be opened.
inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path, 0, 0}, "cannot open the machine file");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// `limits = [min, max]` times `scale`; `unit` is appended to the messages (e.g. " (mm)").
inline AxisLimits read_limits(const std::string& file, const toml::node& n, double scale, const std::string& unit) {
  const toml::array* a = n.as_array();
  if (!a || a->size() != 2) throw InputError(at(file, n.source()), "limits: expected [min, max]" + unit);
  auto lo = (*a)[0].value<double>(), hi = (*a)[1].value<double>();
  if (!lo || !hi || !std::isfinite(*lo) || !std::isfinite(*hi))
    throw InputError(at(file, n.source()), "limits: expected two finite numbers" + unit);
  if (!(*lo < *hi)) throw InputError(at(file, n.source()), "limits: expected min < max");
  return {*lo * scale, *hi * scale};
}

}  // namespace ncpost::toml_reading
