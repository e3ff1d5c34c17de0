// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/plan_moves.hpp"

#include <algorithm>
#include <stdexcept>

#include "ncpost/kinematics/forward.hpp"
#include "ncpost/kinematics/inverse.hpp"

namespace ncpost::comp {
namespace {

AxisPosition pose_at(const Machine& m, const Eigen::Vector2d& rotary_rad, const TargetOfRotary& target,
                     const Setup& setup) {
  AxisPosition q;
  q.rotary_rad = rotary_rad;
  q.linear_mm = linear_for(m, rotary_rad, target(rotary_rad), setup);
  return q;
}

AxisPosition lerp(const AxisPosition& a, const AxisPosition& b, double s) {
  AxisPosition q;
  q.linear_mm = a.linear_mm + s * (b.linear_mm - a.linear_mm);
  q.rotary_rad = a.rotary_rad + s * (b.rotary_rad - a.rotary_rad);
  return q;
}

}  // namespace

double largest_deviation(const Machine& m, const AxisPosition& a, const AxisPosition& b, const TargetOfRotary& target,
                         const Setup& setup, int samples) {
  double worst = 0.0;
  for (int k = 1; k <= samples; ++k) {
    const AxisPosition q = lerp(a, b, double(k) / double(samples + 1));
    worst = std::max(worst, (forward(m, q, setup).tip_mm - target(q.rotary_rad)).norm());
  }
  return worst;
}

std::vector<AxisPosition> guided_turn(const Machine& m, const Eigen::Vector2d& from_rad, const Eigen::Vector2d& to_rad,
                                      const TargetOfRotary& target, const Setup& setup, double tolerance_mm) {
  for (int steps = 1; steps <= 4096; steps *= 2) {
    std::vector<AxisPosition> poses;
    AxisPosition previous = pose_at(m, from_rad, target, setup);
    bool within = true;
    for (int k = 1; k <= steps && within; ++k) {
      const AxisPosition q = pose_at(m, from_rad + (double(k) / steps) * (to_rad - from_rad), target, setup);
      within = largest_deviation(m, previous, q, target, setup) <= tolerance_mm;
      poses.push_back(q);
      previous = q;
    }
    if (within) return poses;
  }
  throw std::invalid_argument("a guided turn needs more than 4096 steps to keep the instrument within tolerance");
}

}  // namespace ncpost::comp
