// SPDX-License-Identifier: Apache-2.0
#include "dialect_option.hpp"

#include "ncpost/postproc/write/dialect.hpp"

namespace ncpost::cli {

CLI::Validator dialect_name_or_path() {
  return CLI::Validator(
      [](std::string& v) -> std::string {
        if (v.find('/') != std::string::npos || (v.size() > 5 && v.ends_with(".toml"))) return {};
        for (const auto& n : builtin_dialect_names())
          if (v == n) return {};
        std::string list;
        for (const auto& n : builtin_dialect_names()) list += (list.empty() ? "" : ", ") + n;
        return "'" + v + "': expected a built-in dialect (" + list +
               ") or the path of a dialect file (with a "
               "'/' or ending in .toml)";
      },
      "");
}

}  // namespace ncpost::cli
