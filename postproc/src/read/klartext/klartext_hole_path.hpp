// SPDX-License-Identifier: Apache-2.0
#pragma once
// The Heidenhain hole cycles that no cl::Cycle kind means (TNC 640 / iTNC 530 cycle programming
// manual, "Cycles: drilling"), expanded into the tool tip's path as the cycle run there describes
// it (docs/formats.md "Heidenhain hole cycles"):
//   203 UNIVERSAL DRILLING: pecks that shrink by a decrement, chip breaks, retraction at a feed;
//   241 SINGLE-LIP DEEP-HOLE DRILLING: pre-positioning into a pilot hole, its own spindle speeds;
//   208 BORE MILLING: a helix to the depth on the circle of the bore's diameter less the tool's;
//   201 REAMING: in at a feed, a dwell, out at its own feed (no cl::Cycle kind has both feeds);
//   240 CENTERING: in at a feed to the depth, a dwell, out at FMAX.
// Steps are in the hole's frame: X Y offsets from the hole's centre and Z above the surface Q203,
// along the working plane's axes (the program's X Y Z; the tool axis is Z).
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "ncpost/postproc/read/cl_record.hpp"

namespace ncpost::klartext {

/// One step of an expanded hole cycle.
struct HoleStep {
  enum class Kind {
    rapid,    ///< FMAX to (dx, dy, z)
    feed,     ///< a straight move at `feed_mm_min` to (dx, dy, z)
    arc,      ///< an arc (a helix where z changes) about (cx, cy) through `sweep_rad` (> 0: counter-clockwise)
    dwell,    ///< `dwell_s`
    spindle,  ///< `direction` at `rpm`
    restore,  ///< the spindle as before the cycle
  } kind = Kind::rapid;
  double dx = 0.0, dy = 0.0, z = 0.0;  ///< the end (mm)
  double cx = 0.0, cy = 0.0;           ///< arc: the centre (mm)
  double sweep_rad = 0.0;
  double feed_mm_min = 0.0;
  double dwell_s = 0.0;
  cl::Spindle::Direction direction = cl::Spindle::Direction::cw;
  double rpm = 0.0;
};

/// What the cycle needs from the control's state at its call.
struct HoleContext {
  cl::Spindle::Direction spindle = cl::Spindle::Direction::off;
  double rpm = 0.0;
  std::optional<double> tool_diameter_mm;  ///< 208 needs it
  std::string tool;                        ///< the tool as called (for messages)
};

/// A defined cycle that is expanded at each call.
struct ExpandedCycle {
  int number = 0;
  std::map<int, double> q;
  double surface_mm = 0.0;         ///< Q203
  double return_mm = 0.0;          ///< where the tool stands after a hole, above the surface: max(Q200, Q204)
  std::vector<std::string> notes;  ///< what is noted, not posted (coolant M functions, Q342)
};

/// The cycle from its parameters (checked as far as they do not depend on the call), or why not.
std::variant<ExpandedCycle, std::string> expanded_cycle(int number, const std::map<int, double>& q);

/// The steps of one hole, or why not (a sentence naming the parameter or the state).
std::variant<std::vector<HoleStep>, std::string> hole_steps(const ExpandedCycle& c, const HoleContext& at_call);

}  // namespace ncpost::klartext
