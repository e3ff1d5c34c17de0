// SPDX-License-Identifier: Apache-2.0
#pragma once
// `post --verify` of the program as written: each motion block's text is read back with the words
// of its dialect (written_block.hpp), from the words in force before it, and executed; what the
// executed block does other than the input meant is recorded in VerifyReport::defects with the
// program line and the CL line:
//  - a motion word of the wrong kind (a feed move written as a rapid, an arc the wrong way round);
//  - a feed word off its rule (per minute: the CL feed; G93: 1 / (executed tip path / CL feed),
//    inverse_time.hpp);
//  - a rapid that leaves a cut (retract) or enters one (approach) off the tool-axis line of the
//    cut's end (start) and off the straight CL rapid: the tool would be dragged through the wall.
#include <functional>
#include <optional>
#include <string>

#include "ncpost/kinematics/forward.hpp"
#include "ncpost/postproc/verify/verify.hpp"
#include "ncpost/postproc/verify/written_block.hpp"

namespace ncpost::detail {

/// Where the tool is (W) at parameter t of the move from the words `a` to the words `b` as the
/// control runs it (every axis linear, the tip straight in W under RTCP).
using ExecuteWords = std::function<ToolPoseT<double>(const WrittenState& a, const WrittenState& b, double t)>;

/// The tolerance (mm) of the rapid line checks: word rounding and the sampling, well below any
/// wall a drill could be dragged through.
inline constexpr double kRapidLineToleranceMm = 0.002;

/// A written motion block as read back: its words before and after, and where it is in the program.
struct ReadBackBlock {
  WrittenState from, to;
  std::size_t program_line = 0;
  std::string text;
  int cl_line = 0;
  Vec3d cl_from_mm = Vec3d::Zero(), cl_to_mm = Vec3d::Zero();  ///< the CL rapid (W)
};

/// Adds "program line N (CL line L): what" to the report (the first 20; then a count).
void add_defect(VerifyReport& report, std::size_t program_line, int cl_line, const std::string& what);

/// The largest distance (mm) of the executed tip of `rapid` from both the tool-axis line through
/// its executed start (retract, `at_start`) or end (approach), on the part's side of it, and the
/// CL rapid segment (moved by the execution error at that end). Rapids with a rotary move: 0.
double rapid_off_line_mm(const ReadBackBlock& rapid, bool at_start, const ExecuteWords& execute);

}  // namespace ncpost::detail
