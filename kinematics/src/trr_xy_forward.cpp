// SPDX-License-Identifier: Apache-2.0
#include "ncpost/kinematics/trr_xy_forward.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <stdexcept>

namespace ncpost::trr {
namespace {

using Mat6 = Eigen::Matrix<double, 6, 6>;
using Vec6 = Eigen::Matrix<double, 6, 1>;

}  // namespace

void plate_residuals(const std::array<ChainFrame, 3>& chains, const Vec3d& slider_mm, const Rigidd& pose,
                     Eigen::Matrix<double, 6, 1>& f, Eigen::Matrix<double, 6, 6>& J) {
  for (int i = 0; i < 3; ++i) {
    const ChainFrame& c = chains[static_cast<std::size_t>(i)];
    const Vec3d ra = pose.R * c.ball_in_plate_mm;
    const Vec3d S = pose.t + ra;
    const Vec3d v = S - c.pin_mm(slider_mm[i]);  // link, from the pin joint to the ball joint
    const double L = c.link_length_mm;
    f[i] = (v.squaredNorm() - L * L) / (2.0 * L);
    J.block<1, 3>(i, 0) = v.transpose() / L;
    J.block<1, 3>(i, 3) = ra.cross(v).transpose() / L;
    f[3 + i] = v.dot(c.pin_axis);
    J.block<1, 3>(3 + i, 0) = c.pin_axis.transpose();
    J.block<1, 3>(3 + i, 3) = ra.cross(c.pin_axis).transpose();
  }
}

std::string link_reach_failure(const Geometry& g, const std::array<ChainFrame, 3>& chains, const Vec3d& slider_mm,
                               const Rigidd& machine_T_plate) {
  for (int i = 0; i < 3; ++i) {
    const ChainFrame& c = chains[static_cast<std::size_t>(i)];
    const Vec3d link = c.pin_mm(slider_mm[i]) - machine_T_plate.apply(c.ball_in_plate_mm);  // from S up to B
    const double angle = std::acos(std::clamp(link.normalized().dot(c.screw_down), -1.0, 1.0));
    if (link.dot(c.screw_down) <= 0.0 || angle > g.max_link_angle_rad)
      return fmt::format(
          "link of chain {} at {:.2f} deg from its screw line (reach: hanging below its pin joint within "
          "{:.1f} deg)",
          "abc"[i], rad_to_deg(angle), rad_to_deg(g.max_link_angle_rad));
    if (link.dot(c.radial) <= 0.0)
      return fmt::format("link of chain {} leans outward (its ball joint is outside the screw line)", "abc"[i]);
  }
  return {};
}

PlateOutcome solve_plate(const Geometry& g, const std::array<ChainFrame, 3>& chains, const Vec3d& slider_mm,
                         const Rigidd& start) {
  PlateOutcome out;
  Rigidd pose = start;
  Vec6 f;
  Mat6 J;
  bool converged = false;
  for (int it = 0; it < 60 && !converged; ++it) {
    plate_residuals(chains, slider_mm, pose, f, J);
    const Eigen::FullPivLU<Mat6> lu(J);
    if (lu.rank() < 6) {
      out.failure = "forward kinematics: singular configuration of the parallel head";
      return out;
    }
    const Vec6 step = lu.solve(-f);
    if (!step.allFinite()) break;
    pose.t += step.head<3>();
    pose.R = rotation_vector<double>(step.tail<3>()) * pose.R;
    out.iterations = it + 1;
    converged = step.head<3>().norm() < 1e-11 && step.tail<3>().norm() < 1e-13;
  }
  if (!converged) {
    out.failure = fmt::format("forward kinematics: Newton-Raphson did not converge for sliders {:.4f} {:.4f} {:.4f} mm",
                              slider_mm[0], slider_mm[1], slider_mm[2]);
    return out;
  }
  // re-orthonormalise the rotation (accumulated products of exact rotations drift slowly)
  const Eigen::JacobiSVD<Mat3d> svd(pose.R, Eigen::ComputeFullU | Eigen::ComputeFullV);
  pose.R = svd.matrixU() * svd.matrixV().transpose();
  out.failure = link_reach_failure(g, chains, slider_mm, pose);
  if (!out.failure.empty()) return out;
  out.machine_T_plate = pose;
  return out;
}

Rigidd nominal_home_plate(const Geometry& g) { return Rigidd::translation(Vec3d(0, 0, g.tip_offset_mm())); }

Kinematics::Kinematics(Machine machine, Errors errors)
    : machine_(std::move(machine)),
      errors_(errors),
      actual_errors_(machine_.calibration + errors_),
      chains_(chain_frames(machine_.geometry, actual_errors_)) {
  const PlateOutcome home =
      solve_plate(machine_.geometry, chains_, Vec3d::Zero(), nominal_home_plate(machine_.geometry));
  if (!home.ok()) throw std::runtime_error("TRR-XY: the home pose cannot be solved: " + home.failure);
  home_plate_ = *home.machine_T_plate;
  home_inverse_ = home_plate_.inverse();
}

PlateOutcome Kinematics::plate(const Vec3d& slider_mm, const std::optional<Rigidd>& start) const {
  return solve_plate(machine_.geometry, chains_, slider_mm, start ? *start : home_plate_);
}

ToolPose Kinematics::tool_from_plate(const Rigidd& machine_T_plate) const {
  const Rigidd moved = machine_T_plate * home_inverse_;  // tool side: actual pose relative to actual home
  ToolPose tp;
  tp.tcp_mm = moved.t;
  tp.axis = moved.R.col(2);
  tp.machine_T_plate = machine_T_plate;
  return tp;
}

std::optional<ToolPose> Kinematics::tool(const Vec3d& slider_mm, const std::optional<Rigidd>& start,
                                         std::string* why) const {
  const PlateOutcome p = plate(slider_mm, start);
  if (!p.ok()) {
    if (why) *why = p.failure;
    return std::nullopt;
  }
  return tool_from_plate(*p.machine_T_plate);
}

}  // namespace ncpost::trr
