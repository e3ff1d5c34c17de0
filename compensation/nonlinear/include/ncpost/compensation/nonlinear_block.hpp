// SPDX-License-Identifier: Apache-2.0
#pragma once
// One NC block as the control executes it, and its deviation from the CL data
// (docs/conventions.md "Execution model of an NC program"; seed 001, Zhang, Wang, Tang 2023).
//
// A block goes from axis position q0 to q1; the control interpolates every axis linearly,
// q(t) = q0 + t·(q1 − q0), t ∈ [0, 1] (no RTCP). The executed tool tip x(t) and tool axis a(t)
// come from the one forward chain (`tool_pose`) evaluated through an error functor `Errors`
// (`NominalErrors` for the nominal machine, a model functor for the actual machine).
//
// Frames and units: CL points, tips, axes and deviations in W; lengths in mm; angles in rad.
// The reference is the straight CL segment p0 → p1 of the block's CL end points (not the forward
// kinematics of q0, q1, so that model errors count too):
//   position error    = distance of x(t) from the segment p0 → p1 (closest point, clamped),
//   orientation error = angle between a(t) and normalise((1 − t)·u0 + t·u1).
#include <cmath>
#include <optional>
#include <type_traits>

#include "ncpost/kinematics/forward.hpp"

namespace ncpost::nonlinear {

/// A block: CL end points in W and the commanded axis positions that reach them.
struct ClBlock {
  ClPoint start;
  ClPoint end;
  AxisPosition from;
  AxisPosition to;
  /// The executed poses at `from` and `to` on the block's machine, when the caller has them (the
  /// solver evaluated them): the bound then does not evaluate them again.
  std::optional<ToolPoseT<double>> from_pose = std::nullopt;
  std::optional<ToolPoseT<double>> to_pose = std::nullopt;
};

/// q0 + t·(q1 − q0) on every axis (mm, rad).
AxisPosition lerp(const AxisPosition& q0, const AxisPosition& q1, double t);

/// Unit vector on the great circle from unit u0 to unit u1 at fraction t (slerp); for
/// antiparallel vectors an arbitrary great circle through both.
Vec3d slerp(const Vec3d& u0, const Vec3d& u1, double t);

/// The CL point at fraction t of a block: tip on the straight segment, axis on the great circle.
ClPoint cl_at(const ClPoint& start, const ClPoint& end, double t);

/// normalise((1 − t)·u0 + t·u1): the reference axis of the spec's orientation error.
Vec3d lerp_axis(const Vec3d& u0, const Vec3d& u1, double t);

/// Vector from the closest point of the segment p0 → p1 to x (mm, W).
Vec3d offset_from_segment(const Vec3d& x, const Vec3d& p0, const Vec3d& p1);

/// Angle (rad) between two (not necessarily unit) vectors, robust near 0 and π.
double angle_between(const Vec3d& a, const Vec3d& b);

/// Deviation of the executed block at one parameter value.
struct Deviation {
  Vec3d tip_mm = Vec3d::Zero();     ///< executed tool tip x(t), W
  Vec3d axis = Vec3d::UnitZ();      ///< executed tool axis a(t), W
  Vec3d offset_mm = Vec3d::Zero();  ///< x(t) minus its closest point on the CL segment, W
  double orientation_rad = 0.0;     ///< angle between a(t) and the interpolated CL axis
  double error_mm() const { return offset_mm.norm(); }
};

/// The executed motion of one block through the forward chain, with the home pose cached
/// (the same computation as `chain_pose`, done once per block instead of once per point).
template <class Errors = NominalErrors>
class ExecutedBlock {
 public:
  /// `errors` must outlive the object unless it is stateless (it is then copied).
  ExecutedBlock(const Machine& machine, const Setup& setup, const ClBlock& block, const Errors& errors = {})
      : machine_(machine), setup_(setup), block_(block), errors_(errors) {
    if constexpr (!std::is_same_v<Errors, NominalErrors>) {  // nominal: every axis transform is I at home
      const HomeInverse* cached = nullptr;
      if constexpr (CachesHome<Errors>) cached = errors_.cached_home(setup_.tool_length_mm);
      if (cached) {
        home_table_inv_ = cached->table;
        home_tool_inv_ = cached->tool;
      } else {
        const ChainPose<double> home =
            raw_chain_pose<double>(machine_, AxisPosition{}, setup_.tool_length_mm, errors_, true);
        home_table_inv_ = home.bed_T_table.inverse();
        home_tool_inv_ = home.bed_T_tool.inverse();
      }
    }
  }

  const ClBlock& block() const { return block_; }
  const Errors& errors() const { return errors_; }
  /// The tool side's home inverse (identity on the nominal machine): the TCP enters the raw chain
  /// at home_tool_inverse().t.
  const Rigidd& home_tool_inverse() const { return home_tool_inv_; }

  /// Executed tip and axis (W) at axis position q (the chain of `tool_pose`).
  ToolPoseT<double> pose_at(const AxisPosition& q) const {
    const ChainPose<double> raw = raw_chain_pose<double>(machine_, q, setup_.tool_length_mm, errors_, false);
    const ChainPose<double> actual{raw.bed_T_table * home_table_inv_, raw.bed_T_tool * home_tool_inv_};
    const Rigidd table_T_tool = actual.table_T_tool();
    return {table_T_tool.t - setup_.workpiece_origin_mm, table_T_tool.R.col(2)};
  }

  /// Rotation of the table (W axes) in M at axis position q: Δtip_M = R · Δtip_W.
  Mat3d table_rotation_at(const AxisPosition& q) const {
    const ChainPose<double> raw = raw_chain_pose<double>(machine_, q, setup_.tool_length_mm, errors_, false);
    return (raw.bed_T_table * home_table_inv_).R;
  }

  /// Deviation at parameter t ∈ [0, 1] of the block.
  Deviation at(double t) const { return deviation_of(pose_at(lerp(block_.from, block_.to, t)), t); }

  /// Deviation of an executed pose taken at parameter t of the block's CL segment.
  Deviation deviation_of(const ToolPoseT<double>& pose, double t) const {
    Deviation d;
    d.tip_mm = pose.tip_mm;
    d.axis = pose.axis;
    d.offset_mm = offset_from_segment(pose.tip_mm, block_.start.tip_mm, block_.end.tip_mm);
    d.orientation_rad = angle_between(pose.axis, lerp_axis(block_.start.axis, block_.end.axis, t));
    return d;
  }

 private:
  const Machine& machine_;
  Setup setup_;
  ClBlock block_;
  std::conditional_t<std::is_empty_v<Errors>, Errors, const Errors&> errors_;
  Rigidd home_table_inv_;
  Rigidd home_tool_inv_;
};

/// The axis position near `q` whose executed tip (W) is `target_W`, changing the linear axes only
/// (Newton steps with the table rotation as the Jacobian of the tip in W w.r.t. X Y Z).
template <class Errors>
AxisPosition shift_linear_axes(const ExecutedBlock<Errors>& executed, AxisPosition q, const Vec3d& target_W) {
  for (int it = 0; it < 4; ++it) {
    const Vec3d residual = target_W - executed.pose_at(q).tip_mm;
    if (residual.norm() < 1e-10) break;
    q.linear_mm += executed.table_rotation_at(q) * residual;
  }
  return q;
}

}  // namespace ncpost::nonlinear
