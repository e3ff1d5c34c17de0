// SPDX-License-Identifier: Apache-2.0
// Work offset files: TOML or a LinuxCNC var-file subset (see work_offsets.hpp).
#include "ncpost/postproc/read/gcode/work_offsets.hpp"
#include "ncpost/kinematics/units.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "ncpost/machines/input_error.hpp"
#include "ncpost/machines/toml_input.hpp"

namespace ncpost::gcode {
namespace {

constexpr int kMaxExtendedOffset = 300;  ///< G54.1 P1 .. P300 (Fanuc 30i; 48 on a 0i)
constexpr double kMaxOffsetMm = 1e6;     ///< beyond: a typing slip, not a machine
constexpr int kVarFirst = 5221;          ///< LinuxCNC: G54's X
constexpr int kVarStride = 20;           ///< G55's X is 5241, ...
constexpr int kVarOffsets = 9;           ///< G54 .. G59.3

const char* const kRegisterNames[kVarOffsets] = {"G54", "G55", "G56", "G57", "G58", "G59", "G59.1", "G59.2", "G59.3"};

std::string upper_without_blanks(std::string_view s) {
  std::string out;
  for (const char c : s)
    if (c != ' ' && c != '\t') out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

using toml_input::at;

/// One offset's table: X Y Z (mm or inch) and A B C (deg).
OffsetValues read_values(const toml::table& t, double length_scale, const std::string& file, const std::string& name) {
  OffsetValues v;
  for (const auto& [key, node] : t) {
    const std::string letter = upper_without_blanks(key.str());
    const std::size_t slot = letter.size() == 1 ? std::string_view("XYZABC").find(letter[0]) : std::string_view::npos;
    if (slot == std::string_view::npos)
      throw InputError(at(file, key.source()),
                       fmt::format("unknown axis '{}' in [{}] (expected X, Y, Z in the file's units, A, B, C in deg)",
                                   key.str(), name));
    const std::optional<double> value = node.value<double>();
    if (!value || !std::isfinite(*value) || std::abs(*value * length_scale) > kMaxOffsetMm)
      throw InputError(at(file, node.source()),
                       fmt::format("{} of {}: expected a number within +-1e6 mm", letter, name));
    v[slot] = slot < 3 ? *value * length_scale : *value * kRadPerDeg;
  }
  return v;
}

WorkOffsetTable parse_toml(const std::string& text, const std::string& file) {
  const toml::table root = toml_input::parse_toml(text, file);
  double length_scale = 1.0;
  if (const toml::node* u = root.get("units")) {
    const std::optional<std::string> units = u->value<std::string>();
    if (!units || (*units != "mm" && *units != "inch"))
      throw InputError(at(file, u->source()), "units: expected \"mm\" or \"inch\"");
    length_scale = *units == "inch" ? kMmPerInch : 1.0;
  }
  WorkOffsetTable out;
  out.file = file;
  for (const auto& [key, node] : root) {
    if (key.str() == "units") continue;
    const std::optional<std::string> name = work_offset_name(key.str());
    if (!name)
      throw InputError(at(file, key.source()),
                       fmt::format("'{}' is no work offset (expected G54 .. G59, G59.1 .. G59.3, \"G54.1 P1\" .. "
                                   "\"G54.1 P300\", or units)",
                                   key.str()));
    const toml::table* t = node.as_table();
    if (!t) throw InputError(at(file, node.source()), fmt::format("{}: expected a table of axis values", *name));
    if (out.offsets.count(*name)) throw InputError(at(file, key.source()), fmt::format("{} is given twice", *name));
    out.offsets[*name] = read_values(*t, length_scale, file, *name);
  }
  return out;
}

bool parse_number(std::string_view s, double& v) {
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  return ec == std::errc() && end == s.data() + s.size() && std::isfinite(v);
}

WorkOffsetTable parse_var_file(const std::string& text, const std::string& file) {
  WorkOffsetTable out;
  out.file = file;
  std::istringstream in(text);
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream words(line);
    std::string number_text, value_text, rest;
    if (!(words >> number_text)) continue;  // blank
    double number = 0.0, value = 0.0;
    if (!(words >> value_text) || (words >> rest) || !parse_number(number_text, number) ||
        !parse_number(value_text, value) || number != std::floor(number))
      throw InputError({file, line_number, 1}, "expected a LinuxCNC parameter line: a parameter number and its value");
    const int k = static_cast<int>(number) - kVarFirst;
    if (number < kVarFirst || k >= kVarOffsets * kVarStride || k % kVarStride >= 6) continue;
    const auto slot = static_cast<std::size_t>(k % kVarStride);
    if (std::abs(value) > kMaxOffsetMm) throw InputError({file, line_number, 1}, "expected an offset within +-1e6 mm");
    out.offsets[kRegisterNames[k / kVarStride]][slot] = slot < 3 ? value : value * kRadPerDeg;
  }
  return out;
}

/// The first line that is neither blank nor a comment starts with a digit: a var file.
bool looks_like_var_file(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    return std::isdigit(static_cast<unsigned char>(line[first])) != 0;
  }
  return false;
}

}  // namespace

std::optional<std::string> work_offset_name(std::string_view text) {
  const std::string s = upper_without_blanks(text);
  for (const char* name : kRegisterNames)
    if (s == name) return std::string(name);
  if (s.rfind("G54.1P", 0) != 0) return std::nullopt;
  const std::string_view digits = std::string_view(s).substr(6);
  int n = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), n);
  if (ec != std::errc() || end != digits.data() + digits.size() || n < 1 || n > kMaxExtendedOffset) return std::nullopt;
  return fmt::format("G54.1 P{}", n);
}

std::optional<std::string> work_offset_of_register(int n) {
  if (n < 1 || n > kVarOffsets) return std::nullopt;
  return std::string(kRegisterNames[n - 1]);
}

WorkOffsetTable parse_work_offsets(const std::string& text, const std::string& file) {
  return looks_like_var_file(text) ? parse_var_file(text, file) : parse_toml(text, file);
}

WorkOffsetTable load_work_offsets(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path, 0, 0}, "cannot open the work offsets file for reading");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_work_offsets(text.str(), path);
}

}  // namespace ncpost::gcode
