// SPDX-License-Identifier: Apache-2.0
#pragma once
// Reversal (backlash) as a play / dead band (docs/conventions.md "Geometric errors"): the actual
// position of an axis with reversal width b follows
//   actual_k = clamp(actual_{k-1}, command_k, command_k + b)
// so that it equals the command while the command rises, command + b while it falls, and stands
// still inside the band after a reversal. The offset actual − command of every row is what the
// error model adds to the command (ErrorFunctor's RowState).
//
// History before the first row is unknown; the first row is taken as approached from below
// (offset 0), like the set-up at home. Units: mm for linear, rad for rotary axes.
#include <algorithm>
#include <vector>

#include "ncpost/compensation/error_model.hpp"

namespace ncpost::comp {

/// The dead-band state of one axis: where it actually is, given where it was.
template <class P>
P dead_band_actual(const P& previous_actual, double command, const P& width) {
  P lo = P(command), hi = P(command) + width;
  if (hi < lo) std::swap(lo, hi);
  if (previous_actual < lo) return lo;
  if (previous_actual > hi) return hi;
  return previous_actual;
}

/// Offsets actual − command of each command of a sequence (first row from below).
template <class P>
std::vector<P> dead_band_offsets(const std::vector<double>& commands, const P& width) {
  std::vector<P> out;
  out.reserve(commands.size());
  P actual = commands.empty() ? P(0) : P(commands.front());
  for (double c : commands) {
    actual = dead_band_actual<P>(actual, c, width);
    out.push_back(actual - P(c));
  }
  return out;
}

/// Row states (reversal offsets of every axis with a reversal parameter, time stamps) for a
/// sequence of commanded positions in measuring order.
template <class P>
std::vector<RowState<P>> row_states(const ModelLayout& layout, const P* values,
                                    const std::vector<AxisPosition>& commands, const std::vector<double>& times_s) {
  std::vector<RowState<P>> states(commands.size());
  for (std::size_t k = 0; k < commands.size(); ++k) states[k].time_s = k < times_s.size() ? times_s[k] : 0.0;
  for (int axis = 0; axis < kMaxAxes; ++axis) {
    const int p = layout.reversal_of(axis);
    if (p < 0) continue;
    std::vector<double> c(commands.size());
    for (std::size_t k = 0; k < commands.size(); ++k) c[k] = commands[k][axis];
    const std::vector<P> offsets = dead_band_offsets<P>(c, values[p]);
    for (std::size_t k = 0; k < commands.size(); ++k) states[k].reversal[static_cast<std::size_t>(axis)] = offsets[k];
  }
  return states;
}

}  // namespace ncpost::comp
