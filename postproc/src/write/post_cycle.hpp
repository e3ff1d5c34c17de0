// SPDX-License-Identifier: Apache-2.0
#pragma once
// One hole of a CYCLE (cl::Cycle) in W: its planes along the tool axis, the explicit moves that
// drill, peck, tap or bore it where no native cycle can (a dialect without the cycle, a hole not
// along −Z of the program frame), and the words of the native block where one can.
#include <optional>
#include <string>
#include <vector>

#include "ncpost/postproc/read/cl_record.hpp"
#include "ncpost/postproc/write/cycle_words.hpp"
#include "ncpost/postproc/write/nc_writer.hpp"

namespace ncpost::detail {

/// The points of one hole in W (mm), all on the tool axis through the GOTO point.
struct HolePlanes {
  ClPoint retract;           ///< where the tool starts and ends (RTRCTO, or the R plane)
  ClPoint r_plane;           ///< where the feed starts (RAPTO / CLEAR)
  ClPoint bottom;            ///< FEDTO / DEPTH
  bool retract_to_r = true;  ///< no retract plane above the R plane: G99
};
HolePlanes hole_planes(const cl::Cycle& c, const ClPoint& hole);

/// One explicit step of an expanded hole.
struct HoleStep {
  enum class Kind { rapid, feed, dwell, spindle } kind = Kind::rapid;
  ClPoint to;                                                                ///< rapid, feed
  double feed_mm_min = 0.0;                                                  ///< feed
  double dwell_s = 0.0;                                                      ///< dwell
  enum class Turn { clockwise, counter_clockwise, stop } turn = Turn::stop;  ///< spindle (the dialect's words)
};

/// Retract of a chip-breaking peck (G73 style), mm; and the clearance above the previous depth at
/// which a full-retract peck (G83 style) resumes feeding.
inline constexpr double kChipBreakRetractMm = 0.5;
inline constexpr double kPeckResumeClearanceMm = 0.5;

/// The explicit moves of one hole from `p.retract` back to it. `feed_mm_min`: the drilling feed
/// (for a tap, pitch × rpm). `spindle_ccw`: the spindle turns M4 (a tap then reverses to M3).
std::vector<HoleStep> expand_hole(const cl::Cycle& c, const HolePlanes& p, double feed_mm_min, bool spindle_ccw);

/// The native block of a hole whose axis is −Z of the program frame, from the program-frame
/// positions of its planes; none when the dialect has no word for the kind. `notice` gets what
/// the native block does differently from the CL record (pecks), if anything.
std::optional<NcCycle> native_hole(const cl::Cycle& c, const CycleWords& w, const Vec3d& r_plane, const Vec3d& bottom,
                                   bool retract_to_r, double feed_mm_min, double rpm, int linear_decimals,
                                   std::string& notice);

}  // namespace ncpost::detail
