// SPDX-License-Identifier: Apache-2.0
#pragma once
// The exact nonlinear error of one block (docs/conventions.md "Execution model of an NC program";
// seed 001): the largest distance (mm, W) of the executed tool tip from the straight CL segment,
// where along the block it occurs (t ∈ [0, 1], linear in axis space), and the largest orientation
// error (rad) between the executed tool axis and the normalised, linearly interpolated CL axis.
//
// Method: a uniform scan, fine enough for the rotary motion of the block (one interval per
// `scan_step_rad` of the largest rotary travel, at least `min_scan_intervals`), brackets the local
// maxima; Brent's method refines the best brackets to `t_tolerance`. Tested against a dense
// independent simulation (tests/compensation/nonlinear_error_test.cpp).
#include <algorithm>
#include <cmath>
#include <vector>

#include "ncpost/compensation/nonlinear_block.hpp"
#include "ncpost/compensation/nonlinear_maximise.hpp"

namespace ncpost::nonlinear {

struct NonlinearErrorOptions {
  int min_scan_intervals = 8;
  int max_scan_intervals = 512;
  double scan_step_rad = 0.05;  ///< one scan interval per this much travel of the busiest rotary axis
  double t_tolerance = 1e-7;
  bool orientation = true;  ///< also maximise the orientation error (false: the scan's largest value)
  bool valid() const {
    return min_scan_intervals >= 2 && max_scan_intervals >= min_scan_intervals && scan_step_rad > 0 && t_tolerance > 0;
  }
};

/// The nonlinear error of a block.
struct NonlinearError {
  double max_error_mm = 0.0;         ///< largest distance of the executed tip from the CL segment
  double at_t = 0.0;                 ///< where (block parameter, linear in axis space)
  Vec3d offset_mm = Vec3d::Zero();   ///< the deviation vector there (W)
  double max_orientation_rad = 0.0;  ///< largest orientation error
  double orientation_at_t = 0.0;
  int evaluations = 0;  ///< forward-kinematics evaluations spent
};

/// Options for deciding on many blocks (compensation): a coarser scan (4 intervals at least),
/// t to 1e-5 (the value to ~1e-9 relative, the maximum being flat), orientation from the scan only.
inline NonlinearErrorOptions fast_error_options() {
  NonlinearErrorOptions o;
  o.min_scan_intervals = 4;
  o.t_tolerance = 1e-5;
  o.orientation = false;
  return o;
}

/// Scan intervals used for a block: enough to bracket the maxima of its rotary motion.
inline int scan_intervals_for(const ClBlock& block, const NonlinearErrorOptions& options) {
  const double travel = max_abs_step(block.to.rotary_rad, block.from.rotary_rad);
  const int n = static_cast<int>(std::ceil(travel / options.scan_step_rad));
  return std::clamp(n, options.min_scan_intervals, options.max_scan_intervals);
}

template <class Errors>
NonlinearError nonlinear_error(const ExecutedBlock<Errors>& executed, const NonlinearErrorOptions& options = {}) {
  const int n = scan_intervals_for(executed.block(), options);
  std::vector<double> ts(static_cast<std::size_t>(n + 1)), position(ts.size()), orientation(ts.size());
  for (int i = 0; i <= n; ++i) {
    ts[i] = static_cast<double>(i) / n;
    const Deviation d = executed.at(ts[i]);
    position[i] = d.error_mm();
    orientation[i] = d.orientation_rad;
  }
  MaximiseOptions refine;
  refine.t_tolerance = options.t_tolerance;
  NonlinearError out;
  const Maximum p = refine_scan([&](double t) { return executed.at(t).error_mm(); }, ts, position, refine);
  out.max_error_mm = p.value;
  out.at_t = p.t;
  out.offset_mm = executed.at(p.t).offset_mm;
  out.evaluations = n + 2 + p.evaluations;
  if (!options.orientation) {
    const auto it = std::max_element(orientation.begin(), orientation.end());
    out.max_orientation_rad = *it;
    out.orientation_at_t = ts[static_cast<std::size_t>(it - orientation.begin())];
  } else {
    const Maximum o = refine_scan([&](double t) { return executed.at(t).orientation_rad; }, ts, orientation, refine);
    out.max_orientation_rad = o.value;
    out.orientation_at_t = o.t;
    out.evaluations += o.evaluations;
  }
  return out;
}

/// The nonlinear error of `block` on the machine described by `errors` (nominal by default).
template <class Errors = NominalErrors>
NonlinearError nonlinear_error(const Machine& machine, const Setup& setup, const ClBlock& block,
                               const Errors& errors = {}, const NonlinearErrorOptions& options = {}) {
  return nonlinear_error(ExecutedBlock<Errors>(machine, setup, block, errors), options);
}

}  // namespace ncpost::nonlinear
