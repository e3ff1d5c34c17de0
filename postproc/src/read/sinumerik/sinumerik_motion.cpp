// SPDX-License-Identifier: Apache-2.0
// Motion blocks of the Sinumerik translator (sinumerik_translator.hpp): targets through the
// frames, arcs, rotary words and tool orientation vectors, SUPA, G75.
#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "ncpost/kinematics/inverse.hpp"
#include "ncpost/postproc/read/gcode/gcode_arc.hpp"
#include "ncpost/postproc/read/gcode/gcode_expression.hpp"
#include "read/machine_points.hpp"
#include "read/sinumerik/sinumerik_translator.hpp"
#include "read/sinumerik/sinumerik_words.hpp"

namespace ncpost::sinumerik {
namespace {

constexpr const char* kXyz = "XYZ";

std::string num(double v) { return gcode::word_number(std::abs(v) < 5e-11 ? 0.0 : v); }

bool incremental_word(Reference r, bool modal_incremental) {
  return r == Reference::incremental || (r == Reference::modal && modal_incremental);
}

}  // namespace

Eigen::Vector3d Translator::current_prog(const ProgramLine& l, int column) const {
  const Frame f = frame();
  if (f.shift_only()) return base_ - f.offset;
  for (int i = 0; i < 3; ++i)
    if (!base_known_[static_cast<std::size_t>(i)])
      fail(l, column,
           fmt::format("{} is not known here (not programmed since the start, a SUPA block or CYCLE800), and "
                       "the frame rotates or scales: program X, Y and Z in this block",
                       kXyz[i]));
  return f.inverse(base_);
}

void Translator::linear_target(const ProgramLine& l, const Words& w, Eigen::Vector3d& target,
                               std::array<bool, 3>& programmed) {
  bool need_current = false;
  for (std::size_t i = 0; i < 3; ++i)
    need_current = need_current || !w.xyz[i] || incremental_word(w.xyz_ref[i], incremental_);
  const Eigen::Vector3d current = need_current ? current_prog(l, w.axis_column) : Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < 3; ++i) {
    programmed[i] = w.xyz[i].has_value();
    if (!programmed[i]) {
      target[static_cast<int>(i)] = current[static_cast<int>(i)];
      continue;
    }
    const bool inc = incremental_word(w.xyz_ref[i], incremental_);
    if (inc && !base_known_[i])
      fail(l, w.axis_column,
           fmt::format("{} incremental before {} is known: where it starts is not known", kXyz[i], kXyz[i]));
    target[static_cast<int>(i)] = inc ? current[static_cast<int>(i)] + *w.xyz[i] : *w.xyz[i];
  }
}

/// The X Y Z words of the target in W: only the programmed ones where the frame only shifts (and
/// `all` is false), else all three; the position is then known.
std::string Translator::axis_words(const ProgramLine& l, const Eigen::Vector3d& target,
                                   const std::array<bool, 3>& programmed, bool all) {
  const Frame f = frame();
  const Eigen::Vector3d w = f.apply(target);
  std::string s;
  const bool per_axis = f.shift_only() && !all;
  machine_mm_ = {};  // written X Y Z: the linear axes move
  for (std::size_t i = 0; i < 3; ++i) {
    if (per_axis && !programmed[i]) continue;
    if (!per_axis && !programmed[i] && !base_known_[i])
      fail(l, 1, fmt::format("{} is not known here and the frame rotates: program X, Y and Z", kXyz[i]));
    s += fmt::format(" {}{}", kXyz[i], num(w[static_cast<int>(i)]));
    base_[static_cast<int>(i)] = w[static_cast<int>(i)];
    base_known_[i] = true;
  }
  return s;
}

std::string Translator::rotary_words(const ProgramLine& l, Words& w) {
  std::string s;
  for (std::size_t i = 0; i < 3; ++i) {
    if (!w.abc[i]) continue;
    const bool inc = incremental_word(w.abc_ref[i], incremental_);
    if (inc && !rotary_known_[i])
      fail(l, w.column, fmt::format("{} incremental before {} is known", "ABC"[i], "ABC"[i]));
    rotary_deg_[i] = inc ? rotary_deg_[i] + *w.abc[i] : *w.abc[i];
    rotary_known_[i] = true;
    s += fmt::format(" {}{}", "ABC"[i], num(rotary_deg_[i]));
  }
  return s;
}

std::optional<RotaryAngles> Translator::nearest_solution(const Eigen::Vector3d& axis_W, int direction) const {
  std::optional<RotaryAngles> best;
  double best_cost = std::numeric_limits<double>::infinity();
  for (const RotarySolution& sol : rotary_solutions(machine_, axis_W.normalized(), 1e-9)) {
    RotaryAngles a = sol.rotary_rad;
    double cost = 0.0;
    bool inside = true;
    for (int k = 0; k < machine_.rotary_count(); ++k) {
      const Axis& axis = machine_.rotary(k);
      const std::size_t slot = static_cast<std::size_t>(axis.letter - 'A');
      const double now = slot < 3 && rotary_known_[slot] ? rotary_deg_[slot] * M_PI / 180.0 : 0.0;
      if (sol.free_axis == k) a[k] = now;  // undetermined (on the axis): stays where it is
      if (axis.continuous()) a[k] = now + std::remainder(a[k] - now, 2.0 * M_PI);
      inside = inside && (!axis.limits || axis.limits->contains(a[k], 1e-9));
      cost += std::abs(a[k] - now);
    }
    if (direction != 0 && machine_.rotary_count() > 0 && std::abs(a[0]) > 1e-9 && (a[0] > 0) != (direction > 0))
      cost += 1e6;
    if (inside && cost < best_cost) {
      best_cost = cost;
      best = a;
    }
  }
  return best;
}

/// A3= B3= C3= under TRAORI: the machine's rotary angles for the tool axis (in W through the frame).
std::string Translator::orientation_words(const ProgramLine& l, const Words& w) {
  if (!traori_) fail(l, w.column, "A3= B3= C3= (a tool orientation vector) without TRAORI: program TRAORI first");
  if (w.any_rotary()) fail(l, w.column, "a tool orientation vector beside rotary axis words: program one of them");
  const Eigen::Vector3d v(w.orientation[0].value_or(0.0), w.orientation[1].value_or(0.0),
                          w.orientation[2].value_or(0.0));
  if (v.norm() < 1e-12) fail(l, w.column, "A3= B3= C3=: a zero vector");
  const Eigen::Vector3d axis_W = frame().apply_direction(v).normalized();
  const std::optional<RotaryAngles> a = nearest_solution(axis_W, 0);
  if (!a)
    fail(l, w.column,
         fmt::format("the tool orientation ({:.6f}, {:.6f}, {:.6f}) is beyond the reach or the limits of the "
                     "rotary axes of machine {}",
                     axis_W.x(), axis_W.y(), axis_W.z(), machine_.name));
  std::string s;
  for (int k = 0; k < machine_.rotary_count(); ++k) {
    const char letter = machine_.rotary(k).letter;
    const double deg = (*a)[k] * 180.0 / M_PI;
    if (letter >= 'A' && letter <= 'C') {
      rotary_deg_[static_cast<std::size_t>(letter - 'A')] = deg;
      rotary_known_[static_cast<std::size_t>(letter - 'A')] = true;
    }
    s += fmt::format(" {}{}", letter, num(deg));
  }
  return s;
}

/// SUPA: machine coordinates for the block (G53); the positions in W are not known after it.
std::string Translator::supa_words(const ProgramLine& l, const Words& w) {
  std::string s = fmt::format("G53 G{}", w.motion.value_or(motion_ < 0 ? 0 : motion_) == 0 ? 0 : 1);
  const char* what = w.suppression();
  if (w.motion && *w.motion > 1) fail(l, w.column, fmt::format("{} with G2/G3 is not read", what));
  if (w.any_orientation()) fail(l, w.column, fmt::format("{} with A3= B3= C3= is not read", what));
  for (std::size_t i = 0; i < 3; ++i) {
    if (w.xyz[i]) {
      if (w.xyz_ref[i] == Reference::incremental || (w.xyz_ref[i] == Reference::modal && incremental_))
        fail(l, w.column, fmt::format("{} with incremental words is not read", what));
      s += fmt::format(" {}{}", kXyz[i], num(*w.xyz[i]));
      base_known_[i] = false;
    }
    if (w.abc[i]) {
      rotary_deg_[i] = *w.abc[i];
      rotary_known_[i] = true;
      s += fmt::format(" {}{}", "ABC"[i], num(*w.abc[i]));
    }
  }
  note_machine_words(w);
  if (w.motion) motion_ = *w.motion;
  return s;
}

/// G75 FP=n (SINUMERIK 840D sl Programming Manual Fundamentals, "Fixed-point approach (G75)"): the
/// named machine axes go at rapid traverse to fixed point n (1 to 4; without FP= 1), the control's
/// machine data (MD30600 $MA_FIX_POINT_POS[n-1]), which the machine file gives as `fixed_point`; the
/// values written for the axes are not used and no frame or offset acts. A block of its own: the
/// modal G0..G3 stays. Written as G53 G0 counted from the reference point (machine_points.hpp), as
/// SUPA is; the positions in W are not known after it, the machine position of the named linear axes is.
std::string Translator::fixed_point_words(const ProgramLine& l, const Words& w) {
  const int column = *w.g75_column;
  if (w.motion || w.supa || w.any_orientation() || w.radius || w.ijk[0] || w.ijk[1] || w.ijk[2])
    fail(l, column, "G75 beside G0..G3, G53/SUPA, A3= B3= C3=, CR= or I J K: G75 is a block of its own");
  if (traori_) fail(l, column, "G75 under TRAORI is not read: program TRAFOOF before the fixed point approach");
  if (mcall_) fail(l, column, "G75 while a cycle is modal (MCALL) is not read: end it with MCALL first");
  const double n = w.fixed_point.value_or(1.0);
  if (n != std::floor(n) || n < 1 || n > 4)
    fail(l, w.fixed_point_column, fmt::format("FP={}: expected the fixed point 1, 2, 3 or 4", num(n)));
  const auto k = static_cast<std::size_t>(n);
  std::string s = "G53 G0";
  for (std::size_t i = 0; i < 6; ++i) {
    if (!(i < 3 ? w.xyz[i] : w.abc[i - 3])) continue;
    const char letter = "XYZABC"[i];
    const int at = machine_.index_of(letter);
    if (at < 0) fail(l, column, fmt::format("G75 {}: the machine {} has no axis {}", letter, machine_.name, letter));
    const Axis& axis = machine_.axes[static_cast<std::size_t>(at)];
    const char* unit = axis.is_rotary() ? "deg" : "mm";
    if (axis.fixed_points.size() < k)
      fail(l, column,
           fmt::format("G75 FP={} {}: fixed point {} of {} (the control's machine data MD30600 $MA_FIX_POINT_POS[{}]) "
                       "is not in the machine file {}: give it as [axes.{}] fixed_point = [...] ({}, FP=1 first)",
                       k, letter, k, letter, k - 1, machine_.name, letter, unit));
    std::optional<double> zero = reference_or_top(axis);
    if (!zero && axis.is_rotary()) zero = 0.0;  // G53 on a rotary axis without a reference: its machine angle
    if (!zero)
      fail(l, column,
           fmt::format("G75 {}: the posted G53 counts from {}'s reference point, which the machine file {} does not "
                       "give: add [axes.{}] reference ({})",
                       letter, letter, machine_.name, letter, unit));
    const double value = axis.is_rotary() ? (axis.fixed_points[k - 1] - *zero) * 180.0 / M_PI
                                          : (axis.fixed_points[k - 1] - *zero) / (inch_ ? 25.4 : 1.0);
    s += fmt::format(" {}{}", letter, num(value));
    if (i < 3)  // where the axis stands is known in M (the plane CYCLE800 swivels to reads it), not in W
      base_known_[i] = false, machine_mm_[i] = axis.fixed_points[k - 1];
    else
      rotary_deg_[i - 3] = axis.fixed_points[k - 1] * 180.0 / M_PI, rotary_known_[i - 3] = true;
  }
  if (s.size() == 6) fail(l, column, "G75 without axis words: the axes to approach the fixed point must be named");
  notice_once(l, "G75",
              "G75 (fixed point approach) goes to the machine file's fixed_point, written as G53 counted from the "
              "reference point: the G53 notices at its lines are its moves");
  return s;
}

void Translator::motion(const ProgramLine& l, Words& w, std::string& iso) {
  if (w.motion) motion_ = *w.motion;
  if (motion_ < 0)
    fail(l, w.column, "a motion before G0, G1, G2 or G3 is programmed (the control's initial setting is not known)");
  if (length_off_ && !rotary_only_under_d0(w))
    fail(l, w.column,
         "a motion with D0 (no tool offset) outside SUPA: the words name the spindle's gauge point, the "
         "post places the tool tip; program D1 (the tool's edge) before it, or move with SUPA");
  if (w.any_linear() || traori_ || swivel_tip_) machine_mm_ = {};  // the linear axes move (under TRAORI with the tip)
  std::string words = w.any_orientation() ? orientation_words(l, w) : rotary_words(l, w);
  Eigen::Vector3d target;
  std::array<bool, 3> programmed{};
  linear_target(l, w, target, programmed);
  const std::string head = iso.empty() ? "" : iso + " ";
  if (motion_ >= 2) return arc(l, w, target, iso, words);
  if (w.radius || w.ijk[0] || w.ijk[1] || w.ijk[2]) fail(l, w.column, "CR= or I J K on a straight motion (G0/G1)");
  iso = head + fmt::format("G{}", motion_) + (w.any_linear() ? axis_words(l, target, programmed, false) : "") + words;
}

/// G2/G3 from the current position to `target` about I J K (incremental, AC(): absolute) or with
/// CR=, in the plane G17/G18/G19 of the program's coordinates.
void Translator::arc(const ProgramLine& l, Words& w, const Eigen::Vector3d& target, std::string& iso,
                     const std::string& rotary) {
  if (!rotary.empty()) fail(l, w.column, "G2/G3 with rotary axis words is not read");
  const gcode::Plane plane = plane_ == 17 ? gcode::Plane::xy : plane_ == 18 ? gcode::Plane::zx : gcode::Plane::yz;
  const gcode::PlaneAxes ax = gcode::axes_of(plane);
  const Eigen::Vector3d start = current_prog(l, w.column);
  for (int i = 0; i < 3; ++i)
    if (!base_known_[static_cast<std::size_t>(i)]) fail(l, w.column, fmt::format("G2/G3 before {} is known", kXyz[i]));
  gcode::ProgramPoint s{start.x(), start.y(), start.z(), 0, 0, 0}, e{target.x(), target.y(), target.z(), 0, 0, 0};
  const bool cw = motion_ == 2;
  gcode::ArcOutcome a;
  if (w.radius) {
    if (w.ijk[0] || w.ijk[1] || w.ijk[2]) fail(l, w.column, "CR= beside I J K");
    a = gcode::arc_from_radius(s, e, plane, cw, *w.radius, 1);
  } else {
    std::array<double, 2> c{};
    const int plane_axes[2] = {ax.a1, ax.a2};
    for (int k = 0; k < 2; ++k) {
      const auto i = static_cast<std::size_t>(plane_axes[k]);
      c[static_cast<std::size_t>(k)] = w.ijk_absolute[i] ? w.ijk[i].value_or(0.0) : s[i] + w.ijk[i].value_or(0.0);
    }
    a = gcode::arc_from_centre(s, e, plane, cw, c[0], c[1], 1);
  }
  if (!a.arc) fail(l, w.column, a.error);
  const Frame f = frame();
  const Eigen::Vector3d normal = Eigen::Vector3d::Unit(ax.normal);
  const std::string head = iso.empty() ? "" : iso + " ";
  if (f.apply_direction(normal).dot(normal) > 1.0 - 1e-12) {  // the frame keeps the plane: G2/G3 in W
    Eigen::Vector3d centre = start;
    centre[ax.a1] = a.arc->centre1_mm;
    centre[ax.a2] = a.arc->centre2_mm;
    const Eigen::Vector3d ijk_W = f.apply(centre) - f.apply(start);
    const std::array<bool, 3> all{true, true, true};
    iso = head + fmt::format("G{}", motion_) + axis_words(l, target, all, false) +
          fmt::format(" {}{} {}{}", "IJK"[ax.a1], num(ijk_W[ax.a1]), "IJK"[ax.a2], num(ijk_W[ax.a2]));
    return;
  }
  const long n = gcode::arc_segments(*a.arc, options_.arc_chord_tolerance_mm);
  if (n > gcode::kMaxArcSegments) fail(l, w.column, "the arc would need too many points");
  if (!head.empty()) emit(l, iso);
  iso.clear();
  const std::array<bool, 3> all{true, true, true};
  for (long k = 1; k <= n; ++k) {
    const gcode::ProgramPoint p = a.arc->at(static_cast<double>(k) / static_cast<double>(n));
    emit(l, "G1" + axis_words(l, Eigen::Vector3d(p[0], p[1], p[2]), all, true));
  }
}

}  // namespace ncpost::sinumerik
