// SPDX-License-Identifier: Apache-2.0
// Subprograms in other files (see gcode_subprogram_files.hpp).
#include "read/gcode/gcode_subprogram_files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <system_error>

namespace ncpost::gcode {
namespace {

namespace fs = std::filesystem;

/// The program number a file name stands for (O1234.nc, 01234, o1234.NC -> 1234), or -1.
long number_of_name(const std::string& name) {
  std::string stem = name.substr(0, name.find('.'));
  if (!stem.empty() && (stem[0] == 'O' || stem[0] == 'o')) stem.erase(0, 1);
  if (stem.empty() || stem.size() > 9 ||
      !std::all_of(stem.begin(), stem.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
    return -1;
  return std::stol(stem);
}

std::string listed(const std::vector<std::string>& dirs) {
  std::string out;
  for (std::size_t i = 0; i < dirs.size(); ++i)
    out += (i == 0 ? "" : i + 1 == dirs.size() ? " and " : ", ") + fmt::format("'{}'", dirs[i]);
  return out.empty() ? std::string("no directory (the input has none)") : out;
}

}  // namespace

SubprogramFile find_program_file(long number, const std::vector<std::string>& dirs) {
  for (const std::string& dir : dirs) {
    std::error_code ec;
    std::vector<std::string> found;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
      if (!it->is_regular_file(ec)) continue;
      if (number_of_name(it->path().filename().string()) == number) found.push_back(it->path().string());
    }
    std::sort(found.begin(), found.end());
    if (found.size() > 1)
      return {"",
              fmt::format("'{}' and '{}' could both hold O{}: keep one of them (or give the directory of the "
                          "right one with --subprogram-dir)",
                          found[0], found[1], number),
              true};
    if (found.size() == 1) return {found[0], ""};
  }
  return {"", fmt::format("no file O{}.* or {}.* in {}", number, number, listed(dirs))};
}

SubprogramFile find_sub_file(const std::string& name, const std::vector<std::string>& dirs) {
  for (const std::string& dir : dirs) {
    const fs::path p = fs::path(dir) / (name + ".ngc");
    std::error_code ec;
    if (fs::is_regular_file(p, ec)) return {p.string(), ""};
  }
  return {"", fmt::format("no file {}.ngc in {}", name, listed(dirs))};
}

}  // namespace ncpost::gcode
