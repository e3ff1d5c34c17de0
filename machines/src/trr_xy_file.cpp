// SPDX-License-Identifier: Apache-2.0
#include "ncpost/machines/trr_xy_file.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <toml++/toml.h>

#include "ncpost/kinematics/trr_xy_forward.hpp"
#include "toml_reading.hpp"

namespace ncpost {
namespace {

using toml_reading::at;
using toml_reading::parse_toml;
using toml_reading::read_text;
using toml_reading::reject_unknown_keys;

double positive_length(const std::string& file, const toml::table& t, const char* key) {
  const toml::node* n = t.get(key);
  if (!n) throw InputError(at(file, t.source()), fmt::format("[trr_xy]: missing key '{}' (mm)", key));
  auto v = n->value<double>();
  if (!v || !std::isfinite(*v) || *v <= 0.0)
    throw InputError(at(file, n->source()), fmt::format("[trr_xy] {}: expected a positive number (mm)", key));
  return *v;
}

/// [trr_xy.calibration]: the machine's measured deviations from the symmetric design, with the names
/// and units of the model JSON (`<param>_<chain>`, mm and rad; docs/trr-xy.md "Error parameters").
/// The home pose of the calibrated machine must solve.
trr::Errors read_calibration(const std::string& file, const toml::table& t, const trr::Geometry& g) {
  trr::Errors e;
  for (const auto& [key, node] : t) {
    const std::string name(key.str());
    const int k = trr::Errors::index_of(name);
    if (k < 0)
      throw InputError(
          at(file, key.source()),
          fmt::format("[trr_xy.calibration] {}: not a TRR-XY parameter (expected <param>_<chain> with param "
                      "dr, dt, ar, at, ds, gp, dl, drs, dts or dzs and chain a, b or c)",
                      name));
    auto v = node.value<double>();
    if (!v || !std::isfinite(*v))
      throw InputError(at(file, node.source()), fmt::format("[trr_xy.calibration] {}: expected a finite number ({})",
                                                            name, trr::Errors::is_angle(k) ? "rad" : "mm"));
    e[k] = *v;
  }
  trr::Machine probe;
  probe.geometry = g;
  probe.calibration = e;
  try {
    (void)trr::Kinematics(probe);
  } catch (const std::runtime_error& ex) {
    throw InputError(at(file, t.source()), fmt::format("[trr_xy.calibration]: {}; the calibration is far too large "
                                                       "for this machine's dimensions",
                                                       ex.what()));
  }
  return e;
}

}  // namespace

std::string machine_file_kind(const std::string& path) {
  const std::string text = read_text(path);
  const toml::table root = parse_toml(text, path);
  if (const toml::table* mt = root["machine"].as_table())
    if (auto kind = (*mt)["kind"].value<std::string>()) return *kind;
  return "serial";
}

trr::Machine parse_trr_xy_machine(const std::string& text, const std::string& file) {
  const toml::table root = parse_toml(text, file);
  reject_unknown_keys(file, root, {"machine", "trr_xy", "axes", "tolerances"}, "top level");
  const toml::table* mt = root["machine"].as_table();
  if (!mt) throw InputError({file, 1, 1}, "missing table [machine] (name, kind = \"trr-xy\")");
  reject_unknown_keys(file, *mt, {"name", "kind", "serial", "owner"}, "machine");
  trr::Machine m;
  auto name = (*mt)["name"].value<std::string>();
  if (!name) throw InputError(at(file, mt->source()), "[machine]: missing key 'name' (a string)");
  m.name = *name;
  const toml::node* kind = mt->get("kind");
  if (!kind) throw InputError(at(file, mt->source()), "[machine]: missing key 'kind' (\"trr-xy\")");
  if (kind->value<std::string>() != std::optional<std::string>("trr-xy"))
    throw InputError(at(file, kind->source()), "[machine] kind: expected \"trr-xy\"");

  const toml::table* g = root["trr_xy"].as_table();
  if (!g)
    throw InputError(at(file, root.source()),
                     "missing table [trr_xy] (base_radius, platform_radius, link_length, "
                     "ball_joint_height, tool_offset)");
  reject_unknown_keys(file, *g,
                      {"base_radius", "platform_radius", "link_length", "ball_joint_height", "tool_offset",
                       "max_link_angle", "calibration"},
                      "trr_xy");
  trr::Geometry& geo = m.geometry;
  geo.base_radius_mm = positive_length(file, *g, "base_radius");
  geo.platform_radius_mm = positive_length(file, *g, "platform_radius");
  geo.link_length_mm = positive_length(file, *g, "link_length");
  geo.ball_joint_height_mm = positive_length(file, *g, "ball_joint_height");
  geo.tool_offset_mm = positive_length(file, *g, "tool_offset");
  if (const toml::node* n = g->get("max_link_angle")) {
    auto v = n->value<double>();
    if (!v || !(*v > 0.0 && *v < 90.0))
      throw InputError(at(file, n->source()), "[trr_xy] max_link_angle: expected a number of degrees in (0, 90)");
    geo.max_link_angle_rad = deg_to_rad(*v);
  }
  const double offset = geo.base_radius_mm - geo.platform_radius_mm;
  if (!(offset > 0.0 && offset < geo.link_length_mm))
    throw InputError(at(file, g->source()),
                     "[trr_xy]: expected platform_radius < base_radius < platform_radius + link_length "
                     "(the links must reach inward from the screw lines)");
  if (const toml::node* n = g->get("calibration")) {
    const toml::table* t = n->as_table();
    if (!t) throw InputError(at(file, n->source()), "[trr_xy] calibration: expected a table [trr_xy.calibration]");
    m.calibration = read_calibration(file, *t, geo);
  }

  const toml::table* axes = root["axes"].as_table();
  if (!axes) throw InputError(at(file, root.source()), "missing [axes.X], [axes.Y], [axes.U], [axes.V], [axes.W]");
  const std::string letters = "XYUVW";
  for (const auto& [key, node] : *axes) {
    const std::string k(key.str());
    if (k.size() != 1 || letters.find(k[0]) == std::string::npos)
      throw InputError(at(file, key.source()),
                       fmt::format("axis '{}': a TRR-XY machine has the axes X, Y (table) and U, V, W (sliders)", k));
    const toml::table* t = node.as_table();
    if (!t) throw InputError(at(file, node.source()), fmt::format("[axes.{}]: expected a table", k));
    reject_unknown_keys(file, *t, {"type", "limits"}, "axes." + k);
    const toml::node* type = t->get("type");
    if (!type) throw InputError(at(file, t->source()), fmt::format("[axes.{}]: missing key 'type' (\"linear\")", k));
    if (type->value<std::string>() != std::optional<std::string>("linear"))
      throw InputError(at(file, type->source()), fmt::format("[axes.{}] type: expected \"linear\"", k));
    std::optional<AxisLimits> lim;
    if (const toml::node* n = t->get("limits")) lim = toml_reading::read_limits(file, *n, 1.0, " (mm)");
    const auto idx = letters.find(k[0]);
    if (idx < 2)
      m.table_limits[idx] = lim;
    else
      m.slider_limits[idx - 2] = lim;
  }
  for (char c : letters)
    if (!axes->contains(std::string(1, c)))
      throw InputError(at(file, axes->source()), fmt::format("missing axis [axes.{}]", c));
  return m;
}

trr::Machine load_trr_xy_machine(const std::string& path) { return parse_trr_xy_machine(read_text(path), path); }

}  // namespace ncpost
