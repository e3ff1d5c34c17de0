// SPDX-License-Identifier: Apache-2.0
#pragma once
// The harmonic model of a block's nonlinear error (seed 001, Zhang, Wang, Tang 2023, eq. 2–3):
//   L(t) = Σ A_k sin(kπt) + B_k cos(kπt); with zero error at both block ends the first-order form
//   is L(t) = Emax · sin(πt), t ∈ [0, 1] along the block.
// Here the model is a vector in W: L(t) = Emax · sin(πt) · n, n the unit direction of the error.
//
// How Emax and n are fitted (`HarmonicFit`):
//   midpoint  the deviation at t = ½ (one forward-kinematics evaluation): the model's own estimate,
//             used for the preview column `harmonic_mm` and by the harmonic compensation;
//   peak      the exact largest deviation and its direction (the paper's "largest error of the
//             segment"; needs the exact maximisation first).
// Units: mm, W.
#include <cmath>

#include "ncpost/compensation/nonlinear_error.hpp"

namespace ncpost::nonlinear {

enum class HarmonicFit { midpoint, peak };

struct HarmonicModel {
  double amplitude_mm = 0.0;         ///< Emax of the model
  Vec3d direction = Vec3d::UnitX();  ///< unit, W

  double magnitude_at(double t) const { return amplitude_mm * std::sin(kPi * t); }
  Vec3d offset_at(double t) const { return magnitude_at(t) * direction; }
};

inline HarmonicModel harmonic_from_offset(const Vec3d& offset_mm) {
  HarmonicModel m;
  m.amplitude_mm = offset_mm.norm();
  if (m.amplitude_mm > 0) m.direction = offset_mm / m.amplitude_mm;
  return m;
}

/// Midpoint fit: Emax·n = deviation vector at t = ½.
template <class Errors>
HarmonicModel fit_harmonic_midpoint(const ExecutedBlock<Errors>& executed) {
  return harmonic_from_offset(executed.at(0.5).offset_mm);
}

/// Peak fit: Emax·n = deviation vector at the exact maximum.
inline HarmonicModel fit_harmonic_peak(const NonlinearError& exact) { return harmonic_from_offset(exact.offset_mm); }

template <class Errors>
HarmonicModel fit_harmonic(const ExecutedBlock<Errors>& executed, HarmonicFit fit,
                           const NonlinearErrorOptions& options = {}) {
  if (fit == HarmonicFit::midpoint) return fit_harmonic_midpoint(executed);
  return fit_harmonic_peak(nonlinear_error(executed, options));
}

/// How far the model is from the exact error curve of its block.
struct HarmonicResidual {
  double magnitude_mm = 0.0;  ///< max over t of | |e(t)| − Emax·sin(πt) | (the paper's comparison)
  double magnitude_at_t = 0.0;
  double vector_mm = 0.0;  ///< max over t of |e(t) − L(t)|: the error left by an exact shift by L(t)
  double vector_at_t = 0.0;
};

template <class Errors>
HarmonicResidual harmonic_residual(const ExecutedBlock<Errors>& executed, const HarmonicModel& model,
                                   const NonlinearErrorOptions& options = {}) {
  MaximiseOptions m;
  m.scan_intervals = std::max(16, scan_intervals_for(executed.block(), options));
  m.t_tolerance = options.t_tolerance;
  HarmonicResidual r;
  const Maximum a = maximise_bracketed(
      [&](double t) { return std::abs(executed.at(t).error_mm() - model.magnitude_at(t)); }, 0.0, 1.0, m);
  const Maximum b =
      maximise_bracketed([&](double t) { return (executed.at(t).offset_mm - model.offset_at(t)).norm(); }, 0.0, 1.0, m);
  r.magnitude_mm = a.value;
  r.magnitude_at_t = a.t;
  r.vector_mm = b.value;
  r.vector_at_t = b.t;
  return r;
}

}  // namespace ncpost::nonlinear
