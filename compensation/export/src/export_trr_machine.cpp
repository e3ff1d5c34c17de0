// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/export_trr_machine.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace ncpost::comp {
namespace {

/// Round-trips through the TOML reader: 17 significant digits.
std::string exact_number(double v) { return fmt::format("{:.17g}", v); }

/// A TOML basic string.
std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

}  // namespace

TrrMachineExport corrected_trr_machine(const trr::Machine& machine, const trr::Errors& model) {
  if (model.all_zero())
    throw std::invalid_argument("every parameter of the model is zero: there is nothing to fold in");
  TrrMachineExport out;
  out.corrected = machine;
  out.corrected.name = machine.name + "-calibrated";
  out.corrected.calibration = machine.calibration + model;
  for (int k = 0; k < trr::kParameterCount; ++k)
    if (model[k] != 0.0) out.applied.push_back(trr::Errors::name(k));
  return out;
}

std::string format_trr_machine_toml(const trr::Machine& m, const std::vector<std::string>& notes) {
  std::string out;
  for (const std::string& n : notes) out += "# " + n + "\n";
  out += fmt::format("[machine]\nname = {}\nkind = \"trr-xy\"\n", quoted(m.name));
  const trr::Geometry& g = m.geometry;
  out += fmt::format(
      "\n[trr_xy]\nbase_radius = {}\nplatform_radius = {}\nlink_length = {}\nball_joint_height = {}\n"
      "tool_offset = {}\nmax_link_angle = {}\n",
      exact_number(g.base_radius_mm), exact_number(g.platform_radius_mm), exact_number(g.link_length_mm),
      exact_number(g.ball_joint_height_mm), exact_number(g.tool_offset_mm),
      exact_number(rad_to_deg(g.max_link_angle_rad)));
  out += "\n[trr_xy.calibration]  # mm; ar, at, gp in rad (docs/trr-xy.md \"Error parameters\")\n";
  for (int k = 0; k < trr::kParameterCount; ++k)
    if (m.calibration[k] != 0.0) out += fmt::format("{} = {}\n", trr::Errors::name(k), exact_number(m.calibration[k]));
  const char* letters = "XYUVW";
  for (int i = 0; i < 5; ++i) {
    const std::optional<AxisLimits>& lim = i < 2 ? m.table_limits[i] : m.slider_limits[i - 2];
    out += fmt::format("\n[axes.{}]\ntype = \"linear\"\n", letters[i]);
    if (lim) out += fmt::format("limits = [{}, {}]\n", exact_number(lim->min), exact_number(lim->max));
  }
  return out;
}

}  // namespace ncpost::comp
