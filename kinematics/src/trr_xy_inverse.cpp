// SPDX-License-Identifier: Apache-2.0
#include "ncpost/kinematics/trr_xy_inverse.hpp"

#include <cmath>

#include <fmt/format.h>

namespace ncpost::trr {
namespace {

/// The rotation taking e_z to the unit `axis` about e_z × axis (no spin).
Mat3d align_z_to(const Vec3d& axis) {
  const Vec3d c = Vec3d::UnitZ().cross(axis);
  const double s = c.norm();
  if (s < 1e-15) return Mat3d::Identity();
  return rotation_about<double>(c / s, std::atan2(s, axis.z()));
}

}  // namespace

std::optional<Rigidd> nominal_plate_for(const Geometry& g, const Vec3d& axis, double tcp_z_mm, std::string* why) {
  const std::array<ChainFrame, 3> chains = chain_frames(g, Errors{});
  const Mat3d tilt = align_z_to(axis);
  const double pz = tcp_z_mm + g.tip_offset_mm() * axis.z();
  Eigen::Vector3d x(0, 0, 0);  // plate x, y (mm), spin ψ (rad)
  for (int it = 0; it < 50; ++it) {
    const Mat3d R = tilt * rotation_about<double>(Vec3d::UnitZ(), x[2]);
    const Vec3d P(x[0], x[1], pz);
    Eigen::Vector3d f;
    Eigen::Matrix3d J;
    for (int i = 0; i < 3; ++i) {
      const ChainFrame& c = chains[static_cast<std::size_t>(i)];
      const Vec3d ra = R * c.ball_in_plate_mm;
      f[i] = (P + ra).dot(c.tangential);  // B_i·t_i = 0 on the nominal machine
      J(i, 0) = c.tangential.x();
      J(i, 1) = c.tangential.y();
      J(i, 2) = axis.cross(ra).dot(c.tangential);
    }
    const Eigen::Vector3d step = J.fullPivLu().solve(-f);
    if (!step.allFinite()) break;
    x += step;
    if (step.head<2>().norm() < 1e-12 && std::abs(step[2]) < 1e-14) {
      Rigidd pose;
      pose.R = tilt * rotation_about<double>(Vec3d::UnitZ(), x[2]);
      pose.t = Vec3d(x[0], x[1], pz);
      return pose;
    }
  }
  if (why) *why = "inverse kinematics: the pin-plane constraints have no solution for this tool axis";
  return std::nullopt;
}

std::optional<Vec3d> nominal_sliders_for(const Geometry& g, const Rigidd& machine_T_plate, std::string* why) {
  const std::array<ChainFrame, 3> chains = chain_frames(g, Errors{});
  const double H = g.pin_height_mm(), l = g.link_length_mm;
  Vec3d s;
  for (int i = 0; i < 3; ++i) {
    const ChainFrame& c = chains[static_cast<std::size_t>(i)];
    const Vec3d S = machine_T_plate.apply(c.ball_in_plate_mm);
    const Vec3d h = S - g.base_radius_mm * c.radial;
    const double h2 = h.x() * h.x() + h.y() * h.y();
    if (h2 >= l * l) {
      if (why)
        *why =
            fmt::format("link of chain {} cannot reach its screw line (ball joint {:.1f} mm from it, link {:.1f} mm)",
                        "abc"[i], std::sqrt(h2), l);
      return std::nullopt;
    }
    s[i] = H - S.z() - std::sqrt(l * l - h2);  // the root with the pin joint above the ball joint
  }
  const std::string reach = link_reach_failure(g, chains, s, machine_T_plate);
  if (!reach.empty()) {
    if (why) *why = reach;
    return std::nullopt;
  }
  return s;
}

std::string limits_failure(const Machine& m, const Command& c) {
  static const char kWords[] = "XYUVW";
  const auto v = c.words();
  for (int j = 0; j < 5; ++j) {
    const std::optional<AxisLimits>& lim = j < 2 ? m.table_limits[j] : m.slider_limits[j - 2];
    if (lim && !lim->contains(v[j], 1e-6))
      return fmt::format("{}{:.4f} is outside the limits [{:g}, {:g}] mm", kWords[j], v[j], lim->min, lim->max);
  }
  return {};
}

InverseOutcome inverse(const Kinematics& k, const ClPoint& cl, const Vec3d& workpiece_origin_mm, bool check_limits) {
  InverseOutcome out;
  const Geometry& g = k.geometry();
  const Vec3d axis = cl.axis.normalized();
  const Vec3d target_mm = workpiece_origin_mm + cl.tip_mm;  // where the TCP must be, at the table's home
  if (axis.z() <= 1e-6) {
    out.failure = "tool axis at or beyond 90 deg from +Z: out of reach of the parallel head";
    return out;
  }
  std::optional<Rigidd> plate = nominal_plate_for(g, axis, target_mm.z(), &out.failure);
  if (!plate) return out;
  std::optional<Vec3d> sliders = nominal_sliders_for(g, *plate, &out.failure);
  if (!sliders) return out;
  Vec3d s = *sliders;
  Vec3d tcp = plate->t - g.tip_offset_mm() * axis;

  if (!k.actual_errors().all_zero()) {
    // Newton on the sliders: actual tool axis (x, y components) and actual TCP height.
    std::optional<Rigidd> warm = plate;
    bool converged = false;
    for (int it = 0; it < 30 && !converged; ++it) {
      std::optional<ToolPose> tp = k.tool(s, warm, &out.failure);
      if (!tp) return out;
      warm = tp->machine_T_plate;
      const Vec3d f(tp->axis.x() - axis.x(), tp->axis.y() - axis.y(), tp->tcp_mm.z() - target_mm.z());
      if (f.head<2>().norm() < 1e-14 && std::abs(f.z()) < 1e-11) {
        converged = true;
        plate = tp->machine_T_plate;
        tcp = tp->tcp_mm;
        break;
      }
      Eigen::Matrix3d J;
      constexpr double h = 1e-4;  // mm
      for (int j = 0; j < 3; ++j) {
        Vec3d sj = s;
        sj[j] += h;
        std::optional<ToolPose> tj = k.tool(sj, warm, &out.failure);
        if (!tj) return out;
        J.col(j) = (Vec3d(tj->axis.x() - axis.x(), tj->axis.y() - axis.y(), tj->tcp_mm.z() - target_mm.z()) - f) / h;
      }
      const Vec3d step = J.fullPivLu().solve(-f);
      if (!step.allFinite()) break;
      s += step;
    }
    if (!converged) {
      out.failure = "inverse kinematics on the error model did not converge";
      return out;
    }
  }
  Command c;
  c.slider_mm = s;
  c.table_mm = (target_mm - tcp).head<2>();
  if (check_limits) {
    out.failure = limits_failure(k.machine(), c);
    if (!out.failure.empty()) return out;
  }
  out.machine_T_plate = *plate;
  out.command = c;
  out.failure.clear();
  return out;
}

}  // namespace ncpost::trr
