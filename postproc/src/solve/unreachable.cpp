// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/solve/unreachable.hpp"

#include "ncpost/machines/formatters.hpp"

#include <fmt/format.h>

#include <cmath>
#include <vector>

namespace ncpost {
namespace {

/// The value of rotary axis `axis` nearest its limits among the 2π turns of `rad` nearest `previous_rad`.
double nearest_turn_to_limits(const Axis& axis, double rad, double previous_rad) {
  const double nearest = rad + 2.0 * kPi * std::round((previous_rad - rad) / (2.0 * kPi));
  if (!axis.limits) return nearest;
  double best = nearest, best_gap = INFINITY;
  for (int shift : {0, -1, 1, -2, 2}) {
    const double v = nearest + 2.0 * kPi * shift;
    const double gap = std::max({0.0, axis.limits->min - v, v - axis.limits->max});
    if (gap < best_gap - 1e-12) best = v, best_gap = gap;
  }
  return best;
}

std::string out_of_limits(const Axis& axis, double value) {
  const bool rotary = axis.is_rotary();
  const double k = rotary ? 180.0 / kPi : 1.0;
  const char* unit = rotary ? "°" : " mm";
  return fmt::format("{} would be {:.3f}{} (limits {:.3f} to {:.3f}{})", axis.letter, value * k, unit,
                     axis.limits->min * k, axis.limits->max * k, unit);
}

}  // namespace

std::string axes_out_of_limits(const KinematicModel& solver, SolverData& data, const ClPoint& cl,
                               const AxisPosition& previous, bool* linear_out) {
  if (!solver.words().limits_name_the_axis) return {};  // the solver's failure names the axis (e.g. the TRR-XY sliders)
  const Machine& m = solver.machine();
  std::vector<RotaryAngles> rotaries;
  const RotaryAngles before = rotary_of(previous, m.rotary_count());
  if (m.rotary_count() == 0) {
    rotaries.push_back(RotaryAngles());
  } else {
    for (const RotarySolution& s : rotary_solutions(m, cl.axis, 1e-7)) {
      RotaryAngles r = s.rotary_rad;
      if (s.free_axis >= 0) r[s.free_axis] = before[s.free_axis];
      for (int k = 0; k < m.rotary_count(); ++k) r[k] = nearest_turn_to_limits(m.rotary(k), r[k], before[k]);
      rotaries.push_back(r);
    }
  }
  std::string text;
  for (const RotaryAngles& r : rotaries) {
    std::vector<std::string> out;
    for (int k = 0; k < m.rotary_count(); ++k)
      if (m.rotary(k).limits && !m.rotary(k).limits->contains(r[k], 1e-9))
        out.push_back(out_of_limits(m.rotary(k), r[k]));
    if (out.empty()) {  // the rotary angles are within: which linear axes leave their travel
      const AxisPosition q = solver.with_rotary(cl, r, data);
      for (int i = 0; i < 3; ++i)
        if (m.axes[static_cast<std::size_t>(i)].limits &&
            !m.axes[static_cast<std::size_t>(i)].limits->contains(q.linear_mm[i], 1e-6))
          out.push_back(out_of_limits(m.axes[static_cast<std::size_t>(i)], q.linear_mm[i]));
      if (linear_out && !out.empty()) *linear_out = true;
    }
    if (out.empty()) continue;
    std::string with;
    for (int k = 0; k < m.rotary_count(); ++k)
      with += fmt::format("{}{} {:.3f}°", k ? " " : "with ", m.rotary(k).letter, r[k] * 180.0 / kPi);
    if (!text.empty()) text += "; ";
    text += with.empty() ? "" : with + ": ";
    for (std::size_t i = 0; i < out.size(); ++i) text += (i ? ", " : "") + out[i];
  }
  return text;
}

std::string unreachable_message(const std::string& input, int line, const KinematicModel& solver, SolverData& data,
                                const ClPoint& cl, const AxisPosition& previous, const std::string& why) {
  bool linear = false;
  const std::string axes = axes_out_of_limits(solver, data, cl, previous, &linear);
  return fmt::format("{}:{}: {}{}{} (tip {:.4f} mm, axis {:.6f}){}", input, line, why, axes.empty() ? "" : ": ", axes,
                     cl.tip_mm, cl.axis,
                     linear ? "; a linear axis leaves its travel: check --workpiece-origin and the tool length" : "");
}

}  // namespace ncpost
