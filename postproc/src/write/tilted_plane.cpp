// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/write/tilted_plane.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace ncpost {
namespace {

constexpr double kDeg = 180.0 / 3.14159265358979323846;
constexpr double kDegenerate = 1e-9;  ///< |sin| of the middle angle below which the triple is not unique

Mat3d rz(double deg) { return Eigen::AngleAxisd(deg / kDeg, Vec3d::UnitZ()).toRotationMatrix(); }
Mat3d ry(double deg) { return Eigen::AngleAxisd(deg / kDeg, Vec3d::UnitY()).toRotationMatrix(); }
Mat3d rx(double deg) { return Eigen::AngleAxisd(deg / kDeg, Vec3d::UnitX()).toRotationMatrix(); }

/// `deg` plus the whole turns that bring it nearest `near`.
double unwound(double deg, double near) { return deg + 360.0 * std::round((near - deg) / 360.0); }
/// In (-180, 180].
double principal(double deg) {
  double d = std::fmod(deg, 360.0);
  if (d <= -180.0) d += 360.0;
  if (d > 180.0) d -= 360.0;
  return d;
}

using Triple = std::array<double, 3>;

Triple pick(const std::vector<Triple>& candidates, const std::optional<Triple>& previous) {
  if (!previous) {
    const Triple& t = candidates.front();
    return {principal(t[0]), principal(t[1]), principal(t[2])};
  }
  Triple best{};
  double best_cost = 1e300;
  for (const Triple& t : candidates) {
    Triple u;
    double cost = 0.0;
    for (std::size_t i = 0; i < 3; ++i) {
      u[i] = unwound(t[i], (*previous)[i]);
      cost += std::abs(u[i] - (*previous)[i]);
    }
    if (cost < best_cost - 1e-12) {
      best_cost = cost;
      best = u;
    }
  }
  return best;
}

Triple euler_zxz(const Mat3d& R, const std::optional<Triple>& previous) {
  const double b = std::acos(std::clamp(R(2, 2), -1.0, 1.0)) * kDeg;
  const double sb = std::sqrt(R(0, 2) * R(0, 2) + R(1, 2) * R(1, 2));
  if (sb < kDegenerate) {
    // b = 0: Rz(a + c); b = 180: Rz(a) Rx(180) Rz(c) turns by a - c. a keeps its previous value.
    const double a = previous ? (*previous)[0] : 0.0;
    const double turn = std::atan2(R(1, 0), R(0, 0)) * kDeg;
    const double bb = R(2, 2) > 0.0 ? 0.0 : 180.0;
    double c = R(2, 2) > 0.0 ? turn - a : a - turn;
    c = previous ? unwound(c, (*previous)[2]) : principal(c);
    return {a, previous ? unwound(bb, (*previous)[1]) : bb, c};
  }
  const double a = std::atan2(R(0, 2), -R(1, 2)) * kDeg;
  const double c = std::atan2(R(2, 0), R(2, 1)) * kDeg;
  return pick({{a, b, c}, {a + 180.0, -b, c + 180.0}}, previous);
}

Triple fixed_xyz(const Mat3d& R, const std::optional<Triple>& previous) {
  const double cb = std::sqrt(R(2, 1) * R(2, 1) + R(2, 2) * R(2, 2));
  if (cb < kDegenerate) {
    // b = ±90: c keeps its previous value, a takes up the rest (Rz(c)^T R = Ry(b) Rx(a))
    const double c = previous ? (*previous)[2] : 0.0;
    const Mat3d M = rz(c).transpose() * R;
    const double b = R(2, 0) < 0.0 ? 90.0 : -90.0;
    double a = std::atan2(-M(1, 2), M(1, 1)) * kDeg;
    a = previous ? unwound(a, (*previous)[0]) : principal(a);
    return {a, previous ? unwound(b, (*previous)[1]) : b, c};
  }
  const double b = std::asin(std::clamp(-R(2, 0), -1.0, 1.0)) * kDeg;
  const double a = std::atan2(R(2, 1), R(2, 2)) * kDeg;
  const double c = std::atan2(R(1, 0), R(0, 0)) * kDeg;
  return pick({{a, b, c}, {a + 180.0, 180.0 - b, c + 180.0}}, previous);
}

}  // namespace

Mat3d plane_rotation(TiltedPlaneWords::Angles convention, const std::array<double, 3>& angles_deg) {
  const auto& [a, b, c] = angles_deg;
  if (convention == TiltedPlaneWords::Angles::euler_zxz) return rz(a) * rx(b) * rz(c);
  return rz(c) * ry(b) * rx(a);
}

std::array<double, 3> plane_angles(TiltedPlaneWords::Angles convention, const Mat3d& P_R_F,
                                   const std::optional<std::array<double, 3>>& previous_deg) {
  return convention == TiltedPlaneWords::Angles::euler_zxz ? euler_zxz(P_R_F, previous_deg)
                                                           : fixed_xyz(P_R_F, previous_deg);
}

Mat3d plane_frame(const Vec3d& axis_P, const Vec3d& x_hint_P, const Vec3d& y_hint_P) {
  const Vec3d z = axis_P.normalized();
  Vec3d x = x_hint_P - x_hint_P.dot(z) * z;
  Mat3d R;
  if (x.norm() >= 1e-6) {
    x.normalize();
    R.col(0) = x;
    R.col(1) = z.cross(x);
  } else {
    Vec3d y = y_hint_P - y_hint_P.dot(z) * z;
    y.normalize();
    R.col(0) = y.cross(z);
    R.col(1) = y;
  }
  R.col(2) = z;
  return R;
}

}  // namespace ncpost
