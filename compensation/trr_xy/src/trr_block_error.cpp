// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/trr_block_error.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ncpost::trr {

std::optional<ExecutedPoint> BlockEvaluator::at(const Block& b, double t, EvaluatorWork& work, std::string* why) const {
  const Command c = Command::from_words((1.0 - t) * b.from.words() + t * b.to.words());
  const std::optional<ToolPose> tp = k_.tool(c.slider_mm, work.warm_plate, why);
  if (!tp) return std::nullopt;
  work.warm_plate = tp->machine_T_plate;
  ExecutedPoint e;
  e.tip_mm = Kinematics::tip_in_workpiece(*tp, c, origin_);
  e.axis = tp->axis;
  const Vec3d a = b.from_cl.tip_mm, d = b.to_cl.tip_mm - a;
  const double len2 = d.squaredNorm();
  const double u = len2 > 0 ? std::clamp((e.tip_mm - a).dot(d) / len2, 0.0, 1.0) : 0.0;
  e.offset_mm = e.tip_mm - (a + u * d);
  const Vec3d axis_cl = ((1.0 - t) * b.from_cl.axis + t * b.to_cl.axis).normalized();
  e.orientation_rad = std::atan2(e.axis.cross(axis_cl).norm(), e.axis.dot(axis_cl));
  return e;
}

BlockError BlockEvaluator::evaluate(const Block& b, EvaluatorWork& work, int samples) const {
  BlockError r;
  std::string why;
  auto eval = [&](double t) {
    const std::optional<ExecutedPoint> e = at(b, t, work, &why);
    if (!e) throw std::runtime_error(why);
    return *e;
  };
  std::vector<double> mag(static_cast<std::size_t>(samples) + 1, 0.0);
  int best = 0;
  for (int j = 0; j <= samples; ++j) {
    const double t = static_cast<double>(j) / samples;
    const ExecutedPoint e = eval(t);
    mag[static_cast<std::size_t>(j)] = e.offset_mm.norm();
    if (mag[static_cast<std::size_t>(j)] > r.max_mm) {
      r.max_mm = mag[static_cast<std::size_t>(j)];
      r.at_t = t;
      r.offset_mm = e.offset_mm;
      best = j;
    }
    if (e.orientation_rad > r.orientation_rad) {
      r.orientation_rad = e.orientation_rad;
      r.orientation_at_t = t;
    }
  }
  // golden-section refinement of the largest deviation in the bracket around the best sample
  double lo = std::max(0.0, (best - 1.0) / samples), hi = std::min(1.0, (best + 1.0) / samples);
  constexpr double g = 0.6180339887498949;
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  ExecutedPoint e1 = eval(x1), e2 = eval(x2);
  for (int it = 0; it < 30 && hi - lo > 1e-7; ++it) {
    if (e1.offset_mm.norm() > e2.offset_mm.norm()) {
      hi = x2;
      x2 = x1;
      e2 = e1;
      x1 = hi - g * (hi - lo);
      e1 = eval(x1);
    } else {
      lo = x1;
      x1 = x2;
      e1 = e2;
      x2 = lo + g * (hi - lo);
      e2 = eval(x2);
    }
  }
  for (const auto& [x, e] : {std::pair{x1, e1}, std::pair{x2, e2}}) {
    if (e.offset_mm.norm() > r.max_mm) {
      r.max_mm = e.offset_mm.norm();
      r.at_t = x;
      r.offset_mm = e.offset_mm;
    }
  }
  r.midpoint_mm = eval(0.5).offset_mm.norm();
  for (int j = 0; j <= samples; ++j) {
    const double t = static_cast<double>(j) / samples;
    r.harmonic_residual_mm = std::max(r.harmonic_residual_mm,
                                      std::abs(mag[static_cast<std::size_t>(j)] - r.midpoint_mm * std::sin(kPi * t)));
  }
  return r;
}

}  // namespace ncpost::trr
