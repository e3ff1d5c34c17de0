// SPDX-License-Identifier: Apache-2.0
#pragma once
// Circular (and helical, and slightly spiral) G2/G3 arcs in program coordinates, and their
// expansion into points with a bounded chord error.
//
// Plane axes (a1, a2, normal): G17 (X, Y, Z), G18 (Z, X, Y), G19 (Y, Z, X); each triple is
// right-handed, so G3 (counter-clockwise seen from +normal) is a positive angle from a1 toward a2.
// The control moves the helix axis and the rotary axes linearly with the angle, and the radius
// linearly from the start radius to the end radius (LinuxCNC's spiral rule).
// Lengths in mm, angles in rad.
#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "ncpost/postproc/read/cl_record.hpp"

namespace ncpost::gcode {

/// X Y Z (mm) and A B C (rad) as programmed, after unit conversion.
using ProgramPoint = std::array<double, 6>;

enum class Plane { xy, zx, yz };  ///< G17, G18, G19

struct PlaneAxes {
  int a1, a2, normal;  ///< ProgramPoint indices
};
PlaneAxes axes_of(Plane plane);

struct ArcMove {
  ProgramPoint start{};
  ProgramPoint end{};
  PlaneAxes axes{0, 1, 2};
  double centre1_mm = 0.0;  ///< centre along a1 (absolute)
  double centre2_mm = 0.0;  ///< centre along a2 (absolute)
  double radius_start_mm = 0.0;
  double radius_end_mm = 0.0;
  double angle_start_rad = 0.0;  ///< of the start point about the centre, from a1 toward a2
  double sweep_rad = 0.0;        ///< signed: > 0 counter-clockwise (G3), < 0 clockwise (G2)

  /// The point at fraction t in [0, 1] of the sweep (exactly `end` at t = 1).
  ProgramPoint at(double t) const;
};

/// An arc or the reason there is none (the message says what was expected).
struct ArcOutcome {
  std::optional<ArcMove> arc;
  std::string error;
};

/// Arc given by its centre (absolute, along a1 and a2). `turns` >= 1 (LinuxCNC P word).
/// Start = end means a full circle.
ArcOutcome arc_from_centre(const ProgramPoint& start, const ProgramPoint& end, Plane plane, bool clockwise,
                           double centre1_mm, double centre2_mm, int turns);

using cl::ArcCentre;

/// The centre (absolute, along a1 and a2) that the offsets I J K (along a1 and a2, mm) name under
/// `reading`, for an arc from `start`.
std::array<double, 2> arc_centre_of(ArcCentre reading, const ProgramPoint& start, PlaneAxes axes, double offset1_mm,
                                    double offset2_mm);

/// The --arc-centre value that names `reading` ("incremental", "centre-to-start", "absolute").
std::string_view arc_centre_name(ArcCentre reading);

/// What `reading` takes I and J (in the plane's letters, e.g. "I and J") to be, for messages.
std::string arc_centre_meaning(ArcCentre reading, std::string_view letters);

/// Arc given by its radius (R word; negative: the arc longer than half a circle).
ArcOutcome arc_from_radius(const ProgramPoint& start, const ProgramPoint& end, Plane plane, bool clockwise,
                           double radius_mm, int turns);

/// Number of equal segments whose chord error (in the plane) stays within `chord_tolerance_mm`.
long arc_segments(const ArcMove& arc, double chord_tolerance_mm);

/// Largest number of points an arc may expand to (bad input beyond).
constexpr long kMaxArcSegments = 200'000;

}  // namespace ncpost::gcode
