// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/export_axis_table.hpp"
#include "ncpost/kinematics/units.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

namespace ncpost::comp {

namespace {

/// A rotary axis's direction has a component along X, Y or Z when it is above this.
constexpr double kDirectionComponent = 1e-9;
/// A location component lies along the axis (its zero-position error) when |direction| is 1 within this.
constexpr double kAlongAxis = 1e-12;

const char* component_word(bool rotary, int component) {
  static const char* linear_words[6] = {"error motion in X",
                                        "error motion in Y",
                                        "error motion in Z",
                                        "angular error motion about X",
                                        "angular error motion about Y",
                                        "angular error motion about Z"};
  static const char* rotary_words[6] = {"radial or axial error motion in X", "radial or axial error motion in Y",
                                        "radial or axial error motion in Z", "tilt error motion about X",
                                        "tilt error motion about Y",         "tilt error motion about Z"};
  return rotary ? rotary_words[component] : linear_words[component];
}

/// The effect a parameter is listed under: "EYX:t" for every node of a table, else effect_of.
std::string listed_effect(const ParameterSpec& s) {
  if (s.kind == ParameterKind::table) return s.name.substr(0, 3) + ":t";
  return effect_of(s.name);
}

/// True when the parameter's component is the axis's own motion (positioning).
bool own_component(const Axis& axis, int axis_index, const ParameterSpec& s) {
  if (!axis.is_rotary()) return s.component == axis_index;  // X=0, Y=1, Z=2
  return s.component >= 3 && std::abs(axis.direction[s.component - 3]) > kDirectionComponent;
}

/// Sorts the parameters of the axis: what the table holds (positioning, reversal), what it leaves
/// out (with why); `other_effects`: the effects listed for the other axes.
void sort_parameters(const MachineModel& model, const Axis& axis, AxisExport& out,
                     std::set<std::string>& other_effects) {
  const ModelLayout& layout = model.layout();
  std::set<std::string> left_seen;
  for (std::size_t i = 0; i < layout.size(); ++i) {
    const ParameterSpec& s = layout.spec(static_cast<int>(i));
    if (s.measurement_only()) continue;
    if (s.axis_index != out.axis_index) {
      other_effects.insert(listed_effect(s));
      continue;
    }
    const double v = model.values()[i];
    switch (s.kind) {
      case ParameterKind::reversal:
        out.reversal = v;
        out.held.push_back(s.name);
        break;
      case ParameterKind::location:
        // the zero-position error (the component along the axis) turns the axis at home as well:
        // the set-up at home absorbs it, it has no effect to compensate
        if (s.component >= 3 && std::abs(std::abs(axis.direction[s.component - 3]) - 1.0) < kAlongAxis) break;
        if (left_seen.insert(s.name).second)
          out.left_out.push_back(
              fmt::format("{} (location error of {}: a one-axis table cannot move an axis "
                          "line; --format machine does)",
                          s.name, out.letter));
        break;
      case ParameterKind::squareness:
        if (left_seen.insert(s.name).second)
          out.left_out.push_back(fmt::format("{} (squareness: a cross term, not a positioning error)", s.name));
        break;
      case ParameterKind::harmonic:
      case ParameterKind::polynomial:
      case ParameterKind::table:
        if (own_component(axis, out.axis_index, s)) {
          out.has_positioning = true;
          out.held.push_back(s.name);
          // a rotary axis's table is periodic, its nodes in rad (at_mm is a linear axis's)
          if (s.kind == ParameterKind::table)
            out.model_nodes.push_back(s.periodic ? s.at_rad : s.at_mm);
          else
            out.piecewise_linear = false;
        } else if (const std::string effect = listed_effect(s); left_seen.insert(effect).second) {
          out.left_out.push_back(fmt::format("{} ({} of {}: acts across the axis or turns the tool)", effect,
                                             component_word(out.rotary, s.component), out.letter));
        }
        break;
      case ParameterKind::coupled:
        if (left_seen.insert(s.name).second)
          out.left_out.push_back(fmt::format(
              "{} (location error of {} that changes with {}: a one-axis table cannot move "
              "an axis line)",
              s.name, out.letter, model.machine().axes[static_cast<std::size_t>(s.coupled_axis_index)].letter));
        break;
      default:
        break;
    }
  }
}

/// The travel the table covers: the limits, one turn of a rotary axis without them, or the nodes
/// of a table (held at its end values beyond); a polynomial without limits is refused.
void set_travel(const Axis& axis, AxisExport& out) {
  const char letter = out.letter;
  if (axis.limits) {
    out.travel_min = axis.limits->min;
    out.travel_max = axis.limits->max;
  } else if (out.rotary) {
    out.continuous = true;
    out.travel_min = 0.0;
    out.travel_max = kTwoPi;
  } else if (out.piecewise_linear) {
    // tables are held at their end values outside their nodes, as the controls hold a table's ends
    out.travel_min = out.model_nodes.empty() ? 0.0 : out.model_nodes.front();
    out.travel_max = out.model_nodes.empty() ? 0.0 : out.model_nodes.back();
  } else {
    throw ExportRefusal(
        ExportRefusal::Source::machine,
        fmt::format(
            "axis {} has no limits in the machine file and its error is a polynomial, which grows without "
            "bound beyond any table: add `limits = [MIN, MAX]` (mm) to [axes.{}] so that the table covers the travel",
            letter, letter));
  }
}

/// A rotary axis's table nodes (rad, one turn from 0) at every turn that falls within the travel.
std::vector<double> nodes_in_travel(const AxisExport& out) {
  std::vector<double> nodes;
  for (double at : out.model_nodes)
    for (double x = at + kTwoPi * std::ceil((out.travel_min - at) / kTwoPi); x <= out.travel_max; x += kTwoPi)
      nodes.push_back(x);
  return nodes;
}

/// Item 4 of issue 25: where the travel reaches beyond a linear table's nodes, the end values hold
/// there (the model's rule and the controls'); said, never silent.
void note_held_beyond(const Axis& axis, AxisExport& out) {
  if (out.rotary || out.model_nodes.empty()) return;
  const double lo = out.model_nodes.front(), hi = out.model_nodes.back();
  const std::string table = fmt::format("E{}{}:t", out.letter, out.letter);
  if (!axis.limits) {
    out.held_beyond.push_back(
        fmt::format("{}: the table's nodes span {:g} to {:g} mm and the machine file gives {} no "
                    "limits: beyond them the end values are held, not extrapolated",
                    table, lo, hi, out.letter));
    return;
  }
  if (out.travel_min < lo)
    out.held_beyond.push_back(
        fmt::format("{}: from {:g} to {:g} mm the travel lies beyond the table's first node: its "
                    "value there is held, not extrapolated (measure to the limit to know it)",
                    table, out.travel_min, lo));
  if (out.travel_max > hi)
    out.held_beyond.push_back(
        fmt::format("{}: from {:g} to {:g} mm the travel lies beyond the table's last node: its "
                    "value there is held, not extrapolated (measure to the limit to know it)",
                    table, hi, out.travel_max));
}

}  // namespace

AxisExport describe_axis_export(const MachineModel& model, char letter) {
  const Machine& m = model.machine();
  AxisExport out;
  out.axis_index = m.index_of(letter);
  if (out.axis_index < 0)
    throw ExportRefusal(ExportRefusal::Source::model,
                        fmt::format("the machine '{}' has no axis {} (its axes: {})", m.name, letter, [&] {
                          std::string s;
                          for (const Axis& a : m.axes) s += a.letter;
                          return s;
                        }()));
  const Axis& axis = m.axes[static_cast<std::size_t>(out.axis_index)];
  out.letter = letter;
  out.rotary = axis.is_rotary();
  std::set<std::string> other_effects;
  sort_parameters(model, axis, out, other_effects);
  if (!out.has_positioning && out.reversal == 0.0) {
    int dominant = 0;
    for (int c = 1; c < 3; ++c)
      if (std::abs(axis.direction[c]) > std::abs(axis.direction[dominant])) dominant = c;
    const std::string own =
        out.rotary ? fmt::format("E{}{}", char('A' + dominant), letter) : fmt::format("E{}{}", letter, letter);
    throw ExportRefusal(ExportRefusal::Source::model,
                        fmt::format("the model has no positioning error ({}) and no reversal (reversal:{}) of "
                                    "axis {}: there is nothing for a one-axis table to hold",
                                    own, letter, letter));
  }
  out.other_axis_terms = static_cast<int>(other_effects.size());
  std::sort(out.model_nodes.begin(), out.model_nodes.end());
  out.model_nodes.erase(std::unique(out.model_nodes.begin(), out.model_nodes.end()), out.model_nodes.end());
  set_travel(axis, out);
  if (out.rotary) {
    out.model_nodes = nodes_in_travel(out);
    std::sort(out.model_nodes.begin(), out.model_nodes.end());
  } else {
    note_held_beyond(axis, out);
    // nodes beyond the travel change nothing within it: their kinks lie outside
    std::erase_if(out.model_nodes, [&](double x) { return x < out.travel_min || x > out.travel_max; });
  }
  return out;
}

double axis_positioning_error(const MachineModel& model, int axis_index, double q, bool falling) {
  const Machine& m = model.machine();
  const Axis& axis = m.axes[static_cast<std::size_t>(axis_index)];
  RowState<double> state;
  if (const int r = model.layout().reversal_of(axis_index); r >= 0) {
    const double b = model.values()[static_cast<std::size_t>(r)];
    state.reversal[static_cast<std::size_t>(axis_index)] = falling ? std::max(b, 0.0) : std::min(b, 0.0);
  }
  AxisPosition command;
  command[axis_index] = q;
  const Setup setup{};  // tool length 0: the reference point itself
  if (!axis.is_rotary()) {
    const ToolPoseT<double> actual = model.tool_pose(command, setup, state);
    const ToolPoseT<double> nominal = forward(m, command, setup);
    return (actual.tip_mm - nominal.tip_mm).dot(axis.direction);
  }
  const ChainPose<double> pose = chain_pose<double>(m, command, 0.0, model.errors(state));
  const Mat3d& actual_R = axis.side == Side::workpiece ? pose.bed_T_table.R : pose.bed_T_tool.R;
  const Mat3d nominal_R = rotation_about<double>(axis.direction, q);
  const Eigen::AngleAxisd turn(Mat3d(actual_R * nominal_R.transpose()));
  return (turn.angle() * turn.axis()).dot(axis.direction);
}

double axis_correction(const MachineModel& model, int axis_index, double nominal, bool falling) {
  double t = 0.0;
  for (int k = 0; k < 50; ++k) {
    const double next = -axis_positioning_error(model, axis_index, nominal + t, falling);
    if (std::abs(next - t) < 1e-13) return next;
    t = next;
  }
  return t;
}

}  // namespace ncpost::comp
