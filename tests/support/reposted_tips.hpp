// SPDX-License-Identifier: Apache-2.0
#pragma once
// The re-post check of issue 24 for tool-tip (RTCP) input, the real corpus's reading: the INPUT
// program executed as its control would (control_interpreter.hpp: X Y Z are the tool tip in the
// workpiece frame W, the rotary words the angles) against the written OUTPUT executed by
// nc_executor.hpp through the machine's forward kinematics with the job's workpiece origin.
//
// - Every input block end once every axis is programmed: the output must reach it, in order, with
//   the tip within 1 µm and the tool axis within 1e-6 (an end where the input does not move needs no
//   output block).
// - Between the ends of an input feed move (G1, G2/G3, a cycle's feed) every output block that
//   realises it is sampled at 16 points (a straight block against a straight path: at its two ends,
//   where the distance to a segment, convex along a line, is largest); each sample must lie within the tolerance the
//   output's header states (+ 1 µm) of the input's path: under RTCP the tip moves straight in W from end to end, an arc
//   turns about its centre in its plane (the radius and the third axis change linearly with the angle: a slightly
//   spiral arc and a helix as the control runs them). None of those output blocks may be a rapid. Rapids are not
//   sampled: their path is the control's own.
// - Machine-coordinate moves (G28/G30/G53) place the machine's axes at the machine file's
//   reference points (Z without one: the top of its travel, as docs/formats.md says a control's
//   reference is), read from the file by ExecMachine; the tip follows through the closure.
// - A linear axis the input never programs (a 2D plasma program without Z) is left out of the
//   comparison (its place is nowhere in the input); an axis not programmed yet leaves the end out.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "control_interpreter.hpp"
#include "input_output_tips.hpp"
#include "nc_executor.hpp"

namespace ncpost::test {

/// What the check compared: input ends reached, output samples checked, the largest deviations.
struct RepostCheck {
  int ends = 0;
  int samples = 0;
  double worst_end_mm = 0.0;
  double worst_between_mm = 0.0;
  std::string failure;  ///< the first difference found ("" none): where, and by how much
};

/// The interpreter set for a tool-tip reading on the machine `m` (the words: the tip in W, the work
/// offsets' values 0): G28/G30/G53 move the machine's axes, found from the tip through the closure
/// and back; the reference points are the machine file's `reference`/`reference2` (M), Z without
/// `reference` the top of its travel.
inline void set_machine_moves(ControlSpec& spec, const ExecMachine& m, const ExecJob& job) {
  for (const auto& [letter, a] : m.all_axes) {
    std::optional<double> ref = a.reference;
    if (!ref && letter == 'Z') ref = a.limit_max;
    if (ref) spec.reference[letter] = *ref;
    if (a.reference2) spec.reference2[letter] = *a.reference2;
  }
  auto rotary_of = [](const std::map<char, double>& w) {
    std::map<char, double> r;
    for (const auto& [a, v] : w)
      if (a != 'X' && a != 'Y' && a != 'Z') r[a] = v;
    return r;
  };
  spec.tip_to_machine = [&m, job, rotary_of](const std::map<char, double>& words) {
    std::map<char, double> out = words;
    const V3 xyz = machine_xyz_for_tip(m, job, V3(words.at('X'), words.at('Y'), words.at('Z')), rotary_of(words));
    out['X'] = xyz.x(), out['Y'] = xyz.y(), out['Z'] = xyz.z();
    return out;
  };
  spec.machine_to_tip = [&m, job, rotary_of](const std::map<char, double>& axes) {
    std::map<char, double> out = axes;
    const V3 tip = forward(m, job, V3(axes.at('X'), axes.at('Y'), axes.at('Z')), rotary_of(axes)).tip_W;
    out['X'] = tip.x(), out['Y'] = tip.y(), out['Z'] = tip.z();
    return out;
  };
}

/// The input's path between two ends: a straight tip line in W, or an arc.
struct InputPath {
  V3 from = V3::Zero(), to = V3::Zero();
  bool arc = false;
  V3 centre = V3::Zero();
  std::array<int, 3> axes{0, 1, 2};  ///< the plane's two axes and its normal
  double a0 = 0.0, sweep = 0.0, r0 = 0.0, r1 = 0.0;

  InputPath(const V3& a, const V3& b, const ControlEnd& e, const V3& centre_W) : from(a), to(b) {
    if (e.motion < 2) return;
    arc = true;
    centre = centre_W;
    axes = e.plane == 17   ? std::array<int, 3>{0, 1, 2}
           : e.plane == 18 ? std::array<int, 3>{2, 0, 1}
                           : std::array<int, 3>{1, 2, 0};
    const int u = axes[0], v = axes[1];
    a0 = std::atan2(a[v] - centre[v], a[u] - centre[u]);
    const double a1 = std::atan2(b[v] - centre[v], b[u] - centre[u]);
    r0 = std::hypot(a[u] - centre[u], a[v] - centre[v]);
    r1 = std::hypot(b[u] - centre[u], b[v] - centre[v]);
    sweep = a1 - a0;
    if (e.motion == 3 && sweep <= 1e-9) sweep += 2 * M_PI;
    if (e.motion == 2 && sweep >= -1e-9) sweep -= 2 * M_PI;
  }

  V3 at(double t) const {
    if (!arc) return from + t * (to - from);
    V3 p;
    const double r = r0 + t * (r1 - r0), a = a0 + t * sweep;
    p[axes[0]] = centre[axes[0]] + r * std::cos(a);
    p[axes[1]] = centre[axes[1]] + r * std::sin(a);
    p[axes[2]] = from[axes[2]] + t * (to[axes[2]] - from[axes[2]]);
    return p;
  }

  /// The distance from p: exact for a line; for an arc the nearest of samples 1/32 rad apart (the
  /// distance to a circle or helix has one minimum within each such bracket), refined.
  double distance(const V3& p) const {
    if (!arc) return from_segment(p, from, to);
    const int n = std::clamp(static_cast<int>(std::ceil(std::abs(sweep) * 32.0)), 16, 4096);
    int best = 0;
    double best_d = 1e300;
    for (int i = 0; i <= n; ++i) {
      const double d = (at(static_cast<double>(i) / n) - p).norm();
      if (d < best_d) best_d = d, best = i;
    }
    double lo = std::max(0, best - 1) / static_cast<double>(n), hi = std::min(n, best + 1) / static_cast<double>(n);
    for (int k = 0; k < 60; ++k) {  // golden-section search on the bracket
      const double m1 = hi - (hi - lo) * 0.618033988749895, m2 = lo + (hi - lo) * 0.618033988749895;
      if ((at(m1) - p).norm() < (at(m2) - p).norm())
        hi = m2;
      else
        lo = m1;
    }
    return std::min(best_d, (at((lo + hi) / 2) - p).norm());
  }
};

/// The output blocks [first, last) that realise one input feed move along `path`: none a rapid that
/// moves, every sample within `between_mm` (components where `mask` is 0 not compared). The
/// failure ("" none); counts and the largest distance go into `r`.
inline std::string check_between(const Executor& ex, const InputPath& path, const std::vector<ExecPose>& out_ends,
                                 std::size_t first, std::size_t last, const V3& mask, double between_mm,
                                 RepostCheck& r) {
  for (std::size_t b = first; b < last; ++b) {
    const ExecBlock& ob = ex.blocks[b];
    const std::string block = "output line " + std::to_string(ob.line) + " '" + ob.text + "'";
    const bool moves = (ex.at(ob, 0.0).tip_W - out_ends[b].tip_W).cwiseProduct(mask).norm() >= 1e-3;
    if (ob.kind == ExecBlock::Kind::rapid && moves) return block + " is a rapid where the input feeds";
    // a straight output block (no rotary axis turning) against a straight input path: the distance
    // to a segment is convex along a line, its largest at the block's ends
    bool straight = !path.arc && ob.kind == ExecBlock::Kind::linear;
    for (char c : ex.machine.rotary_letters)
      straight = straight && (ob.from.count(c) ? ob.from.at(c) : 0.0) == (ob.to.count(c) ? ob.to.at(c) : 0.0);
    for (int k = straight ? 0 : 1; k <= 16; k += straight ? 16 : 1) {
      V3 p = ex.at(ob, k / 16.0).tip_W;
      for (int i = 0; i < 3; ++i)
        if (mask[i] == 0.0) p[i] = path.at(0.0)[i];  // an axis never programmed: not compared
      const double d = path.distance(p);
      ++r.samples;
      r.worst_between_mm = std::max(r.worst_between_mm, d);
      if (d > between_mm)
        return block + " at " + std::to_string(k) + "/16 lies " + std::to_string(d) +
               " mm from the input's path (allowed " + std::to_string(between_mm) + " mm)";
    }
  }
  return {};
}

/// Tip (components where `mask` is 1) within 1 µm and tool axis within 1e-6: the same place.
inline bool same_place(const ExecPose& a, const ExecPose& b, const V3& mask = V3(1, 1, 1)) {
  return (a.tip_W - b.tip_W).cwiseProduct(mask).norm() < 1e-3 && (a.axis_W - b.axis_W).norm() < 1e-6;
}

/// The first output end from `next` on at `in`'s place: `next` moves past it; "" found, else the
/// failure (after which output line nothing ends there).
inline std::string reach_output_end(const Executor& ex, const std::vector<ExecPose>& out_ends, std::size_t& next,
                                    const ExecPose& in, const V3& mask = V3(1, 1, 1)) {
  const std::size_t first_block = next;
  for (; next < out_ends.size(); ++next)
    if (same_place(out_ends[next], in, mask)) return ++next, std::string();
  return "no output block ends there (1 um, 1e-6) after output line " +
         (first_block < ex.blocks.size() ? std::to_string(ex.blocks[first_block].line) : std::string("end"));
}

/// Executes `input` (tool-tip reading) and `output` and compares them as the header says.
inline RepostCheck compare_reposted_tips(const std::string& input, ControlSpec spec, const std::string& machine_file,
                                         const ExecJob& job, const std::string& output) {
  constexpr double kTipToleranceMm = 1e-3;
  const Executor ex(machine_file, job, output);
  set_machine_moves(spec, ex.machine, job);
  ControlInterpreter control(input, spec);
  const std::vector<ControlEnd> ends = control.run();
  const std::string never = control.never_programmed();
  V3 mask(1, 1, 1);  // the components compared
  RepostCheck r;
  for (char a : never) {
    if (std::string("XYZ").find(a) == std::string::npos)
      return RepostCheck{0, 0, 0, 0, std::string("rotary axis ") + a + " never programmed: leave it out of spec.axes"};
    mask[a == 'X' ? 0 : a == 'Y' ? 1 : 2] = 0.0;
  }
  auto gap = [&](const V3& a, const V3& b) { return (a - b).cwiseProduct(mask).norm(); };
  const std::map<char, double> base = control.value_at_first_motion(control.offset_at_first_motion());
  const double between_mm = stated_tolerance_mm(output, kTipToleranceMm) + kTipToleranceMm;

  std::vector<ExecPose> out_ends;
  for (const ExecBlock& b : ex.blocks) out_ends.push_back(ex.at(b, 1.0));
  auto input_pose = [&](const std::map<char, double>& machine) {
    std::map<char, double> rot;
    for (const auto& [a, v] : machine)
      if (a != 'X' && a != 'Y' && a != 'Z') rot[a] = v - base.at(a);
    ExecPose p = forward(ex.machine, job, V3::Zero(), rot);
    p.tip_W = V3(machine.at('X') - base.at('X'), machine.at('Y') - base.at('Y'), machine.at('Z') - base.at('Z'));
    return p;
  };

  std::size_t next = 0;
  std::optional<ExecPose> previous;
  for (const ControlEnd& e : ends) {
    bool only_never = true;
    for (char a : e.unknown) only_never = only_never && never.find(a) != std::string::npos;
    if (!e.complete && !only_never) {
      previous.reset();
      continue;
    }
    const ExecPose in = input_pose(e.machine);
    auto where = [&] {
      std::ostringstream o;
      o << "input line " << e.line << " (tip " << in.tip_W.transpose() << ", axis " << in.axis_W.transpose() << "): ";
      return o.str();
    };
    if (previous && e.motion < 2 && same_place(*previous, in, mask)) {
      ++r.ends;  // the input does not move: no output block needed
      continue;
    }
    const std::size_t first_block = next;
    if (const std::string missed = reach_output_end(ex, out_ends, next, in, mask); !missed.empty()) {
      r.failure = where() + missed;
      return r;
    }
    ++r.ends;
    r.worst_end_mm = std::max(r.worst_end_mm, gap(out_ends[next - 1].tip_W, in.tip_W));
    if (previous && !e.rapid) {
      V3 centre = V3::Zero();
      for (int i = 0; i < 3 && e.motion >= 2; ++i) centre[i] = e.centre.at("XYZ"[i]) - base.at("XYZ"[i]);
      const InputPath path(previous->tip_W, in.tip_W, e, centre);
      const std::string failure = check_between(ex, path, out_ends, first_block, next, mask, between_mm, r);
      if (!failure.empty()) {
        r.failure = where() + failure;
        return r;
      }
    }
    previous = in;
  }
  return r;
}

}  // namespace ncpost::test
