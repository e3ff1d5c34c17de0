// SPDX-License-Identifier: Apache-2.0
#pragma once
// The unit constants every layer uses, defined once (each file of a library may be compiled in one
// unit with others: cmake/ncpost_helpers.cmake, ncpost_unity).

namespace ncpost {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kTwoPi = 2.0 * kPi;
inline constexpr double kDegPerRad = 180.0 / kPi;
inline constexpr double kRadPerDeg = kPi / 180.0;
inline constexpr double kMmPerInch = 25.4;  ///< exact, by definition

inline double deg_to_rad(double deg) { return deg * kRadPerDeg; }
inline double rad_to_deg(double rad) { return rad * kDegPerRad; }

}  // namespace ncpost
