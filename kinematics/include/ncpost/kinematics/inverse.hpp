// SPDX-License-Identifier: Apache-2.0
#pragma once
// Closed-form inverse kinematics of the nominal serial chain (docs/conventions.md "Nominal closure"):
//   (X, Y, Z) + T_t(q)·0 = T_w(q)·(workpiece_origin + p)   and   R_t(q)·e_z = R_w(q)·u
// for table-table, head-head and head-table machines with any axis directions.
//
// Method: with v the tool axis direction between the two rotary axes, both rotations preserve
// the component of a vector along their own axis, so v lies on the intersection of two planes
// with the unit sphere: two solutions in general, one on the boundary, none outside the reach.
// One rotary axis (a four-axis machine): the tool axis must keep its component along that axis
// (u·d = e_z·d), then one angle turns it; no rotary axis: the tool axis must be +Z.
// Angles in rad, lengths in mm, CL data in W.
//
// Solution choice (`select_solution`): among the two solutions and their 2π shifts, the one within
// the limits nearest the previous pose (sum of |Δangle|); continuous axes are unwound to the value
// nearest the previous one. At the singular orientation (tool axis along the axis nearest the
// tool-axis end of the chain, e.g. u = +Z on an AC table) the free angle keeps its previous value;
// near it the angle follows the exact solution (no special smoothing: CAM-exact, as NX does).
#include <array>
#include <cassert>
#include <optional>
#include <string>
#include <vector>

#include "ncpost/kinematics/forward.hpp"

namespace ncpost {

/// Up to N values held in place: the candidate lists of the inverse kinematics (no allocation
/// per CL point).
template <class T, std::size_t N>
class SmallList {
 public:
  void push_back(const T& v) {
    assert(size_ < N);
    items_[size_++] = v;
  }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  T& operator[](std::size_t i) { return items_[i]; }
  const T& operator[](std::size_t i) const { return items_[i]; }
  const T& front() const { return items_[0]; }
  T* begin() { return items_.data(); }
  T* end() { return items_.data() + size_; }
  const T* begin() const { return items_.data(); }
  const T* end() const { return items_.data() + size_; }

 private:
  std::array<T, N> items_{};
  std::size_t size_ = 0;
};

/// One rotary solution in principal angles (-π, π]; `free_axis` >= 0 at a singular pose
/// names the rotary index whose angle is undetermined (set to 0 here).
struct RotarySolution {
  RotaryAngles rotary_rad;  ///< one angle per rotary axis of the machine
  int free_axis = -1;
};

/// Rotary solutions for the tool axis `axis_W` (unit, in W). Empty if the orientation is out of
/// reach of the machine (e.g. a tilt beyond what the axis directions allow, or a tilted axis on a
/// three-axis machine). `tolerance` widens the reach test for rounding.
SmallList<RotarySolution, 2> rotary_solutions(const Machine& m, const Vec3d& axis_W, double tolerance = 1e-9);

/// False when no rotary angle of rotary_solutions(m, axis_W) can be free: the tool axis and e_z are
/// more than `clear_rad` (default 1 mrad) from every axis direction they are compared with (a cheap
/// test for callers that want only the free axis of a singular pose, or only poses near one; true
/// does not mean an angle is free).
bool may_have_free_rotary(const Machine& m, const Vec3d& axis_W, double clear_rad = 1e-3);

/// X Y Z (mm) that put the tool tip on `tip_W` for the given rotary angles.
Vec3d linear_for(const Machine& m, const RotaryAngles& rotary_rad, const Vec3d& tip_W, const Setup& setup);

struct IkPolicy {
  double singular_tolerance = 1e-9;  ///< |sin| of the angle between the tool axis and the free axis
  double reach_tolerance = 1e-7;     ///< accepted rounding in the reach test
};

/// Why a CL point has no admissible solution.
struct IkFailure {
  std::string message;
};

struct IkOutcome {
  std::optional<AxisPosition> position;
  /// The tool pose (W) that the solver's machine executes at `position`, when the solver evaluated
  /// it (the compensated IK does; the nominal closed form does not)
  std::optional<ToolPoseT<double>> executed;
  IkFailure failure;  ///< set when !position
  bool singular = false;
  bool ok() const { return position.has_value(); }
};

/// Candidate unwound to be nearest `previous` and within limits; nullopt if no 2π shift fits.
std::optional<AxisPosition> admissible_candidate(const Machine& m, const RotaryAngles& rotary_rad,
                                                 const RotaryAngles& previous_rad);

/// Solve a CL point, choosing the solution nearest `previous` that respects the limits.
IkOutcome solve(const Machine& m, const ClPoint& cl, const Setup& setup, const AxisPosition& previous,
                const IkPolicy& policy = {});

/// All admissible solutions (unwound near `previous`), best first.
SmallList<AxisPosition, 2> admissible_solutions(const Machine& m, const ClPoint& cl, const Setup& setup,
                                                const AxisPosition& previous, const IkPolicy& policy = {});

/// Rotary travel (sum of |Δangle|, rad) from `previous_rad` to the nearest solution for the tool
/// axis `axis_W` if the rotary axes had no limits; nullopt at a singular pose or out of reach. A
/// chosen solution that travels clearly more was forced by the limits onto another branch.
std::optional<double> unlimited_rotary_travel(const Machine& m, const Vec3d& axis_W, const RotaryAngles& previous_rad,
                                              const IkPolicy& policy = {});

/// Angle (rad) that turns `from` into `to` about the unit `d`, both projected on the plane normal
/// to d; nullopt where either projection is shorter than `tolerance`.
std::optional<double> angle_about(const Vec3d& d, const Vec3d& from, const Vec3d& to, double tolerance);

}  // namespace ncpost
