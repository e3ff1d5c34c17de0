// SPDX-License-Identifier: Apache-2.0
#pragma once
// Moves of a measurement program while the instrument is on the machine (issue 14 item 14): the
// tool point (ballbar tool ball, probe stylus) is guided, never left to the straight line the
// control interpolates between two poses in axis space (that line swings it off by the sagitta:
// ≈4 mm between sphere poses 30° apart, ≈29 mm for a 90° B turn at 100 mm tool length).
//
// A guided turn moves the rotary axes from one pose to the next in steps, each pose putting the
// tool point on target(rotary angles); steps are halved until the straight line in axis space
// between any two of them stays within `tolerance_mm` of the target everywhere (checked at 8
// points per step on the nominal forward kinematics).
#include <functional>
#include <vector>

#include "ncpost/kinematics/machine.hpp"

namespace ncpost::comp {

using TargetOfRotary = std::function<Vec3d(const Eigen::Vector2d& rotary_rad)>;

/// The poses after `from` up to and including the end pose (rotary `to_rad`, tool point on
/// target(to_rad)). Throws std::invalid_argument if 4096 steps do not reach the tolerance.
std::vector<AxisPosition> guided_turn(const Machine& machine, const Eigen::Vector2d& from_rad,
                                      const Eigen::Vector2d& to_rad, const TargetOfRotary& target_W, const Setup& setup,
                                      double tolerance_mm);

/// The largest distance of the tool point from target along the axis-space straight line a → b
/// (sampled at `samples` inner points), with the target taken at the interpolated rotary angles.
double largest_deviation(const Machine& machine, const AxisPosition& a, const AxisPosition& b,
                         const TargetOfRotary& target_W, const Setup& setup, int samples = 8);

}  // namespace ncpost::comp
