// SPDX-License-Identifier: Apache-2.0
#pragma once
// The nominal description of a serial machine tool: its axes and its structural chain
// (ISO 10791-1 style, docs/conventions.md "Axes and chains").
//
// Frames and units: directions and pivots are given at home in M (mm). Head-axis pivots are
// relative to the spindle gauge point (the job's tool length is added along +Z). Limits are in mm
// for linear axes and in radians for rotary axes; a rotary axis without limits is continuous.
#include <optional>
#include <string>
#include <vector>

#include "ncpost/kinematics/pose.hpp"

namespace ncpost {

enum class AxisKind { linear, rotary };
/// Which body an axis carries: the workpiece (primed in the chain, e.g. C') or the tool.
enum class Side { workpiece, tool };

struct AxisLimits {
  double min = 0.0;  ///< mm or rad
  double max = 0.0;  ///< mm or rad
  bool contains(double v, double slack = 1e-9) const { return v >= min - slack && v <= max + slack; }
};

struct Axis {
  char letter = '?';
  AxisKind kind = AxisKind::linear;
  Side side = Side::tool;
  Vec3d direction = Vec3d::UnitX();  ///< unit; rotary: positive command turns the carried body about it
  Vec3d pivot_mm = Vec3d::Zero();    ///< rotary: a point of the axis line at home
  std::optional<AxisLimits> limits;  ///< mm or rad; none = unlimited (continuous rotary axis)

  bool is_rotary() const { return kind == AxisKind::rotary; }
  bool continuous() const { return is_rotary() && !limits; }
};

/// A serial machine: exactly the linear axes X, Y, Z and zero or two rotary axes.
/// `axes` is ordered X, Y, Z, then the rotary axes in NC word order (A before B before C), so that
/// rotary axis k is `axes[3 + k]` and `AxisPosition::rotary_rad[k]`.
struct Machine {
  std::string name;
  std::string chain;
  std::vector<Axis> axes;
  std::vector<int> workpiece_side;  ///< indices into axes, from the bed outward toward the workpiece
  std::vector<int> tool_side;       ///< indices into axes, from the bed outward toward the tool

  int rotary_count() const { return static_cast<int>(axes.size()) - 3; }
  const Axis& rotary(int k) const { return axes[static_cast<std::size_t>(3 + k)]; }
  /// Index into `axes` of the axis with this letter, or -1.
  int index_of(char letter) const {
    for (std::size_t i = 0; i < axes.size(); ++i)
      if (axes[i].letter == letter) return static_cast<int>(i);
    return -1;
  }
};

/// Commanded positions of a serial machine: X Y Z in mm, rotary axes in rad (machine order).
template <class S> struct AxisPositionT {
  Vec3<S> linear_mm = Vec3<S>::Zero();
  Eigen::Matrix<S, 2, 1> rotary_rad = Eigen::Matrix<S, 2, 1>::Zero();

  /// Command of axis `index` of Machine::axes (mm or rad).
  S& operator[](int index) { return index < 3 ? linear_mm[index] : rotary_rad[index - 3]; }
  const S& operator[](int index) const { return index < 3 ? linear_mm[index] : rotary_rad[index - 3]; }

  template <class T> AxisPositionT<T> cast() const {
    AxisPositionT<T> r;
    r.linear_mm = linear_mm.template cast<T>();
    r.rotary_rad = rotary_rad.template cast<T>();
    return r;
  }
};
using AxisPosition = AxisPositionT<double>;

/// A cutter-location point in W: the tool tip and the unit tool axis (tip toward spindle).
struct ClPoint {
  Vec3d tip_mm = Vec3d::Zero();
  Vec3d axis = Vec3d::UnitZ();
};

/// Job settings that place the workpiece and the tool (set up at home, docs/conventions.md).
struct Setup {
  Vec3d workpiece_origin_mm = Vec3d::Zero();  ///< origin of W in M at home
  double tool_length_mm = 0.0;                ///< places head pivots and the linear-axis reference point
};

}  // namespace ncpost
