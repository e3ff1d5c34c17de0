// SPDX-License-Identifier: Apache-2.0
#pragma once
// The re-post check of issue 28 for Sinumerik input (the real corpus's reading): the INPUT run by
// the tests' own Sinumerik interpreter (sinumerik_mini.hpp) against the written OUTPUT executed by
// nc_executor.hpp through the machine's forward kinematics, with the rules of reposted_tips.hpp:
// - every input block end once every axis is placed: an output block must end there, in order, the
//   tip within 1 µm and the tool axis within 1e-6 (an end where the input does not move needs none);
// - between the ends of an input feed move (G1, G2/G3) every output block that realises it is
//   sampled (reposted_tips.hpp check_between): within the output's stated tolerance (+ 1 µm) of the
//   input's path, a straight tip line in W or the arc about its centre; no rapid among them. A feed
//   that turns rotary axes in machine coordinates (a curved tip path) is not compared: a failure;
// - under TRAORI with rotary words (the program gives the machine's angles, the control's own
//   solution), the output block that reaches the end must write those angles (within 1e-4 deg; an
//   axis without limits modulo 360 deg, the output may unwind it).
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "nc_executor.hpp"
#include "reposted_tips.hpp"
#include "sinumerik_mini.hpp"

namespace ncpost::test {

/// What the check compared; beyond RepostCheck the ends whose output angles were compared.
struct SinumerikRepostCheck : RepostCheck {
  int angle_ends = 0;
  double worst_angle_deg = 0.0;  ///< the largest difference (modulo 360 on an axis without limits)
};

/// The output's rotary words at `block` against the program's machine angles: "" where they agree.
inline std::string compare_angles(const ExecMachine& m, const ExecBlock& block,
                                  const std::map<char, double>& program_deg, SinumerikRepostCheck& r) {
  constexpr double kAngleToleranceDeg = 1e-4;
  for (const auto& [letter, want] : program_deg) {
    const double got = block.to.count(letter) ? block.to.at(letter) : 0.0;
    double diff = got - want;
    if (!m.all_axes.at(letter).limit_max) diff = std::remainder(diff, 360.0);
    r.worst_angle_deg = std::max(r.worst_angle_deg, std::abs(diff));
    if (std::abs(diff) > kAngleToleranceDeg)
      return "output line " + std::to_string(block.line) + " writes " + letter + std::to_string(got) +
             " where the program's machine angle is " + std::to_string(want);
  }
  ++r.angle_ends;
  return {};
}

/// Executes the Sinumerik `input` and the written `output` on `machine_file` and compares them.
inline SinumerikRepostCheck compare_sinumerik_reposted(const std::string& input, const std::string& machine_file,
                                                       const ExecJob& job, const std::string& output) {
  constexpr double kTipToleranceMm = 1e-3;
  const Executor ex(machine_file, job, output);
  const std::vector<SinumerikEnd> ends = sinumerik_block_ends(input, ex.machine, job);
  const double between_mm = stated_tolerance_mm(output, kTipToleranceMm) + kTipToleranceMm;
  std::vector<ExecPose> out_ends;
  for (const ExecBlock& b : ex.blocks) out_ends.push_back(ex.at(b, 1.0));
  SinumerikRepostCheck r;
  std::size_t next = 0;
  std::optional<ExecPose> previous;
  for (const SinumerikEnd& e : ends) {
    if (!e.complete) continue;
    const std::string where = "input line " + std::to_string(e.line) + ": ";
    ExecPose in;
    in.tip_W = e.tip_W, in.axis_W = e.axis_W;
    if (previous && e.motion < 2 && same_place(*previous, in)) {
      ++r.ends;  // the input does not move: no output block needed
      continue;
    }
    const std::size_t first_block = next;
    if (const std::string missed = reach_output_end(ex, out_ends, next, in); !missed.empty()) {
      std::ostringstream o;
      o << where << "(tip " << e.tip_W.transpose() << ", axis " << e.axis_W.transpose() << ") " << missed;
      r.failure = o.str();
      return r;
    }
    ++r.ends;
    r.worst_end_mm = std::max(r.worst_end_mm, (out_ends[next - 1].tip_W - e.tip_W).norm());
    if (!e.traori_angles_deg.empty())
      r.failure = compare_angles(ex.machine, ex.blocks[next - 1], e.traori_angles_deg, r);
    if (previous && e.motion > 0 && r.failure.empty()) {
      if (!e.tip_straight) r.failure = "a feed that turns rotary axes in machine coordinates: its path is not compared";
      if (e.motion >= 2 && (!e.centre_W || (e.axis_W - V3::UnitZ()).norm() > 1e-6))
        r.failure = "an arc whose centre or plane (XY of W) the tests do not know";
      ControlEnd as_control;
      as_control.motion = e.motion;
      as_control.plane = 17;
      const InputPath path(previous->tip_W, e.tip_W, as_control, e.centre_W.value_or(V3::Zero()));
      if (r.failure.empty())
        r.failure = check_between(ex, path, out_ends, first_block, next, V3(1, 1, 1), between_mm, r);
    }
    if (!r.failure.empty()) {
      r.failure = where + r.failure;
      return r;
    }
    previous = in;
  }
  return r;
}

}  // namespace ncpost::test
