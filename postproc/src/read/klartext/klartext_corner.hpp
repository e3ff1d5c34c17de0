// SPDX-License-Identifier: Apache-2.0
#pragma once
// RND and CHF of Klartext (TNC 640 user manual, "Path contours - Cartesian coordinates"): the corner
// between two straight lines in the working plane X Y (tool axis Z) rounded or chamfered:
//   RND R..  an arc of radius R tangent to both lines; it leaves the first line at T1 and joins the
//            second at T2, each R·tan(θ/2) from the corner (θ the angle the path turns there),
//            counter-clockwise where the path turns left;
//   CHF s    a straight chamfer from T1 to T2, each s from the corner along its line.
// The corner itself is not reached. Program coordinates (X Y mm), as klartext_arc.hpp.
#include <string>
#include <variant>

#include <Eigen/Core>

namespace ncpost::klartext {

struct Corner {
  Eigen::Vector2d leave_xy;   ///< T1, on the first line
  Eigen::Vector2d join_xy;    ///< T2, on the second line
  Eigen::Vector2d centre_xy;  ///< RND: the arc's centre
  bool counter_clockwise = false;
};

/// The corner at `corner_xy` between the line from `from_xy` and the line to `to_xy`, rounded by
/// `radius_mm` (rounding) or chamfered by `side_mm` along each line; `what` names the statement in
/// the message when the corner does not allow it (lines too short, straight on or back).
std::variant<Corner, std::string> corner_of(const Eigen::Vector2d& from_xy, const Eigen::Vector2d& corner_xy,
                                            const Eigen::Vector2d& to_xy, double length_mm, bool rounding);

}  // namespace ncpost::klartext
