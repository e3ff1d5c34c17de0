// SPDX-License-Identifier: Apache-2.0
#pragma once
// Geometry and error parameters of the TRR-XY hybrid machine (seed 004; the contract is
// docs/trr-xy.md): a 3-PRS parallel spindle head (chains a, b, c at 0°, 120°, 240°
// about +Z: vertical ball screw, slider, pin joint, link, ball joint on the spindle plate) on
// an XY table.
//
// Frame M (docs/conventions.md): Z up along the spindle, origin at the TCP at home (all sliders at 0,
// plate level and centred). Lengths in mm, angles in rad. Chain i has the radial unit vector
// r_i = (cos θ_i, sin θ_i, 0) and the tangential t_i = (−sin θ_i, cos θ_i, 0).
//
// Per chain (with the error parameters of the spec, all zero on the nominal machine):
//   pin-joint centre   B_i(s) = (rb + dr)·r_i + dt·t_i + H·e_z − (s + ds)·d_i
//   screw direction    d_i    = Rot(r_i, −at)·Rot(t_i, ar)·e_z
//   pin axis           p_i    = Rot(r_i, gp)·t_i          (constraint (S_i − B_i)·p_i = 0)
//   link length        l + dl
//   ball joint (plate) a_i    = (rs + drs)·r_i + dts·t_i + dzs·e_z,  S_i = P_c + R_p·a_i
// with H = sqrt(l² − (rb − rs)²) + hs + lt, and the TCP P_c − (hs + lt)·R_p·e_z.
// A calibrated machine file's deviations (Machine::calibration) and a model's errors both enter as
// these parameters: the chains are built with their sum (Kinematics::actual_errors).
#include <array>
#include <optional>
#include <string>

#include "ncpost/kinematics/machine.hpp"
#include "ncpost/kinematics/pose.hpp"

namespace ncpost::trr {

/// Nominal dimensions (machine file [trr_xy], mm) and axis limits.
struct Geometry {
  double base_radius_mm = 495.0;        ///< rb: screw lines from the centre
  double platform_radius_mm = 200.0;    ///< rs: ball joints from the plate centre
  double link_length_mm = 1020.0;       ///< l
  double ball_joint_height_mm = 142.0;  ///< hs: ball-joint plane above the plate
  double tool_offset_mm = 270.0;        ///< lt: plate centre to tool tip
  /// Largest angle of a link from the screw line; beyond it a pose is out of reach (a choice
  /// of ncpost, not of the spec: the A-shaped links and ball joints do not allow more).
  double max_link_angle_rad = deg_to_rad(45.0);

  /// Ball-joint plane centre to the TCP along the tool axis (hs + lt).
  double tip_offset_mm() const { return ball_joint_height_mm + tool_offset_mm; }
  /// H: height of the pin joints above the TCP at home.
  double pin_height_mm() const;
};

/// The 10 error parameters of one chain (spec table; mm and rad).
struct ChainErrors {
  double dr = 0, dt = 0;             ///< screw line offset, radial and tangential (mm)
  double ar = 0, at = 0;             ///< screw line tilt toward radial and tangential (rad)
  double ds = 0;                     ///< slider zero offset (mm)
  double gp = 0;                     ///< pin axis turned about the radial direction (rad)
  double dl = 0;                     ///< link length error (mm)
  double drs = 0, dts = 0, dzs = 0;  ///< ball-joint offset on the plate: radial, tangential, normal (mm)
};

inline constexpr int kParameterCount = 30;
inline constexpr int kPerChain = 10;

/// All 30 parameters, chain a then b then c; index k = 10·chain + field (field order as in
/// ChainErrors: dr dt ar at ds gp dl drs dts dzs). Names `<field>_<chain>`, e.g. `dl_a`.
struct Errors {
  std::array<ChainErrors, 3> chain{};

  double& operator[](int k);
  double operator[](int k) const;
  static std::string name(int k);
  /// Index of a parameter name, or -1.
  static int index_of(const std::string& name);
  /// True for the angles (ar, at, gp), in rad; the others are lengths in mm.
  static bool is_angle(int k);
  bool all_zero() const;
};

/// Parameter by parameter sum: the errors `b` on top of `a` (each parameter enters the formulas of
/// the header comment once, so the sum is exactly the machine with both).
Errors operator+(const Errors& a, const Errors& b);

/// The machine: geometry, its calibration and the limits of the axes X, Y (table) and U, V, W
/// (sliders a, b, c).
struct Machine {
  std::string name = "trr-xy";
  Geometry geometry;
  /// The measured deviations of this machine from the symmetric design, in the 30 parameters of
  /// Errors (machine file [trr_xy.calibration], written by `export --format machine`): part of the
  /// machine as the control knows it. A model's errors act on top of them (Kinematics).
  Errors calibration{};
  std::optional<AxisLimits> table_limits[2];   ///< X, Y (mm)
  std::optional<AxisLimits> slider_limits[3];  ///< U, V, W (mm, positive moves the slider down)
};

/// Chain i's geometry with its errors, in M (see the header comment).
struct ChainFrame {
  Vec3d radial = Vec3d::UnitX();           ///< r_i
  Vec3d tangential = Vec3d::UnitY();       ///< t_i
  Vec3d pin_at_zero_mm = Vec3d::Zero();    ///< (rb + dr)·r_i + dt·t_i + H·e_z
  Vec3d screw_down = Vec3d::UnitZ();       ///< d_i (a positive slider command moves B by −d_i)
  double slider_zero_mm = 0.0;             ///< ds
  Vec3d pin_axis = Vec3d::UnitY();         ///< p_i
  double link_length_mm = 0.0;             ///< l + dl
  Vec3d ball_in_plate_mm = Vec3d::Zero();  ///< a_i in the plate frame

  /// B_i for the slider command s (mm).
  Vec3d pin_mm(double slider_mm) const { return pin_at_zero_mm - (slider_mm + slider_zero_mm) * screw_down; }
};

/// The three chains' frames for this geometry and these errors.
std::array<ChainFrame, 3> chain_frames(const Geometry& g, const Errors& e);

}  // namespace ncpost::trr
