// SPDX-License-Identifier: Apache-2.0
// RND / CHF: where the rounding or the chamfer leaves and joins the lines (klartext_corner.hpp).
#include "read/klartext/klartext_corner.hpp"

#include <fmt/format.h>

#include <cmath>

namespace ncpost::klartext {

std::variant<Corner, std::string> corner_of(const Eigen::Vector2d& from_xy, const Eigen::Vector2d& corner_xy,
                                            const Eigen::Vector2d& to_xy, double length_mm, bool rounding) {
  const char* what = rounding ? "RND" : "CHF";
  const Eigen::Vector2d in = corner_xy - from_xy, out = to_xy - corner_xy;
  if (in.norm() < 1e-9 || out.norm() < 1e-9)
    return fmt::format("{}: a line beside the corner has no length in X Y", what);
  const Eigen::Vector2d u1 = in.normalized(), u2 = out.normalized();
  const double turn_rad = std::atan2(u1.x() * u2.y() - u1.y() * u2.x(), u1.dot(u2));  // > 0: a left turn
  if (std::abs(turn_rad) < 1e-9)
    return fmt::format("{}: the lines beside it run straight on: there is no corner", what);
  if (std::abs(turn_rad) > M_PI - 1e-6) return fmt::format("{}: the second line runs back along the first", what);
  if (!(length_mm > 0.0)) return fmt::format("{} {}: expected a length > 0", what, length_mm);
  const double along_mm = rounding ? length_mm * std::tan(std::abs(turn_rad) / 2.0) : length_mm;
  if (along_mm > in.norm() + 1e-9 || along_mm > out.norm() + 1e-9)
    return fmt::format("{} {}: the {} needs {:.4f} mm of each line, longer than the line{} ({:.4f} and {:.4f} mm)",
                       what, length_mm, rounding ? "rounding" : "chamfer", along_mm,
                       in.norm() < out.norm() ? " before" : " after", in.norm(), out.norm());
  Corner c;
  c.leave_xy = corner_xy - along_mm * u1;
  c.join_xy = corner_xy + along_mm * u2;
  c.counter_clockwise = turn_rad > 0.0;
  const Eigen::Vector2d left(-u1.y(), u1.x());
  c.centre_xy = c.leave_xy + (c.counter_clockwise ? 1.0 : -1.0) * length_mm * left;
  return c;
}

}  // namespace ncpost::klartext
