// SPDX-License-Identifier: Apache-2.0
#pragma once
// Sinumerik frames as the reader applies them: a point p of the program's current coordinate
// system lies at offset + scale * rotation * p in the settable frame (G54 ... = W, the job's
// workpiece frame). Lengths in the program's unit, angles in degrees at the interface.
//
// TRANS/ROT/SCALE replace the programmable frame, ATRANS/AROT/ASCALE append to it (the new
// component acts in the coordinates already shifted/rotated); ROT X a Y b Z c is the rotation
// about Z, then Y', then X'' (RPY, the control's default FRAME_ANGLE_ORDER): Rz(c) Ry(b) Rx(a).
// The chain is W <- swivel frame (CYCLE800) <- programmable frame (Programming Manual, "Frame
// chain": $P_WPFRAME before $P_PFRAME).
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace ncpost::sinumerik {

struct Frame {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  double scale = 1.0;
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();

  Eigen::Vector3d apply(const Eigen::Vector3d& p) const { return offset + scale * (rotation * p); }
  Eigen::Vector3d apply_direction(const Eigen::Vector3d& v) const { return rotation * v; }
  Eigen::Vector3d inverse(const Eigen::Vector3d& w) const { return rotation.transpose() * (w - offset) / scale; }
  /// This frame followed by `inner` (a point of `inner`'s coordinates: this->apply(inner.apply(p))).
  Frame then(const Frame& inner) const {
    Frame f;
    f.rotation = rotation * inner.rotation;
    f.scale = scale * inner.scale;
    f.offset = apply(inner.offset);
    return f;
  }
  bool rotates() const { return !rotation.isApprox(Eigen::Matrix3d::Identity(), 1e-15); }
  /// Only a shift: each axis maps on its own.
  bool shift_only() const { return !rotates() && scale == 1.0; }
};

/// A shift by `t`.
inline Frame shift(const Eigen::Vector3d& t) {
  Frame f;
  f.offset = t;
  return f;
}
/// Rz(c) Ry(b) Rx(a), degrees.
Frame rotation_rpy_deg(double a_deg, double b_deg, double c_deg);
/// The rotation about one axis (0 X, 1 Y, 2 Z) by `deg`.
Eigen::Matrix3d about_axis(int axis, double deg);

}  // namespace ncpost::sinumerik
