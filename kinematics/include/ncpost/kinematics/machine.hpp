// SPDX-License-Identifier: Apache-2.0
#pragma once
// The nominal description of a serial machine tool: its axes and its structural chain
// (ISO 10791-1 style, docs/conventions.md "Axes and chains").
//
// Frames and units: directions and pivots are given at home in M (mm). Head-axis pivots are
// relative to the spindle gauge point (the job's tool length is added along +Z). Limits are in mm
// for linear axes and in radians for rotary axes; a rotary axis without limits is continuous.
#include <algorithm>
#include <array>
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
  /// Where the axis stands (its command in M: mm or rad) at its reference point, the zero of the
  /// control's machine coordinates (G28, G53), and at its second reference point (G30); none where
  /// the machine file does not say (docs/formats.md).
  std::optional<double> reference, reference2;
  /// The control's fixed points (Sinumerik G75 FP=1, 2, ...: machine data MD30600), commands in M
  /// (mm or rad), first = FP=1; empty where the machine file does not give them.
  std::vector<double> fixed_points;
  /// Linear axes: where a Sinumerik CYCLE800 retraction (_FR) puts the axis before the swivel (its
  /// command in M, mm), the control's swivel data record ($TC_CARR38..40); none where not given.
  std::optional<double> swivel_retract;

  bool is_rotary() const { return kind == AxisKind::rotary; }
  bool continuous() const { return is_rotary() && !limits; }
};

/// A serial machine: exactly the linear axes X, Y, Z and zero, one or two rotary axes.
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

template <class S>
struct AxisPositionT;
/// All axes of `m` at 0 (home), sized for its rotary axes.
AxisPositionT<double> home_of(const Machine& m);

/// Most rotary (or further) axes a kinematic model has: a serial chain here has 0, 1 or 2, the
/// TRR-XY machine 2 (its V W); held in place (no allocation per point).
inline constexpr int kMaxRotaryAxes = 3;
/// Most axes of a model (3 linear + kMaxRotaryAxes): the capacity of per-axis tables held in
/// place; how many are used is the model's (Machine::axes, CommandWords::count).
inline constexpr int kMaxAxes = 3 + kMaxRotaryAxes;
/// A value per axis of a model, held in place (entries beyond the model's axes are unused).
template <class T>
using PerAxis = std::array<T, kMaxAxes>;
template <class T>
constexpr PerAxis<T> per_axis_filled(const T& v) {
  PerAxis<T> a{};
  a.fill(v);
  return a;
}
/// The rotary commands of a model, as many as it has (rad; machine order).
template <class S>
using RotaryT = Eigen::Matrix<S, Eigen::Dynamic, 1, Eigen::ColMajor, kMaxRotaryAxes, 1>;
using RotaryAngles = RotaryT<double>;

/// Commanded positions: X Y Z in mm, then the model's further axes — on a serial machine its
/// rotary axes in rad (machine order, as many as Machine::rotary_count()); the number of axes is
/// the model's (3 + rotary_rad.size()), not fixed.
template <class S>
struct AxisPositionT {
  Vec3<S> linear_mm = Vec3<S>::Zero();
  RotaryT<S> rotary_rad;  ///< size = the model's rotary axis count (0 on a three-axis machine)

  /// X Y Z at 0 and no rotary axis given: home on every model (rotary_of, operator[]).
  AxisPositionT() = default;
  /// All axes at 0 for a model with `rotary_count` rotary axes.
  static AxisPositionT zero(int rotary_count) {
    AxisPositionT q;
    q.rotary_rad = RotaryT<S>::Zero(rotary_count);
    return q;
  }
  /// X Y Z then the rotary angles given.
  AxisPositionT(const Vec3<S>& linear, const RotaryT<S>& rotary) : linear_mm(linear), rotary_rad(rotary) {}

  /// The same commands, exactly (positions of different sizes differ).
  bool operator==(const AxisPositionT& o) const {
    return rotary_rad.size() == o.rotary_rad.size() && linear_mm == o.linear_mm && rotary_rad == o.rotary_rad;
  }
  /// How many axes: 3 linear and the rotary ones.
  int size() const { return 3 + static_cast<int>(rotary_rad.size()); }
  /// Command of axis `index` of Machine::axes (mm or rad); writing an axis beyond size() adds
  /// the axes up to it (at 0).
  S& operator[](int index) {
    if (index < 3) return linear_mm[index];
    if (index - 3 >= rotary_rad.size()) {
      const Eigen::Index had = rotary_rad.size();
      rotary_rad.conservativeResize(index - 2);
      rotary_rad.tail(rotary_rad.size() - had).setZero();
    }
    return rotary_rad[index - 3];
  }
  /// Command of axis `index` (mm or rad); an axis beyond size() stands at 0 (home).
  S operator[](int index) const {
    if (index < 3) return linear_mm[index];
    return index - 3 < rotary_rad.size() ? rotary_rad[index - 3] : S(0);
  }

  template <class T>
  AxisPositionT<T> cast() const {
    AxisPositionT<T> r;
    r.linear_mm = linear_mm.template cast<T>();
    r.rotary_rad = rotary_rad.template cast<T>();
    return r;
  }
};
using AxisPosition = AxisPositionT<double>;

/// The rotary angles of q on a model with `count` rotary axes: q's own, the missing ones at 0
/// (home) — AxisPosition{} is home on every model.
template <class S>
RotaryT<S> rotary_of(const AxisPositionT<S>& q, int count) {
  RotaryT<S> r = RotaryT<S>::Zero(count);
  const Eigen::Index have = std::min<Eigen::Index>(count, q.rotary_rad.size());
  r.head(have) = q.rotary_rad.head(have);
  return r;
}
/// q with exactly `count` rotary axes (the missing ones at 0, extra ones dropped).
template <class S>
AxisPositionT<S> sized(const AxisPositionT<S>& q, int count) {
  return AxisPositionT<S>(q.linear_mm, rotary_of(q, count));
}
inline AxisPosition home_of(const Machine& m) { return AxisPosition::zero(m.rotary_count()); }

/// Largest |a_k − b_k| over the rotary angles (0 without rotary axes); a and b the same size.
inline double max_abs_step(const RotaryAngles& a, const RotaryAngles& b) {
  return a.size() == 0 ? 0.0 : (a - b).cwiseAbs().maxCoeff();
}

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
