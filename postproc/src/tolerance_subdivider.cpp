#include "ncpost/postproc/tolerance_subdivider.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "ncpost/machines/input_error.hpp"
#include "ncpost/postproc/play_subdivision.hpp"

namespace ncpost {

double rotary_reach_mm(const Machine& machine, const Setup& setup, const ClPoint& a, const ClPoint& b) {
  double reach = 0.0;
  for (const auto& axis : machine.axes) {
    if (!axis.is_rotary()) continue;
    for (const ClPoint* p : {&a, &b})
      reach = std::max(reach, (setup.workpiece_origin_mm + p->tip_mm - axis.pivot_mm).norm() + setup.tool_length_mm);
  }
  return reach;
}

Subdivider make_tolerance_subdivider(const Machine& machine, const Setup& setup, const MotionSolver& solver,
                                     const ActualSolver* actual, const nonlinear::CompensationOptions& options,
                                     const Dialect& dialect, const std::string& input_name) {
  // with reversal the adaptive subdivision follows the play, take-ups included (play_subdivision.hpp)
  if (actual && actual->model().has_reversal() && options.method == nonlinear::Method::adaptive)
    actual->take_up_in_blocks();
  return [&machine, setup, &solver, actual, options, linear = dialect.linear_decimals,
          angle = dialect.angle_decimals, input_name](const SolvedPoint& from, const SolvedPoint& to) {
    nonlinear::CompensationOptions c = options;
    c.rounding_allowance_mm = std::min(
        0.5 * c.tolerance_mm,
        nonlinear::rounding_allowance_mm(linear, angle, rotary_reach_mm(machine, setup, from.cl, to.cl)));
    // inserted points are not CL points of the input: the solver's figures are left as they are
    auto ik = [&solver](const ClPoint& cl, const AxisPosition& previous) { return solver.solve_quiet(cl, previous, nullptr); };
    if (actual && actual->model().has_reversal() && c.method == nonlinear::Method::adaptive) {
      std::string failure;
      std::vector<SolvedPoint> points = subdivide_with_play(machine, setup, *actual, from, to, c, failure);
      if (!failure.empty()) throw Infeasible(fmt::format("{}: {}", input_name, failure));
      return points;
    }
    const nonlinear::ClBlock block{from.cl, to.cl, from.q, to.q, from.executed, to.executed};
    const nonlinear::SplitBlock split =
        actual ? nonlinear::compensate_block(machine, setup, block, actual->errors_from_here(), ik, c)
               : nonlinear::compensate_block(machine, setup, block, NominalErrors{}, ik, c);
    if (!split.ok()) throw Infeasible(fmt::format("{}: {}", input_name, split.failure));
    std::vector<SolvedPoint> points;
    points.reserve(split.nodes.size());
    for (const auto& node : split.nodes) points.push_back({node.cl, node.q});
    return points;
  };
}

}  // namespace ncpost
