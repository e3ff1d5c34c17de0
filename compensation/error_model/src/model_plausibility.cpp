// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/model_plausibility.hpp"

#include <fmt/format.h>

#include <cmath>

namespace ncpost::comp {
namespace {

/// The effect of the value (in mm or rad) and what it is compared with.
struct Effect {
  double size;
  double bound;
  const char* unit;
  std::string at;  ///< where the effect is taken ("" for the value itself)
};

Effect effect_of_value(const ParameterSpec& s, const Machine& m, double v, const PlausibleBounds& b) {
  const double own = s.is_angle() ? b.angle_rad : b.length_mm;
  const char* unit = s.is_angle() ? "rad" : "mm";
  switch (s.kind) {
    case ParameterKind::polynomial:
      return {std::abs(v) * std::pow(b.travel_mm, s.order), own, unit,
              fmt::format(" at {:g} mm of travel", b.travel_mm)};
    case ParameterKind::reversal: {
      const bool rotary = m.axes[static_cast<std::size_t>(s.axis_index)].is_rotary();
      return {std::abs(v), rotary ? b.angle_rad : b.length_mm, rotary ? "rad" : "mm", ""};
    }
    case ParameterKind::drift:
      switch (s.drift) {
        case DriftBasis::linear:
          return {std::abs(v) * b.duration_s, b.length_mm, "mm", fmt::format(" after {:g} s", b.duration_s)};
        case DriftBasis::quadratic:
          return {std::abs(v) * b.duration_s * b.duration_s, b.length_mm, "mm",
                  fmt::format(" after {:g} s", b.duration_s)};
        case DriftBasis::exponential:
          return {std::abs(v), b.length_mm, "mm", ""};
        case DriftBasis::time_constant:
          return {v, b.tau_max_s, "s", ""};
      }
      return {std::abs(v), b.length_mm, "mm", ""};
    case ParameterKind::ballbar_length:
      return {std::abs(v), b.ballbar_mm, "mm", ""};
    case ParameterKind::sphere_position:
      return {std::abs(v), b.sphere_mm, "mm", ""};
    default:
      return {std::abs(v), own, unit, ""};
  }
}

}  // namespace

std::string implausibility(const ParameterSpec& s, const Machine& m, double value, const PlausibleBounds& b) {
  if (!std::isfinite(value)) return "is not finite";
  if (s.kind == ParameterKind::drift && s.drift == DriftBasis::time_constant) {
    if (value < b.tau_min_s || value > b.tau_max_s)
      return fmt::format("= {:g} s is outside the plausible time constants {:g} .. {:g} s", value, b.tau_min_s,
                         b.tau_max_s);
    return {};
  }
  const Effect e = effect_of_value(s, m, value, b);
  if (e.size <= e.bound) return {};
  return fmt::format("= {:g} acts by {:g} {}{}, more than any machine's error of this kind (at most {:g} {})", value,
                     e.size, e.unit, e.at, e.bound, e.unit);
}

}  // namespace ncpost::comp
