// SPDX-License-Identifier: Apache-2.0
#pragma once
// The machine-file text of a minimal AC tilting-rotary table (chain w C' A' Y' b X Z t, A within
// ±120°, C unlimited), for tests, fuzz targets and benchmarks that need a machine without a file.
#include <string>
#include <string_view>

namespace ncpost::testing {

/// `pivot_a` and `pivot_c` are TOML arrays in mm, e.g. "[10, 25, 45]".
inline std::string ac_trunnion_toml(std::string_view name, std::string_view pivot_a = "[0, 0, 0]",
                                    std::string_view pivot_c = "[0, 0, 0]") {
  std::string s = "[machine]\nname = \"";
  s += name;
  s += "\"\nchain = \"w C' A' Y' b X Z t\"\n"
       "[axes.X]\ntype = \"linear\"\n[axes.Y]\ntype = \"linear\"\n[axes.Z]\ntype = \"linear\"\n"
       "[axes.A]\ntype = \"rotary\"\ndirection = [1, 0, 0]\npivot = ";
  s += pivot_a;
  s += "\nlimits = [-120, 120]\n[axes.C]\ntype = \"rotary\"\ndirection = [0, 0, 1]\npivot = ";
  s += pivot_c;
  s += "\n";
  return s;
}

}  // namespace ncpost::testing
