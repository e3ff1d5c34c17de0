// SPDX-License-Identifier: Apache-2.0
#pragma once
// How an identified laser error function is carried between its targets (issue 25 item 6).
//
// The laser data give a function's value at the targets only (50 mm apart on the bundled plan);
// between them the model must say something. Three candidates, on the node values (targets and
// home, mm → mm or rad):
//   linear    the table itself, linear between nodes (error_model.hpp tables);
//   spline    the cubic spline through the nodes, not-a-knot ends (C², no end condition
//             invented: the first and last two intervals are one cubic each);
//   legendre  a least-squares polynomial of degree d (1 ≤ d ≤ min(max_degree, n − 3)) in
//             u = (x − centre) / half span, Legendre basis (well conditioned), shifted through home;
//             tried only when asked (max_degree > 0): on unseen smooth errors it smoothed away
//             real structure the 13 nodes carried (bench/laser_unseen_bench.cpp).
// Selection rule: leave-one-out cross-validation. Each interior node (not the two ends: the
// functions are compared where they interpolate) is left out in turn, the candidate is fitted to
// the others and predicts it; the candidate with the smallest rms prediction error wins, a simpler
// one (linear < legendre of lower degree < spline < higher degree) when within kCvTie of the best.
// Noise-only functions thus stay low-order, smooth ones get the curve their data support.
// The chosen curve is written as a dense table (every `step_mm`, plus every target) over the
// measured span, so the error model's linear interpolation follows it (h²/8·f'' below 0.02 µm
// for a 5 mm step on positioning curves of 30 µm over 100 mm); outside the span the table holds
// its end values, as every table does (no extrapolation beyond the measured travel).
#include <string>
#include <vector>

namespace ncpost::comp {

enum class LaserBasis { linear, spline, legendre };

struct LaserCurve {
  LaserBasis basis = LaserBasis::linear;
  int degree = 0;                        ///< legendre
  double cv_rms = 0.0;                   ///< leave-one-out rms of the chosen candidate (mm or rad)
  double cv_linear_rms = 0.0;            ///< of the table (linear), for the report
  std::vector<double> nodes_mm, values;  ///< the dense table (mm or rad; 0 at home)

  /// "linear", "spline", "legendre 4".
  std::string label() const;
};

/// Largest Legendre degree tried.
constexpr int kMaxLegendreDegree = 8;
/// Candidates within this fraction of the best cross-validation rms count as equal.
constexpr double kCvTie = 0.05;

/// The cubic spline with not-a-knot ends through (x, y) at `at` (x ascending, at least 2 points;
/// 2 points: the line, 3: the parabola). Outside [x.front(), x.back()]: the end cubic continued.
double spline_at(const std::vector<double>& x, const std::vector<double>& y, double at);

/// The least-squares polynomial of `degree` through (x, y) at each of `at` (Legendre basis on
/// the span of x).
std::vector<double> legendre_fit_at(const std::vector<double>& x, const std::vector<double>& y, int degree,
                                    const std::vector<double>& at);

/// The chosen curve of the node values (x ascending, with home at 0 and y = 0 there), its dense
/// table every `step_mm` over [x.front(), x.back()]; Legendre degrees up to `max_degree` (0: only
/// the curves through the nodes, linear and spline).
LaserCurve choose_laser_curve(const std::vector<double>& x, const std::vector<double>& y, double step_mm = 5.0,
                              int max_degree = 0);

}  // namespace ncpost::comp
