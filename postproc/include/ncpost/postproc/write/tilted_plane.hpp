// SPDX-License-Identifier: Apache-2.0
#pragma once
// Tilted work planes (3+2, `post --tilted-plane`, docs/conventions.md "Tilted work planes").
//
// A feature frame F is given in the program frame at home P (M with the rotary axes at 0, or W
// under RTCP; at home W is parallel to P): P_p = origin_P + P_R_F · F_p. Its Z is the tool axis
// (the control turns the rotary axes so that the tool is along it); its X is the machine's X seen
// from the tilted part at the post's rotary solution, projected on the plane (on a table-table
// machine the plane's X, Y, Z are then the machine's X, Y, Z). Angles in degrees only in the words.
//
// Angle conventions (TiltedPlaneWords::Angles):
//   euler_zxz: P_R_F = Rz(a) · Rx(b) · Rz(c)  (Fanuc G68.2 I J K, Haas G268 Q313: Z, then the new X,
//              then the new Z)
//   fixed_xyz: P_R_F = Rz(c) · Ry(b) · Rx(a)  (Heidenhain PLANE SPATIAL SPA SPB SPC: about the fixed
//              X, then the fixed Y, then the fixed Z; Sinumerik CYCLE800 axis-by-axis Z, Y', X'')
#include <array>
#include <optional>

#include "ncpost/kinematics/pose.hpp"
#include "ncpost/postproc/write/dialect.hpp"

namespace ncpost {

using Mat3d = Eigen::Matrix3d;

/// The rotation P_R_F of the three angles (deg) in `convention`.
Mat3d plane_rotation(TiltedPlaneWords::Angles convention, const std::array<double, 3>& angles_deg);

/// Angles (deg) of the rotation `P_R_F` in `convention`. Of the two triples that give it, the one
/// nearest `previous_deg` (each angle unwound to the nearest turn); without one, the principal
/// triple (euler_zxz: b in [0, 180]; fixed_xyz: b in [-90, 90]) in (-180, 180]. Where the triple is
/// not unique (euler_zxz b = 0 or 180, fixed_xyz b = ±90) the first free angle keeps its previous
/// value (0 without one) and the other takes up the rotation.
std::array<double, 3> plane_angles(TiltedPlaneWords::Angles convention, const Mat3d& P_R_F,
                                   const std::optional<std::array<double, 3>>& previous_deg);

/// The frame whose Z is `axis_P` (unit) and whose X is `x_hint_P` projected on the plane normal to
/// it (`y_hint_P` where that projection is shorter than 1e-6).
Mat3d plane_frame(const Vec3d& axis_P, const Vec3d& x_hint_P, const Vec3d& y_hint_P);

/// A tilted plane as the control reads it from the program's words (rounded).
struct TiltedPlane {
  TiltedPlaneWords::Angles convention = TiltedPlaneWords::Angles::euler_zxz;
  std::array<double, 3> angles_deg{};  ///< as written
  Vec3d origin_P_mm = Vec3d::Zero();   ///< as written
  Mat3d P_R_F = Mat3d::Identity();     ///< plane_rotation(convention, angles_deg)
  /// A point of the plane (F, mm) in P.
  Vec3d to_program(const Vec3d& p_F) const { return origin_P_mm + P_R_F * p_F; }
  /// A point of P in the plane's coordinates.
  Vec3d to_plane(const Vec3d& p_P) const { return P_R_F.transpose() * (p_P - origin_P_mm); }
};

}  // namespace ncpost
