// SPDX-License-Identifier: Apache-2.0
#include "ncpost/machines/machine_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <toml++/toml.h>

#include "toml_reading.hpp"

namespace ncpost {
namespace {

/// Rotary axes the serial chain's closed-form inverse solves (inverse.hpp): 0, 1 or 2.
constexpr int kMaxSerialRotaryAxes = 2;
/// Fixed points a Sinumerik control holds per axis (G75 FP=1 ... FP=4).
constexpr std::size_t kMaxFixedPoints = 4;

using toml_reading::at;
using toml_reading::reject_unknown_keys;

[[noreturn]] void fail(const std::string& file, const toml::node& n, const std::string& what) {
  throw InputError(at(file, n.source()), what);
}

Vec3d read_vector(const std::string& file, const toml::node& n, const std::string& what) {
  const toml::array* a = n.as_array();
  if (!a || a->size() != 3) fail(file, n, fmt::format("{}: expected an array of three numbers", what));
  Vec3d v;
  for (std::size_t i = 0; i < 3; ++i) {
    auto x = (*a)[i].value<double>();
    if (!x || !std::isfinite(*x)) fail(file, (*a)[i], fmt::format("{}: expected a finite number", what));
    v[static_cast<int>(i)] = *x;
  }
  return v;
}

/// One command in M of the axis (`key`'s value in the axis's unit: mm or deg), in mm or rad; within
/// the axis's travel where it has one.
double read_machine_point(const std::string& file, const toml::node& n, const Axis& axis, const std::string& key) {
  const double scale = axis.is_rotary() ? kPi / 180.0 : 1.0;
  const auto v = n.value<double>();
  if (!v || !std::isfinite(*v))
    fail(file, n, fmt::format("{}: expected a finite number ({})", key, axis.is_rotary() ? "deg" : "mm"));
  if (axis.limits && !axis.limits->contains(*v * scale, 1e-9))
    fail(file, n,
         fmt::format("{}: {} lies outside the axis's limits [{}, {}]", key, *v, axis.limits->min / scale,
                     axis.limits->max / scale));
  return *v * scale;
}

/// The axis's points in machine coordinates: the reference points (G28/G53 and G30; Klartext M91
/// and M92) and the fixed points (Sinumerik G75 FP=1..4, the control's machine data MD30600).
void read_machine_points(const std::string& file, const toml::table& t, Axis& axis) {
  if (const toml::node* n = t.get("reference")) axis.reference = read_machine_point(file, *n, axis, "reference");
  if (const toml::node* n = t.get("reference2")) axis.reference2 = read_machine_point(file, *n, axis, "reference2");
  const toml::node* n = t.get("fixed_point");
  if (!n) return;
  const toml::array* a = n->as_array();
  if (!a || a->empty() || a->size() > kMaxFixedPoints)
    fail(file, *n,
         fmt::format("fixed_point: expected an array of 1 to {} numbers ({}), FP=1 first", kMaxFixedPoints,
                     axis.is_rotary() ? "deg" : "mm"));
  for (std::size_t k = 0; k < a->size(); ++k)
    axis.fixed_points.push_back(read_machine_point(file, (*a)[k], axis, fmt::format("fixed_point[{}]", k + 1)));
}

/// `swivel_retract` (linear axes, mm in M, within the travel): CYCLE800's retraction position.
void read_swivel_retract(const std::string& file, const toml::table& t, Axis& axis) {
  const toml::node* n = t.get("swivel_retract");
  if (!n) return;
  if (axis.is_rotary()) fail(file, *n, "swivel_retract: a linear axis's key (mm); a rotary axis takes none");
  axis.swivel_retract = read_machine_point(file, *n, axis, "swivel_retract");
}

Axis read_axis(const std::string& file, char letter, const toml::table& t) {
  const std::string section = fmt::format("axes.{}", letter);
  reject_unknown_keys(
      file, t, {"type", "direction", "pivot", "limits", "reference", "reference2", "fixed_point", "swivel_retract"},
      section);
  Axis axis;
  axis.letter = letter;
  auto type = t["type"].value<std::string>();
  if (!type)
    throw InputError(at(file, t.source()), fmt::format("[{}]: missing key 'type' (\"linear\" or \"rotary\")", section));
  if (*type == "linear") {
    axis.kind = AxisKind::linear;
    if (letter != 'X' && letter != 'Y' && letter != 'Z')
      fail(file, *t.get("type"),
           fmt::format("linear axis '{}': a serial machine's linear axes are X, Y and Z", letter));
    if (t.contains("direction") || t.contains("pivot"))
      throw InputError(
          at(file, t.source()),
          fmt::format("[{}]: a linear axis takes no direction or pivot (X, Y, Z are the axes of M)", section));
    axis.direction = Vec3d::Unit(letter - 'X');
    if (const toml::node* n = t.get("limits")) axis.limits = toml_reading::read_limits(file, *n, 1.0, "");
  } else if (*type == "rotary") {
    axis.kind = AxisKind::rotary;
    const toml::node* d = t.get("direction");
    if (!d) throw InputError(at(file, t.source()), fmt::format("[{}]: missing key 'direction' (unit vector)", section));
    axis.direction = read_vector(file, *d, "direction");
    if (std::abs(axis.direction.norm() - 1.0) > 1e-6)
      fail(file, *d, fmt::format("direction: expected a unit vector, its length is {:.9g}", axis.direction.norm()));
    axis.direction.normalize();
    const toml::node* p = t.get("pivot");
    if (!p)
      throw InputError(at(file, t.source()),
                       fmt::format("[{}]: missing key 'pivot' (mm, a point of the axis line)", section));
    axis.pivot_mm = read_vector(file, *p, "pivot");
    if (const toml::node* n = t.get("limits")) axis.limits = toml_reading::read_limits(file, *n, kPi / 180.0, "");
  } else {
    fail(file, *t.get("type"), fmt::format("type: expected \"linear\" or \"rotary\", got \"{}\"", *type));
  }
  read_machine_points(file, t, axis);
  read_swivel_retract(file, t, axis);
  return axis;
}

}  // namespace

void assign_chain(Machine& m, const std::string& chain, const SourcePosition& where) {
  std::istringstream in(chain);
  std::vector<std::string> tokens;
  for (std::string tok; in >> tok;) tokens.push_back(tok);
  auto bad = [&](const std::string& what) {
    throw InputError(where, fmt::format("chain \"{}\": {} (expected e.g. \"w C' A' Y' b X Z t\")", chain, what));
  };
  if (tokens.size() < 3 || tokens.front() != "w" || tokens.back() != "t") bad("must start with 'w' and end with 't'");
  const auto b = std::find(tokens.begin(), tokens.end(), "b");
  if (b == tokens.end() || std::count(tokens.begin(), tokens.end(), "b") != 1) bad("must contain the bed 'b' once");
  std::set<char> seen;
  m.workpiece_side.clear();
  m.tool_side.clear();
  auto take = [&](const std::string& tok, bool primed_expected) -> int {
    const bool primed = tok.size() == 2 && tok[1] == '\'';
    if (tok.empty() || tok.size() > 2 || (tok.size() == 2 && !primed)) bad(fmt::format("bad axis token '{}'", tok));
    if (primed != primed_expected)
      bad(fmt::format("axis '{}' {} the bed must {}be primed", tok, primed_expected ? "before" : "after",
                      primed_expected ? "" : "not "));
    const char letter = tok[0];
    if (!seen.insert(letter).second) bad(fmt::format("axis '{}' appears twice", letter));
    const int idx = m.index_of(letter);
    if (idx < 0) bad(fmt::format("axis '{}' has no [axes.{}] table", letter, letter));
    m.axes[static_cast<std::size_t>(idx)].side = primed ? Side::workpiece : Side::tool;
    return idx;
  };
  // workpiece side: listed from the workpiece to the bed; store from the bed outward
  for (auto it = std::prev(b); it != tokens.begin(); --it) m.workpiece_side.push_back(take(*it, true));
  for (auto it = std::next(b); it != std::prev(tokens.end()); ++it) m.tool_side.push_back(take(*it, false));
  for (const Axis& a : m.axes)
    if (!seen.count(a.letter)) bad(fmt::format("axis '{}' has a table but is not in the chain", a.letter));
  for (const auto* side : {&m.workpiece_side, &m.tool_side}) {
    bool rotary_seen = false;
    for (int i : *side) {
      const Axis& a = m.axes[static_cast<std::size_t>(i)];
      if (a.is_rotary())
        rotary_seen = true;
      else if (rotary_seen)
        bad(fmt::format("linear axis '{}' is carried by a rotary axis; linear axes must be nearer the bed", a.letter));
    }
  }
  m.chain = chain;
}

Machine parse_machine(const std::string& text, const std::string& file_name) {
  const toml::table root = toml_reading::parse_toml(text, file_name);
  if (const toml::table* t = root["machine"].as_table(); t && (*t)["kind"].value<std::string>() == "trr-xy")
    throw InputError(at(file_name, t->get("kind")->source()),  // a parallel machine: trr_xy_file.hpp reads it
                     "[machine] kind = \"trr-xy\": a TRR-XY parallel machine, not a serial chain (load it with "
                     "load_trr_xy_machine; post, preview and sensitivity accept it)");
  reject_unknown_keys(file_name, root, {"machine", "axes", "tolerances"}, "top level");
  const toml::table* mt = root["machine"].as_table();
  if (!mt) throw InputError({file_name, 1, 1}, "missing table [machine] (name, chain)");
  reject_unknown_keys(file_name, *mt, {"name", "chain", "kind", "serial", "owner"}, "machine");
  Machine m;
  auto name = (*mt)["name"].value<std::string>();
  if (!name) throw InputError(at(file_name, mt->source()), "[machine]: missing key 'name' (a string)");
  m.name = *name;
  if (auto kind = (*mt)["kind"].value<std::string>(); kind && *kind != "serial") {
    throw InputError(
        at(file_name, mt->get("kind")->source()),
        fmt::format("[machine] kind = \"{}\": this loader reads serial machines (kind \"serial\" or no kind)", *kind));
  }
  const toml::node* chain = mt->get("chain");
  if (!chain || !chain->is_string())
    throw InputError(at(file_name, mt->source()), "[machine]: missing key 'chain' (a string)");

  const toml::table* axes = root["axes"].as_table();
  if (!axes || axes->empty()) throw InputError(at(file_name, root.source()), "missing [axes.*] tables");
  std::map<char, Axis> by_letter;
  for (const auto& [key, node] : *axes) {
    const std::string k(key.str());
    if (k.size() != 1 || !std::isupper(static_cast<unsigned char>(k[0])))
      throw InputError(at(file_name, key.source()), fmt::format("axis name '{}': expected one capital letter", k));
    const toml::table* t = node.as_table();
    if (!t) fail(file_name, node, fmt::format("[axes.{}]: expected a table", k));
    by_letter[k[0]] = read_axis(file_name, k[0], *t);
  }
  for (char c : {'X', 'Y', 'Z'}) {
    if (!by_letter.count(c))
      throw InputError(at(file_name, axes->source()), fmt::format("missing linear axis [axes.{}]", c));
    m.axes.push_back(by_letter[c]);
  }
  for (auto& [letter, axis] : by_letter)
    if (axis.is_rotary()) m.axes.push_back(axis);
  assign_chain(m, *chain->value<std::string>(), at(file_name, chain->source()));
  if (m.rotary_count() > kMaxSerialRotaryAxes)
    throw InputError(
        at(file_name, axes->source()),
        fmt::format("{} rotary axes: a serial machine has none, one (four-axis) or two (five-axis)", m.rotary_count()));
  if (m.rotary_count() == 2 && m.rotary(0).direction.cross(m.rotary(1).direction).norm() < 1e-6)
    throw InputError(at(file_name, axes->source()),
                     "the two rotary axes are parallel: the tool axis cannot be oriented");
  return m;
}

Machine load_machine(const std::string& path) { return parse_machine(toml_reading::read_text(path), path); }

}  // namespace ncpost
