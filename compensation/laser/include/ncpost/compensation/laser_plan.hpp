// SPDX-License-Identifier: Apache-2.0
#pragma once
// Laser interferometer plan for the linear axes (issue 7; seed 003, Li et al. 2008; ISO 230-2
// test cycle; ISO 230-1 straightness and angular errors from parallel lines).
//
// Per linear axis j, `lines` parallel measuring lines. A line is given by the position of the
// measured point in the two other directions of M (mm, XYZ order). The plan realises each
// direction k either by commanding axis k there — when moving axis k changes the Abbe offset of
// axis j's angular errors (axis k lies between the tool point and axis j in the chain: for a
// workpiece-side j every tool-side axis and every workpiece-side axis nearer the bed; for a
// tool-side j the tool-side axes farther from the bed) — or else by offsetting the reflector
// from the TCP (`tool_point`), since moving such an axis would not change the offset (a head
// axis's pitch and yaw see only where the reflector sits on the spindle).
//
// On every line the plan has one set per measured component: positioning (the axis itself) and
// the two straightness directions. Rows: ISO 230-2 standard test cycle — `runs` runs, each a
// forward pass over the targets (approach +1) then a backward pass (approach −1), the instrument
// zeroed at the first row of each run. Targets: every `step_mm` on a grid through home, plus the
// ends of the travel (less margin and overshoot) where they lie more than a quarter step beyond
// the grid. Commands in mm; time `dt_s` per target.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "ncpost/compensation/plans.hpp"

namespace ncpost::comp {

struct LaserPlanOptions {
  std::string axes = "XYZ";            ///< the axes to measure
  double step_mm = 50.0;               ///< target spacing
  int runs = 5;                        ///< bidirectional runs per line (ISO 230-2: 5)
  int lines = 3;                       ///< parallel lines per axis (1..3)
  bool straightness = true;            ///< also the two straightness sets per line
  double tool_length_mm = 100.0;       ///< reflector holder length in the spindle
  double reflector_offset_mm = 100.0;  ///< reflector offset from the spindle line, where used
  double margin_mm = 0.0;              ///< kept clear of each end of the travel
  double overshoot_mm = 5.0;           ///< NC program: overshoot before each pass (ISO 230-2)
  double feed_mm_min = 2000.0;         ///< NC program: feed between targets
  double dt_s = 6.0;                   ///< time per target (move + dwell + reading)
  double t0_s = 0.0;
  CommandRounding rounding;  ///< the targets, as the NC program writes them

  /// Empty if valid, else what is wrong.
  std::string validate() const;
};

/// True if moving axis k changes the Abbe offset of the angular errors of linear axis j (see
/// the header comment).
bool moves_abbe_offset(const Machine& machine, int j, int k);

/// The targets of axis j (mm, ascending), see the header comment.
/// Throws std::invalid_argument if the axis has no limits.
std::vector<double> laser_targets(const Machine& machine, int j, const LaserPlanOptions& options);

/// The sets, named `<axis><line>_pos`, `<axis><line>_str<direction>` (e.g. X1_pos, X2_strZ).
/// Throws std::invalid_argument if the machine does not fit (no limits, bad options).
std::vector<NamedPlan> plan_laser(const Machine& machine, const LaserPlanOptions& options);

/// The NC program (records for the NC writer, plan_program.hpp) running the sets in order, with
/// the ISO 230-2 overshoot before each pass and a dwell at each target; a program stop where the
/// optics are to be set up.
PlanProgram laser_program(const Machine& machine, const std::vector<NamedPlan>& plans, const LaserPlanOptions& options);

}  // namespace ncpost::comp
