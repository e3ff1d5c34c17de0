// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/parameter_name.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <regex>

#include <fmt/format.h>

namespace ncpost::comp {
namespace {

int component_of(char c) {
  switch (c) {
    case 'X':
      return 0;
    case 'Y':
      return 1;
    case 'Z':
      return 2;
    case 'A':
      return 3;
    case 'B':
      return 4;
    case 'C':
      return 5;
    default:
      return -1;
  }
}

ParseResult refuse(std::string why) { return {std::nullopt, std::move(why)}; }

ParseResult accept(ParameterSpec s) { return {std::move(s), {}}; }

/// |cos| between a unit offset direction and a rotary axis above which the offset lies along the
/// axis's own line (no effect: refused).
constexpr double kAlongOwnLine = 0.999;

/// E<comp>0<axis>: the location of a rotary axis's line, or a squareness (EC0Y, EB0Z, EA0Z).
ParseResult parse_location(ParameterSpec s, char comp, char letter, const Machine& m) {
  s.axis_index = m.index_of(letter);
  if (s.axis_index < 0) return refuse("the machine has no axis " + std::string(1, letter));
  s.component = component_of(comp);
  const Axis& a = m.axes[static_cast<std::size_t>(s.axis_index)];
  if (a.is_rotary()) {
    s.kind = ParameterKind::location;
    if (s.component < 3) {
      Vec3d e = Vec3d::Zero();
      e[s.component] = 1.0;
      if (std::abs(e.dot(a.direction)) > kAlongOwnLine)
        return refuse("an offset of axis " + std::string(1, letter) + " along its own line has no effect");
    }
    return accept(s);
  }
  if (s.name == "EC0Y" || s.name == "EB0Z" || s.name == "EA0Z") {
    s.kind = ParameterKind::squareness;
    return accept(s);
  }
  return refuse("the squareness errors are EC0Y, EB0Z and EA0Z (docs/conventions.md)");
}

/// E<comp><axis>:t:<node>: a table node (mm; degrees in one turn for a rotary axis, periodic).
ParseResult parse_table(ParameterSpec s, char comp, char letter, const std::string& node, const Machine& m) {
  s.kind = ParameterKind::table;
  s.axis_index = m.index_of(letter);
  if (s.axis_index < 0) return refuse("the machine has no axis " + std::string(1, letter));
  s.component = component_of(comp);
  s.at_mm = std::stod(node);
  if (m.axes[static_cast<std::size_t>(s.axis_index)].is_rotary()) {
    // a rotary axis's table is periodic: its nodes are angles in degrees, one turn
    if (s.at_mm < 0.0 || s.at_mm >= 360.0)
      return refuse("the nodes of a rotary axis's table are angles from 0 (inclusive) to 360 degrees (exclusive)");
    s.at_rad = s.at_mm * kPi / 180.0;
    s.at_mm = 0.0;
    s.periodic = true;
  }
  return accept(s);
}

/// True when axis `carrier` lies between the bed and axis `carried` on the same side of the chain.
bool carries(const Machine& m, int carrier, int carried) {
  for (const std::vector<int>* side : {&m.workpiece_side, &m.tool_side}) {
    const auto a = std::find(side->begin(), side->end(), carrier), b = std::find(side->begin(), side->end(), carried);
    if (a != side->end() && b != side->end()) return a < b;
  }
  return false;
}

/// E<c>0<carried>:<carrier>:p<order>: the location error of the carried axis (as its location
/// name) changing with the rotary axis that carries it.
ParseResult parse_coupled(ParameterSpec s, char component, char carried, char carrier, int order, const Machine& m) {
  const std::string name = s.name;
  ParseResult base = parse_parameter_name(fmt::format("E{}0{}", component, carried), m);
  if (!base.spec) return base;
  s = *base.spec;
  s.name = name;
  s.kind = ParameterKind::coupled;
  s.order = order;
  s.coupled_axis_index = m.index_of(carrier);
  if (s.coupled_axis_index < 0) return refuse("the machine has no axis " + std::string(1, carrier));
  if (!m.axes[static_cast<std::size_t>(s.coupled_axis_index)].is_rotary())
    return refuse("a location error changes with a rotary axis here (" + std::string(1, carrier) + " is linear)");
  if (!carries(m, s.coupled_axis_index, s.axis_index))
    return refuse(
        fmt::format("{0}'s location can change with {1} only where {1} carries {0} (between the bed and {0} on "
                    "the same side of the chain)",
                    carried, carrier));
  return accept(s);
}

}  // namespace

bool ParameterSpec::is_angle() const {
  switch (kind) {
    case ParameterKind::location:
    case ParameterKind::harmonic:
    case ParameterKind::polynomial:
    case ParameterKind::table:
    case ParameterKind::coupled:
      return component >= 3;
    case ParameterKind::squareness:
      return true;
    case ParameterKind::reversal:
      return false;  // depends on the axis; see is_rotary of the axis
    default:
      return false;
  }
}

ParseResult parse_parameter_name(const std::string& name, const Machine& m) {
  static const std::regex location(R"(E([XYZABC])0([XYZABC]))");
  static const std::regex harmonic(R"(E([XYZABC])([ABC]):h([1-9][0-9]?):(cos|sin))");
  static const std::regex polynomial(R"(E([XYZABC])([XYZ]):p([1-3]))");
  static const std::regex table(R"(E([XYZABC])([XYZABC]):t:([-+]?[0-9]+(\.[0-9]*)?))");
  static const std::regex coupled(R"(E([XYZABC])0([ABC]):([ABC]):p([12]))");
  static const std::regex reversal(R"(reversal:([XYZABC]))");
  static const std::regex drift(R"(drift:([XYZ]):t:(lin|quad|exp|tau))");
  static const std::regex sphere(R"(sphere:position:([xyz]))");
  std::smatch g;
  ParameterSpec s;
  s.name = name;
  auto axis = [&](char letter) { return m.index_of(letter); };

  if (std::regex_match(name, g, coupled))
    return parse_coupled(s, g[1].str()[0], g[2].str()[0], g[3].str()[0], std::stoi(g[4].str()), m);
  if (std::regex_match(name, g, location)) return parse_location(s, g[1].str()[0], g[2].str()[0], m);
  if (std::regex_match(name, g, harmonic)) {
    s.kind = ParameterKind::harmonic;
    s.axis_index = axis(g[2].str()[0]);
    if (s.axis_index < 0) return refuse("the machine has no axis " + g[2].str());
    if (!m.axes[static_cast<std::size_t>(s.axis_index)].is_rotary())
      return refuse("harmonic terms belong to rotary axes");
    s.component = component_of(g[1].str()[0]);
    s.order = std::stoi(g[3].str());
    s.sine = g[4].str() == "sin";
    return accept(s);
  }
  if (std::regex_match(name, g, polynomial)) {
    s.kind = ParameterKind::polynomial;
    s.axis_index = axis(g[2].str()[0]);
    if (s.axis_index < 0) return refuse("the machine has no axis " + g[2].str());
    s.component = component_of(g[1].str()[0]);
    s.order = std::stoi(g[3].str());
    return accept(s);
  }
  if (std::regex_match(name, g, table)) return parse_table(s, g[1].str()[0], g[2].str()[0], g[3].str(), m);
  if (std::regex_match(name, g, reversal)) {
    s.kind = ParameterKind::reversal;
    s.axis_index = axis(g[1].str()[0]);
    if (s.axis_index < 0) return refuse("the machine has no axis " + g[1].str());
    return accept(s);
  }
  if (std::regex_match(name, g, drift)) {
    s.kind = ParameterKind::drift;
    s.component = component_of(g[1].str()[0]);
    const std::string b = g[2].str();
    s.drift = b == "lin"    ? DriftBasis::linear
              : b == "quad" ? DriftBasis::quadratic
              : b == "exp"  ? DriftBasis::exponential
                            : DriftBasis::time_constant;
    return accept(s);
  }
  if (name == "ballbar:length") {
    s.kind = ParameterKind::ballbar_length;
    return accept(s);
  }
  if (std::regex_match(name, g, sphere)) {
    s.kind = ParameterKind::sphere_position;
    s.component = g[1].str()[0] - 'x';
    return accept(s);
  }
  return refuse(
      "not an error parameter name of docs/conventions.md (e.g. EX0C, EC0Y, ECC:h2:cos, EXX:p1, "
      "EXX:t:-250, ECC:t:30, EA0C:A:p1, reversal:A, drift:Z:t:lin, ballbar:length, sphere:position:x)");
}

std::string table_parameter_name(char component, char axis, double at_mm) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4f", std::abs(at_mm) < 5e-5 ? 0.0 : at_mm);
  std::string v = buf;
  while (v.back() == '0') v.pop_back();
  if (v.back() == '.') v.pop_back();
  return std::string{'E', component, axis} + ":t:" + v;
}

std::string effect_of(const std::string& name) {
  static const std::regex harmonic(R"((E[XYZABC][ABC]:h[1-9][0-9]?):(cos|sin))");
  static const std::regex drift(R"((drift:[XYZ]:t):.*)");
  static const std::regex table(R"((E[XYZABC][XYZABC]:t):.*)");
  std::smatch g;
  if (std::regex_match(name, g, harmonic)) return g[1].str();
  if (std::regex_match(name, g, table)) return g[1].str();
  if (std::regex_match(name, g, drift)) return g[1].str();
  if (name.rfind("sphere:position", 0) == 0) return "sphere:position";
  return name;
}

}  // namespace ncpost::comp
