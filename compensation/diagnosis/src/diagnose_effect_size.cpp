// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/diagnose_effect_size.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ncpost/compensation/parameter_name.hpp"

namespace ncpost::comp {
namespace {

double command_range(const std::vector<MeasurementSet>& sets, int axis) {
  double r = 0.0;
  for (const auto& s : sets)
    for (const auto& row : s.rows) r = std::max(r, std::abs(row.command[axis]));
  return r;
}

}  // namespace

EffectSize effect_size(const Machine& m, const std::vector<MeasurementSet>& sets, const Candidate& c,
                       const ErrorParameters& values, const ErrorParameters& uncertainty, const PlausibleSizes& o) {
  EffectSize e;
  const auto v = [&](std::size_t i) { return values.value_or(c.parameters[i], 0.0); };
  const auto u = [&](std::size_t i) { return uncertainty.value_or(c.parameters[i], 0.0); };
  const ParameterSpec spec = *parse_parameter_name(c.parameters[0], m).spec;
  double limit = o.length_mm;
  switch (c.kind) {
    case CandidateKind::component:
      e.is_angle = spec.component >= 3;
      if (spec.kind == ParameterKind::harmonic) {
        e.size = std::hypot(v(0), v(1));
        e.sigma = e.size > 0 ? std::hypot(v(0) * u(0), v(1) * u(1)) / e.size : std::hypot(u(0), u(1));
      } else if (spec.kind == ParameterKind::table) {
        // the largest node (the node at home is held at 0), with that node's uncertainty
        for (std::size_t i = 0; i < c.parameters.size(); ++i)
          if (std::abs(v(i)) >= e.size) e.size = std::abs(v(i)), e.sigma = u(i);
      } else {
        // a polynomial over its axis's travel; a coupled location error over the carrier's range
        const int by = spec.kind == ParameterKind::coupled ? spec.coupled_axis_index : spec.axis_index;
        const double reach =
            std::pow(std::max(spec.kind == ParameterKind::coupled ? 0.0 : 1.0, command_range(sets, by)), spec.order);
        e.size = std::abs(v(0)) * reach;
        e.sigma = u(0) * reach;
      }
      break;
    case CandidateKind::squareness:
      e.is_angle = true;
      e.size = std::abs(v(0));
      e.sigma = u(0);
      break;
    case CandidateKind::reversal:
      e.is_angle = m.axes[static_cast<std::size_t>(spec.axis_index)].is_rotary();
      e.size = v(0);
      e.sigma = u(0);
      if (e.size <= 0.0) e.implausible = "a negative play is not physical";
      break;
    case CandidateKind::drift: {
      const double tau = values.value_or(c.effect + ":tau", 600.0);
      const double lin = values.value_or(c.effect + ":lin", 0.0), amp = values.value_or(c.effect + ":exp", 0.0);
      const double u_lin = uncertainty.value_or(c.effect + ":lin", 0.0),
                   u_amp = uncertainty.value_or(c.effect + ":exp", 0.0);
      double largest = 0.0, t_end = 0.0;
      for (const auto& s : sets)
        for (const auto& row : s.rows) {
          largest = std::max(largest, std::abs(lin * row.time_s + amp * (1.0 - std::exp(-row.time_s / tau))));
          t_end = std::max(t_end, row.time_s);
        }
      e.size = largest;
      e.sigma = std::hypot(u_lin * t_end, u_amp);
      limit = o.drift_mm;
      break;
    }
    case CandidateKind::instrument: {
      double sq = 0.0, su = 0.0;
      for (std::size_t i = 0; i < c.parameters.size(); ++i) sq += v(i) * v(i), su += u(i) * u(i);
      e.size = std::sqrt(sq);
      e.sigma = std::sqrt(su);
      limit = o.instrument_mm;
      break;
    }
  }
  if (e.is_angle) limit = o.angle_rad;
  if (e.implausible.empty() && std::abs(e.size) > limit)
    e.implausible =
        fmt::format("size {:.4g} {} is beyond the plausible {:.4g}", e.size, e.is_angle ? "rad" : "mm", limit);
  return e;
}

}  // namespace ncpost::comp
