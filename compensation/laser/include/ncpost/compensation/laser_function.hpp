// SPDX-License-Identifier: Apache-2.0
#pragma once
// One identified component error function of a linear axis (issue 7): its values at the targets
// and home, the curve the model carries between them (laser_smooth.hpp: the table itself, a cubic
// spline or a Legendre polynomial, by cross-validation; written as a dense table that the error model
// evaluates as `E<c><axis>:t:<pos>`, parameter_name.hpp), its polynomial p1..p3 through home, and for
// a straightness its ISO 230-1 least-squares reference line. Values in mm (X Y Z components) or rad (A B C).
#include <array>
#include <string>
#include <vector>

#include "ncpost/compensation/laser_smooth.hpp"

namespace ncpost::comp {

/// One component error function E<component><axis> as identified.
struct LaserFunction {
  char component = 'X';  ///< X Y Z (mm) or A B C (rad)
  char axis = 'X';
  std::vector<double> nodes_mm;
  std::vector<double> values;                       ///< mm or rad, ISO 230-1 reference (straightness slope removed)
  std::vector<double> sigma;                        ///< standard deviation of each node (0 where pinned or at home)
  std::vector<bool> seen;                           ///< node identified (home counts as seen)
  std::array<double, 3> polynomial{0.0, 0.0, 0.0};  ///< p1..p3, value·x^k, x in mm
  double polynomial_rms = 0.0;                      ///< rms of the table about the polynomial (mm / rad)
  double iso_slope = 0.0;                           ///< straightness: least-squares slope moved into squareness (rad)
  double iso_straightness_um = 0.0;                 ///< straightness: max − min about the least-squares line
  LaserCurve curve;                                 ///< the model between the nodes (linear: the nodes themselves)

  std::string name() const { return std::string{'E', component, axis}; }
  bool is_angle() const { return component >= 'A' && component <= 'C'; }
  bool fully_seen() const;
  bool partly_seen() const;
  /// "positioning", "straightness in Y", "roll", "pitch", "yaw" (ISO 230-1 words for a VMC).
  std::string kind() const;
  /// The model's value at x (mm / rad): the curve's dense table interpolated, as the error model does.
  double at(double x_mm) const;
};

/// Least-squares line a + s·x through the points; returns the slope s and sets the range
/// (max − min) of the points about the line.
double least_squares_slope(const std::vector<double>& x, const std::vector<double>& y, double& range_about);

/// p1..p3 (value·x^k) through the origin fitted to the points; returns the rms about it. Fewer
/// than four points fit fewer terms (the rest 0).
double fit_polynomial_through_home(const std::vector<double>& x, const std::vector<double>& y,
                                   std::array<double, 3>& p);

}  // namespace ncpost::comp
