// SPDX-License-Identifier: Apache-2.0
#pragma once
// Forward kinematics of the TRR-XY machine (trr_xy_geometry.hpp, docs/trr-xy.md "Forward
// kinematics"): from the slider commands (s_a, s_b, s_c) to the plate pose `machine_T_plate`
// (plate frame: origin at the ball-joint plane centre P_c, axes R_p; the tool axis is R_p·e_z)
// by Newton–Raphson on the three link lengths and the three pin-plane constraints, starting
// from a previous pose (seed 004).
//
// Errors act relative to home (docs/conventions.md "Setup at home"): the tool side moves by
// `machine_T_plate(s) · machine_T_plate(0)⁻¹`, where both are poses of the actual machine; the
// TCP is where that transform takes the origin of M, the tool axis where it turns e_z. On the
// nominal machine this is P_c − (hs + lt)·R_p·e_z and R_p·e_z.
// Lengths in mm, angles in rad, all in M.
#include <optional>
#include <string>

#include "ncpost/kinematics/trr_xy_geometry.hpp"

namespace ncpost::trr {

/// Commands: table X, Y (mm) and sliders U, V, W of chains a, b, c (mm).
struct Command {
  Eigen::Vector2d table_mm = Eigen::Vector2d::Zero();
  Vec3d slider_mm = Vec3d::Zero();

  /// The five NC values in word order X Y U V W.
  Eigen::Matrix<double, 5, 1> words() const {
    Eigen::Matrix<double, 5, 1> v;
    v << table_mm, slider_mm;
    return v;
  }
  static Command from_words(const Eigen::Matrix<double, 5, 1>& v) {
    Command c;
    c.table_mm = v.head<2>();
    c.slider_mm = v.tail<3>();
    return c;
  }
};

struct PlateOutcome {
  std::optional<Rigidd> machine_T_plate;
  std::string failure;  ///< why there is no pose (no convergence, link out of reach)
  int iterations = 0;
  bool ok() const { return machine_T_plate.has_value(); }
};

/// The six residuals of a plate pose — link length errors (|S_i − B_i|² − L_i²)/(2 L_i) (mm, the
/// length error to first order) and pin-plane distances (S_i − B_i)·p_i (mm) — and their Jacobian
/// in (dP, dω) for the update P ← P + dP, R ← Rot(dω)·R.
void plate_residuals(const std::array<ChainFrame, 3>& chains, const Vec3d& slider_mm, const Rigidd& pose,
                     Eigen::Matrix<double, 6, 1>& f, Eigen::Matrix<double, 6, 6>& J);

/// Newton–Raphson for the plate pose; converges when the update is below 1e-11 mm / rad.
/// Checks the result: every link hangs down from its pin joint (B_i above S_i) within
/// `max_link_angle_rad` of the screw line.
PlateOutcome solve_plate(const Geometry& g, const std::array<ChainFrame, 3>& chains, const Vec3d& slider_mm,
                         const Rigidd& start);

/// Empty if every link hangs down from its pin joint, inward, within the reach angle of its
/// screw line; otherwise why not (names the chain).
std::string link_reach_failure(const Geometry& g, const std::array<ChainFrame, 3>& chains, const Vec3d& slider_mm,
                               const Rigidd& machine_T_plate);

/// Nominal plate pose at home: level, P_c = (0, 0, hs + lt).
Rigidd nominal_home_plate(const Geometry& g);

/// The tool pose relative to the workpiece-independent frame M: TCP (mm) and unit tool axis.
struct ToolPose {
  Vec3d tcp_mm = Vec3d::Zero();
  Vec3d axis = Vec3d::UnitZ();
  Rigidd machine_T_plate;  ///< the actual plate pose (a warm start for the next solve)
};

/// One machine (nominal or with errors) ready to solve: its chain frames and actual home pose.
class Kinematics {
 public:
  /// Throws std::runtime_error if the home pose cannot be solved (errors far too large).
  /// `errors`: a model's errors, on top of the machine's calibration.
  explicit Kinematics(Machine machine, Errors errors = {});

  const Machine& machine() const { return machine_; }
  const Geometry& geometry() const { return machine_.geometry; }
  /// The model's errors (without the machine's calibration).
  const Errors& errors() const { return errors_; }
  /// The parameters the chains are built with: the machine's calibration plus the model's errors
  /// (all zero: the symmetric design, whose inverse kinematics is closed).
  const Errors& actual_errors() const { return actual_errors_; }
  const std::array<ChainFrame, 3>& chains() const { return chains_; }
  /// machine_T_plate of the actual machine at home (all sliders 0).
  const Rigidd& home_plate() const { return home_plate_; }

  /// Plate pose for these sliders, from `start` (default: the home pose).
  PlateOutcome plate(const Vec3d& slider_mm, const std::optional<Rigidd>& start = std::nullopt) const;
  /// Tool pose relative to home (see the header comment) for a plate pose.
  ToolPose tool_from_plate(const Rigidd& machine_T_plate) const;
  /// Tool pose for these sliders; nullopt (with `why`) if the plate cannot be solved.
  std::optional<ToolPose> tool(const Vec3d& slider_mm, const std::optional<Rigidd>& start = std::nullopt,
                               std::string* why = nullptr) const;
  /// Tool tip relative to the workpiece, in W: TCP + (X, Y, 0) − workpiece origin.
  static Vec3d tip_in_workpiece(const ToolPose& tool, const Command& c, const Vec3d& workpiece_origin_mm) {
    return tool.tcp_mm + Vec3d(c.table_mm.x(), c.table_mm.y(), 0.0) - workpiece_origin_mm;
  }

 private:
  Machine machine_;
  Errors errors_;
  Errors actual_errors_;
  std::array<ChainFrame, 3> chains_;
  Rigidd home_plate_;
  Rigidd home_inverse_;  ///< plate_T_machine at home
};

}  // namespace ncpost::trr
