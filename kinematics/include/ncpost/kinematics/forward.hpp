// SPDX-License-Identifier: Apache-2.0
#pragma once
// Forward kinematics of the generic serial chain, with an optional error model
// (docs/conventions.md "Axes and chains" and "Geometric errors"; ISO 230-1 notation).
//
// Written once, templated on the scalar S: double for posting and simulation, automatic
// differentiation scalars for identification. The error model is a functor supplying, for each
// axis and command, the displacement terms below; `NominalErrors` supplies none.
//
// Rotary axis j at command q (rad):
//   T_j(q) = Trans(c_j) · D_j(q) · Rot(d̂_j, q + r_j + ε∥) · Trans(-c_j)
//   c_j = P_j + δ_j⊥ ,  d̂_j = Rot(ε_j⊥) · d_j ,  D_j(q) = Trans(δ(q)) · Rot(ε(q))
// Linear axis j at command q (mm), reference point R = (0, 0, L):
//   tool side       T_j(q) = Trans(R + (q + r_j)·d̂_j + δ(q)) · Rot(ε(q)) · Trans(-R)
//   workpiece side  T_j(q) = Trans(R - (q + r_j)·d̂_j - δ(q)) · Rot(-ε(q)) · Trans(-R)
// Each side composes from the bed outward. Set-up at home: the actual transforms are
// T(q) · T(0)^-1, so that every error acts relative to home.
#include <array>
#include <concepts>
#include <optional>
#include <type_traits>

#include "ncpost/kinematics/machine.hpp"

namespace ncpost {

/// The error terms of one axis at one command, in M axes at home (mm, rad).
template <class S>
struct AxisErrorTerms {
  Vec3<S> location_offset_mm = Vec3<S>::Zero();  ///< rotary: δ_j, offset of the axis line
  Vec3<S> location_tilt_rad = Vec3<S>::Zero();   ///< rotary: ε_j, tilt (+ zero error along the axis)
  Vec3<S> direction_offset = Vec3<S>::Zero();    ///< linear: squareness, d̂ = d + this
  Vec3<S> motion_mm = Vec3<S>::Zero();           ///< error motion δ(q): EX, EY, EZ
  Vec3<S> motion_rad = Vec3<S>::Zero();          ///< error motion ε(q): EA, EB, EC
  S reversal = S(0);                             ///< reversal offset added to the command (mm or rad)
};

/// The nominal machine: no errors.
struct NominalErrors {
  template <class S>
  AxisErrorTerms<S> operator()(int /*axis_index*/, const S& /*command*/, bool /*at_home*/) const {
    return {};
  }
};

/// Poses of the table and of the tool body in M (bed frame).
template <class S>
struct ChainPose {
  Rigid<S> bed_T_table;  ///< table frame = M at home, carried by the workpiece-side axes
  Rigid<S> bed_T_tool;   ///< tool frame = M at home, carried by the tool-side axes

  /// The tool body seen from the table: table_T_tool.
  Rigid<S> table_T_tool() const { return bed_T_table.inverse() * bed_T_tool; }
};

/// The inverse of the chain's poses at home, T(0)^-1 on each side (the set-up), for one error
/// model and tool length. It depends on neither the command nor the row state (reversal and drift
/// do not act at home), so posting computes it once instead of once per evaluation.
struct HomeInverse {
  Rigidd table;
  Rigidd tool;
  double tool_length_mm = 0.0;
  /// Per axis: the actual direction of a rotary axis tilted by its location errors,
  /// Rot(ε⊥)·d (the hook's location terms are constants of the model).
  PerAxis<std::optional<Vec3d>> rotary_direction;
  /// Per axis: the error terms at home, which are the terms at every command for a hook whose
  /// terms are all constants (the hook decides when to use them).
  PerAxis<AxisErrorTerms<double>> terms_at_home;
};

/// An error hook that carries its home inverse: `errors.cached_home(tool_length_mm)` returns it
/// (or nullptr when it was computed for another tool length).
template <class Errors>
concept CachesHome = requires(const Errors& e) {
  { e.cached_home(0.0) } -> std::convertible_to<const HomeInverse*>;
};

/// The actual line of a rotary axis under its error terms e: c_j = P_j + δ_j⊥ (tool-side pivots
/// raised by the tool length) and d̂_j = Rot(ε_j⊥)·d_j (taken from the hook's cache when it has one).
template <class S>
struct RotaryLine {
  Vec3<S> point_mm;
  Vec3<S> direction;
};

template <class S, class Errors>
RotaryLine<S> rotary_line(const Axis& axis, int axis_index, const AxisErrorTerms<S>& e, double tool_length_mm,
                          const Errors& errors) {
  const Vec3<S> d = axis.direction.template cast<S>();
  Vec3<S> pivot = axis.pivot_mm.template cast<S>();
  if (axis.side == Side::tool) pivot.z() += S(tool_length_mm);
  const Vec3<S> offset_perp = e.location_offset_mm - e.location_offset_mm.dot(d) * d;
  if constexpr (std::is_same_v<S, double> && CachesHome<Errors>) {
    if (const HomeInverse* cached = errors.cached_home(tool_length_mm))
      if (const auto& direction = cached->rotary_direction[static_cast<std::size_t>(axis_index)])
        return {pivot + offset_perp, *direction};
  }
  const Vec3<S> tilt_perp = e.location_tilt_rad - e.location_tilt_rad.dot(d) * d;
  if constexpr (std::is_same_v<S, double>)
    if (tilt_perp.isZero(0)) return {pivot + offset_perp, d};
  return {pivot + offset_perp, rotation_vector<S>(tilt_perp) * d};
}

/// The error terms of one axis from the hook: with the whole position `all` where the hook takes
/// it (terms of one axis that depend on another axis's command), else with the axis's command only.
template <class S, class Errors>
AxisErrorTerms<S> error_terms(const Errors& errors, int axis_index, const S& q, bool at_home,
                              const AxisPositionT<S>* all) {
  if constexpr (requires { errors(axis_index, q, at_home, *all); }) {
    if (all != nullptr) return errors(axis_index, q, at_home, *all);
  }
  return errors(axis_index, q, at_home);
}

/// Transform of one axis (see header comment), without the set-up at home; `all`: the whole
/// position q is part of (for the error hook), if known.
template <class S, class Errors>
Rigid<S> axis_transform(const Axis& axis, int axis_index, const S& q, double tool_length_mm, const Errors& errors,
                        bool at_home, const AxisPositionT<S>* all = nullptr) {
  if constexpr (std::is_same_v<Errors, NominalErrors>) {
    // the same transforms with every error term zero, without the work of the zero terms
    if (axis.is_rotary()) {
      Vec3<S> pivot = axis.pivot_mm.template cast<S>();
      if (axis.side == Side::tool) pivot.z() += S(tool_length_mm);
      return Rigid<S>::rotation_about_point(rotation_about<S>(axis.direction.template cast<S>(), q), pivot);
    }
    const Vec3<S> d = axis.direction.template cast<S>();
    return Rigid<S>::translation(axis.side == Side::tool ? Vec3<S>(q * d) : Vec3<S>(-q * d));
  }
  const AxisErrorTerms<S> e = error_terms<S>(errors, axis_index, q, at_home, all);
  if constexpr (std::is_same_v<S, double>) {
    // an axis without error terms here: the nominal transform
    if (e.location_offset_mm.isZero(0) && e.location_tilt_rad.isZero(0) && e.direction_offset.isZero(0) &&
        e.motion_mm.isZero(0) && e.motion_rad.isZero(0) && e.reversal == 0.0)
      return axis_transform<S>(axis, axis_index, q, tool_length_mm, NominalErrors{}, at_home);
  }
  const Vec3<S> d = axis.direction.template cast<S>();
  if (axis.is_rotary()) {
    const RotaryLine<S> line = rotary_line<S>(axis, axis_index, e, tool_length_mm, errors);
    const Vec3<S>& c = line.point_mm;
    const Vec3<S>& d_actual = line.direction;
    const S angle = q + e.reversal + e.location_tilt_rad.dot(d);
    if constexpr (std::is_same_v<S, double>) {
      // no error motion: the same transform without its identity factors (posting's hot path)
      if (e.motion_mm.isZero(0) && e.motion_rad.isZero(0))
        return Rigid<S>::rotation_about_point(rotation_about<S>(d_actual, angle), c);
    }
    Rigid<S> motion;
    motion.R = rotation_vector<S>(e.motion_rad);
    motion.t = e.motion_mm;
    return Rigid<S>::translation(c) * motion * Rigid<S>::rotation(rotation_about<S>(d_actual, angle)) *
           Rigid<S>::translation(-c);
  }
  const Vec3<S> ref(S(0), S(0), S(tool_length_mm));
  const Vec3<S> d_actual = d + e.direction_offset;
  const S travel = q + e.reversal;
  if (axis.side == Side::tool) {
    return Rigid<S>::translation(ref + travel * d_actual + e.motion_mm) *
           Rigid<S>::rotation(rotation_vector<S>(e.motion_rad)) * Rigid<S>::translation(-ref);
  }
  return Rigid<S>::translation(ref - travel * d_actual - e.motion_mm) *
         Rigid<S>::rotation(rotation_vector<S>(Vec3<S>(-e.motion_rad))) * Rigid<S>::translation(-ref);
}

/// The chain at command q, without the set-up at home (T(q) itself).
template <class S, class Errors>
ChainPose<S> raw_chain_pose(const Machine& m, const AxisPositionT<S>& q, double tool_length_mm, const Errors& errors,
                            bool at_home) {
  ChainPose<S> pose;
  auto compose = [](Rigid<S>& pose_T, const Rigid<S>& axis_T) {
    if constexpr (std::is_same_v<S, double>) {
      if (axis_T.R == Mat3<S>::Identity()) {  // a linear axis without angular errors: translation only
        pose_T.t += pose_T.R * axis_T.t;
        return;
      }
    }
    pose_T = pose_T * axis_T;
  };
  for (int i : m.workpiece_side)
    compose(pose.bed_T_table, axis_transform<S>(m.axes[i], i, q[i], tool_length_mm, errors, at_home, &q));
  for (int i : m.tool_side)
    compose(pose.bed_T_tool, axis_transform<S>(m.axes[i], i, q[i], tool_length_mm, errors, at_home, &q));
  return pose;
}

template <class Errors>
HomeInverse home_inverse(const Machine& m, double tool_length_mm, const Errors& errors) {
  const ChainPose<double> home = raw_chain_pose<double>(m, AxisPosition{}, tool_length_mm, errors, true);
  HomeInverse h{home.bed_T_table.inverse(), home.bed_T_tool.inverse(), tool_length_mm, {}, {}};
  for (std::size_t i = 0; i < m.axes.size() && i < h.rotary_direction.size(); ++i) {
    const int index = static_cast<int>(i);
    h.terms_at_home[i] = errors(index, 0.0, true);
    if (!m.axes[i].is_rotary()) continue;
    h.rotary_direction[i] =
        rotary_line<double>(m.axes[i], index, h.terms_at_home[i], tool_length_mm, NominalErrors{}).direction;
  }
  return h;
}

/// The actual chain at command q with the set-up at home: T(q) · T(0)^-1 on each side.
template <class S, class Errors>
ChainPose<S> chain_pose(const Machine& m, const AxisPositionT<S>& q, double tool_length_mm, const Errors& errors) {
  // nominal: every axis transform is the identity at home
  if constexpr (std::is_same_v<Errors, NominalErrors>) return raw_chain_pose<S>(m, q, tool_length_mm, errors, false);
  const ChainPose<S> at_q = raw_chain_pose<S>(m, q, tool_length_mm, errors, false);
  if constexpr (std::is_same_v<S, double> && CachesHome<Errors>) {
    if (const HomeInverse* home = errors.cached_home(tool_length_mm))
      return {at_q.bed_T_table * home->table, at_q.bed_T_tool * home->tool};
  }
  const ChainPose<S> at_home = raw_chain_pose<S>(m, AxisPositionT<S>{}, tool_length_mm, errors, true);
  return {at_q.bed_T_table * at_home.bed_T_table.inverse(), at_q.bed_T_tool * at_home.bed_T_tool.inverse()};
}

/// Tool tip (TCP) and tool axis in W at command q.
template <class S>
struct ToolPoseT {
  Vec3<S> tip_mm;
  Vec3<S> axis;
};

template <class S, class Errors>
ToolPoseT<S> tool_pose(const Machine& m, const AxisPositionT<S>& q, const Setup& setup, const Errors& errors) {
  const Rigid<S> table_T_tool = chain_pose<S>(m, q, setup.tool_length_mm, errors).table_T_tool();
  return {table_T_tool.t - setup.workpiece_origin_mm.template cast<S>(), table_T_tool.R.col(2)};
}

/// Nominal forward kinematics in double.
inline ToolPoseT<double> forward(const Machine& m, const AxisPosition& q, const Setup& setup) {
  return tool_pose<double>(m, q, setup, NominalErrors{});
}

}  // namespace ncpost
