// SPDX-License-Identifier: Apache-2.0
#pragma once
// Bracketed maximisation of a scalar function of one parameter on [a, b]: a uniform scan
// brackets the local maxima, then Brent's method (golden section with parabolic steps; R. P. Brent,
// "Algorithms for Minimization without Derivatives", 1973, ch. 5) refines the best brackets.
// Used for the largest nonlinear error of a block (nonlinear_error.hpp). Unitless.
#include <algorithm>
#include <cmath>
#include <vector>

namespace ncpost::nonlinear {

struct MaximiseOptions {
  int scan_intervals = 16;    ///< uniform scan intervals bracketing the maxima (>= 2)
  int refined_brackets = 3;   ///< at most this many local maxima of the scan are refined
  double t_tolerance = 1e-7;  ///< absolute tolerance on the arg max (fraction of [a, b])
  int max_iterations = 80;    ///< per bracket
  bool valid() const { return scan_intervals >= 2 && refined_brackets >= 1 && t_tolerance > 0 && max_iterations > 0; }
};

struct Maximum {
  double t = 0.0;
  double value = 0.0;
  int evaluations = 0;
};

/// Brent's minimisation of g on [a, b], starting from x0 ∈ [a, b] with g(x0) = g0 known.
template <class G>
Maximum brent_minimise(G&& g, double a, double b, double x0, double g0, double tolerance, int max_iterations) {
  constexpr double golden = 0.3819660112501051;  // (3 − √5) / 2
  double x = x0, w = x0, v = x0;
  double fx = g0, fw = g0, fv = g0;
  double d = 0.0, e = 0.0;
  int evaluations = 0;
  for (int it = 0; it < max_iterations; ++it) {
    const double m = 0.5 * (a + b);
    const double tol1 = tolerance;
    const double tol2 = 2.0 * tol1;
    if (std::abs(x - m) <= tol2 - 0.5 * (b - a)) break;
    bool golden_step = true;
    if (std::abs(e) > tol1) {  // try a parabola through x, w, v
      const double r = (x - w) * (fx - fv);
      double q = (x - v) * (fx - fw);
      double p = (x - v) * q - (x - w) * r;
      q = 2.0 * (q - r);
      if (q > 0.0)
        p = -p;
      else
        q = -q;
      const double e_previous = e;
      e = d;
      if (std::abs(p) < std::abs(0.5 * q * e_previous) && p > q * (a - x) && p < q * (b - x)) {
        d = p / q;
        const double u = x + d;
        if (u - a < tol2 || b - u < tol2) d = std::copysign(tol1, m - x);
        golden_step = false;
      }
    }
    if (golden_step) {
      e = (x >= m) ? a - x : b - x;
      d = golden * e;
    }
    const double u = std::abs(d) >= tol1 ? x + d : x + std::copysign(tol1, d);
    const double fu = g(u);
    ++evaluations;
    if (fu <= fx) {
      if (u >= x)
        a = x;
      else
        b = x;
      v = w;
      fv = fw;
      w = x;
      fw = fx;
      x = u;
      fx = fu;
    } else {
      if (u < x)
        a = u;
      else
        b = u;
      if (fu <= fw || w == x) {
        v = w;
        fv = fw;
        w = u;
        fw = fu;
      } else if (fu <= fv || v == x || v == w) {
        v = u;
        fv = fu;
      }
    }
  }
  return {x, fx, evaluations};
}

/// Refines a scan (ts ascending, fs = f(ts)): brackets every local maximum of the scan, refines the
/// `refined_brackets` highest with Brent's method and returns the best (evaluations: refinement only).
template <class F>
Maximum refine_scan(F&& f, const std::vector<double>& ts, const std::vector<double>& fs,
                    const MaximiseOptions& options = {}) {
  const int n = static_cast<int>(ts.size()) - 1;
  Maximum best{ts[0], fs[0], 0};
  std::vector<int> peaks;
  for (int i = 0; i <= n; ++i) {
    if (fs[i] > best.value) best = {ts[i], fs[i], 0};
    const bool left_ok = i == 0 || fs[i] >= fs[i - 1];
    const bool right_ok = i == n || fs[i] >= fs[i + 1];
    if (left_ok && right_ok && !(i > 0 && fs[i] == fs[i - 1])) peaks.push_back(i);
  }
  std::sort(peaks.begin(), peaks.end(), [&](int l, int r) { return fs[l] > fs[r]; });
  if (static_cast<int>(peaks.size()) > options.refined_brackets)
    peaks.resize(static_cast<std::size_t>(options.refined_brackets));
  const double tolerance = options.t_tolerance * (ts[n] - ts[0]);
  for (int i : peaks) {
    const double lo = ts[std::max(i - 1, 0)];
    const double hi = ts[std::min(i + 1, n)];
    const Maximum m =
        brent_minimise([&](double t) { return -f(t); }, lo, hi, ts[i], -fs[i], tolerance, options.max_iterations);
    best.evaluations += m.evaluations;
    if (-m.value > best.value) {
      best.t = m.t;
      best.value = -m.value;
    }
  }
  return best;
}

/// The largest value of f on [a, b]: a scan of `scan_intervals`, then `refine_scan`.
template <class F>
Maximum maximise_bracketed(F&& f, double a, double b, const MaximiseOptions& options = {}) {
  const int n = options.scan_intervals;
  std::vector<double> ts(static_cast<std::size_t>(n + 1)), fs(ts.size());
  for (int i = 0; i <= n; ++i) {
    ts[i] = a + (b - a) * i / n;
    fs[i] = f(ts[i]);
  }
  Maximum best = refine_scan(f, ts, fs, options);
  best.evaluations += n + 1;
  return best;
}

}  // namespace ncpost::nonlinear
