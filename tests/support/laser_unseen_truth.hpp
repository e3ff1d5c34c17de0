// SPDX-License-Identifier: Apache-2.0
#pragma once
// Unseen truths for the three-axis laser loop (issue 25 item 6): a VMC with all 21 geometric
// errors whose 18 component error functions are NOT of the identification's own form (tables
// linear between the targets, polynomials p1..p3). Each function is a sum, drawn from a fixed seed, of
//   - a polynomial of degree 5 in u = x / half-travel (random coefficients),
//   - one or two sines of non-harmonic periods (0.45 to 1.6 travels, random phase),
//   - an exponential rising towards one travel end (decay length 40 to 120 mm), half the time,
//   - a local Gaussian bump (σ 35 to 60 mm, somewhere on the travel), half the time,
// scaled to a realistic size (range over the travel: positioning 15–35 µm, straightness 2–6 µm,
// roll/pitch/yaw 15–45 µrad), minus its value at home (every error acts relative to home). The
// truth is written as tables with a node every 2 mm over the whole travel of each axis (limits of
// the machine file), so between the laser targets (50 mm apart) and beyond the outermost ones it
// follows the smooth function, not a line (linear between 2 mm nodes departs from the function by
// h²/8·f'' < 0.01 µm for these sizes). Squareness ±15–45 µrad, reversal 2–5 µm per axis.
// ISO 230-1 reference as the bundled truth (laser_test_support.hpp): the straightness of X in Y
// and Z and of Y in Z carry no least-squares slope over the laser targets (the axes define M).
// Units: mm and rad in the parameters; sizes below in µm and µrad.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "ncpost/compensation/error_parameters.hpp"
#include "ncpost/compensation/laser_plan.hpp"
#include "ncpost/compensation/parameter_name.hpp"
#include "ncpost/compensation/simulate.hpp"
#include "ncpost/kinematics/machine.hpp"

namespace ncpost::test {

/// One smooth function of the axis position (mm → mm or rad), of no form the model has.
struct UnseenFunction {
  double half_travel_mm = 1.0;
  double centre_mm = 0.0;
  std::vector<double> poly;  ///< coefficients of u^1..u^5, u = (x − centre) / half travel
  struct Sine {
    double amplitude, period_mm, phase_rad;
  };
  std::vector<Sine> sines;
  double exp_amplitude = 0.0, exp_end_mm = 0.0, exp_length_mm = 1.0;
  double bump_amplitude = 0.0, bump_at_mm = 0.0, bump_sigma_mm = 1.0;
  double scale = 1.0;

  double raw(double x_mm) const {
    const double u = (x_mm - centre_mm) / half_travel_mm;
    double v = 0.0, p = 1.0;
    for (double c : poly) v += c * (p *= u);
    for (const Sine& s : sines) v += s.amplitude * std::sin(2.0 * M_PI * x_mm / s.period_mm + s.phase_rad);
    v += exp_amplitude * std::exp(-std::abs(x_mm - exp_end_mm) / exp_length_mm);
    const double b = (x_mm - bump_at_mm) / bump_sigma_mm;
    v += bump_amplitude * std::exp(-0.5 * b * b);
    return v;
  }
  /// The value relative to home (mm or rad).
  double operator()(double x_mm) const { return scale * (raw(x_mm) - raw(0.0)); }
};

/// Draws one function over [lo, hi] mm whose range over the travel is `range` (mm or rad).
inline UnseenFunction draw_unseen_function(std::mt19937_64& rng, double lo, double hi, double range) {
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  auto in = [&](double a, double b) { return a + (b - a) * uni(rng); };
  UnseenFunction f;
  f.centre_mm = 0.5 * (lo + hi);
  f.half_travel_mm = 0.5 * (hi - lo);
  for (int k = 1; k <= 5; ++k) f.poly.push_back(in(-1.0, 1.0) / k);
  const int sines = 1 + static_cast<int>(uni(rng) < 0.5);
  for (int k = 0; k < sines; ++k) f.sines.push_back({in(0.2, 0.6), in(0.45, 1.6) * (hi - lo), in(0.0, 2.0 * M_PI)});
  if (uni(rng) < 0.5) {
    f.exp_amplitude = in(-0.8, 0.8);
    f.exp_end_mm = uni(rng) < 0.5 ? lo : hi;
    f.exp_length_mm = in(40.0, 120.0);
  }
  if (uni(rng) < 0.5) {
    f.bump_amplitude = in(-0.5, 0.5);
    f.bump_at_mm = in(lo + 60.0, hi - 60.0);
    f.bump_sigma_mm = in(35.0, 60.0);
  }
  double vmin = 1e300, vmax = -1e300;
  for (double x = lo; x <= hi + 1e-9; x += 1.0) {
    vmin = std::min(vmin, f.raw(x));
    vmax = std::max(vmax, f.raw(x));
  }
  f.scale = range / (vmax - vmin);
  return f;
}

struct UnseenTruth {
  comp::ErrorParameters parameters;
  std::vector<std::string> names;         ///< "EXX", "EYX", …
  std::vector<UnseenFunction> functions;  ///< the same order
};

/// Least-squares slope of f over the points (mm → per mm).
inline double unseen_ls_slope(const UnseenFunction& f, const std::vector<double>& xs) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = double(xs.size());
  for (double x : xs) {
    sx += x;
    sy += f(x);
    sxx += x * x;
    sxy += x * f(x);
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

/// The truth of seed `seed` for a three-axis machine with linear X Y Z (node every `node_mm`).
inline UnseenTruth unseen_truth(const Machine& m, const comp::LaserPlanOptions& plan, std::uint64_t seed,
                                double node_mm = 2.0) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  auto in = [&](double a, double b) { return a + (b - a) * uni(rng); };
  UnseenTruth t;
  const char* comps = "XYZABC";
  for (int a = 0; a < 3; ++a) {
    const Axis& axis = m.axes[static_cast<std::size_t>(a)];  // X, Y, Z first (machine.hpp)
    const double lo = axis.limits->min, hi = axis.limits->max;
    for (int c = 0; c < 6; ++c) {
      const double range = c == a ? in(15e-3, 35e-3) : c < 3 ? in(2e-3, 6e-3) : in(15e-6, 45e-6);
      UnseenFunction f = draw_unseen_function(rng, lo, hi, range);
      const std::string name{'E', comps[c], static_cast<char>('X' + a)};
      // ISO 230-1 reference: X defines x̂, X and Y the XY plane
      if (name == "EYX" || name == "EZX" || name == "EZY") {
        const double s = unseen_ls_slope(f, comp::laser_targets(m, a, plan));
        f.poly[0] -= s * f.half_travel_mm / f.scale;  // u^1 term: a slope of s mm per mm after scaling
      }
      const int nodes = static_cast<int>(std::lround((hi - lo) / node_mm));
      for (int i = 0; i <= nodes; ++i) {
        const double x = lo + (hi - lo) * i / nodes;
        t.parameters.set(comp::table_parameter_name(comps[c], static_cast<char>('X' + a), x), f(x));
      }
      t.names.push_back(name);
      t.functions.push_back(f);
    }
  }
  const double sign[2] = {-1.0, 1.0};
  for (const char* q : {"EC0Y", "EB0Z", "EA0Z"}) t.parameters.set(q, sign[uni(rng) < 0.5] * in(15e-6, 45e-6));
  for (const char* r : {"reversal:X", "reversal:Y", "reversal:Z"}) t.parameters.set(r, in(0.002, 0.005));
  return t;
}

/// The laser sets of the plan measured on the truth with Gaussian noise (one seed per set).
inline std::vector<comp::MeasurementSet> unseen_laser_data(const Machine& m, const comp::ErrorParameters& truth,
                                                           const comp::LaserPlanOptions& plan, double noise_um,
                                                           std::uint64_t seed) {
  std::vector<comp::MeasurementSet> out;
  std::uint64_t s = seed * 1000;
  for (const auto& p : comp::plan_laser(m, plan)) out.push_back(comp::simulate(m, p.set, truth, {noise_um, ++s}));
  return out;
}

}  // namespace ncpost::test
