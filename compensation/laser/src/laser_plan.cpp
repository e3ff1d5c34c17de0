// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/laser_plan.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace ncpost::comp {
namespace {

/// The travel ends are targets too where they lie more than this fraction of a step beyond the grid.
constexpr double kEndBeyondGridSteps = 0.25;
/// The measuring lines of an axis that is commanded lie on this grid (mm), at 1/4 and 3/4 of its travel.
constexpr double kLineGridMm = 5.0;
/// Time to re-set the optics between two sets (s), in the rows' time stamps.
constexpr double kOpticsSetupS = 60.0;
/// Of each target's time (dt_s), the move there takes this long; the rest is the dwell (s) ...
constexpr double kTargetMoveS = 2.0;
/// ... but the dwell is at least this long (s).
constexpr double kMinDwellS = 1.0;
/// Slack of the count of steps in a travel (floating point).
constexpr double kStepSlack = 1e-9;
/// The rows' time stamps are written to 1/100 s.
constexpr double kTimeStampsPerS = 100.0;

int position_in(const std::vector<int>& side, int axis) {
  const auto it = std::find(side.begin(), side.end(), axis);
  return it == side.end() ? -1 : static_cast<int>(it - side.begin());
}

double rounded_to_quantum(double v, double quantum) {
  const double r = std::round(v / quantum) * quantum;
  return r == 0.0 ? 0.0 : r;
}

/// Travel of linear axis j minus the margins (mm).
std::pair<double, double> travel(const Machine& m, int j, double margin_mm) {
  const Axis& a = m.axes[static_cast<std::size_t>(j)];
  if (!a.limits) throw std::invalid_argument(fmt::format("axis {} has no limits in the machine file", a.letter));
  const double lo = a.limits->min + margin_mm, hi = a.limits->max - margin_mm;
  if (hi <= lo) throw std::invalid_argument(fmt::format("axis {}: the margins leave no travel", a.letter));
  return {lo, hi};
}

}  // namespace

std::string LaserPlanOptions::validate() const {
  if (axes.empty()) return "no axes to measure";
  for (char c : axes)
    if (c != 'X' && c != 'Y' && c != 'Z') return fmt::format("axes must be among X, Y, Z, found '{}'", c);
  if (!(step_mm > 0.0)) return "the target step must be positive";
  if (runs < 1) return "at least one run";
  if (lines < 1 || lines > 3) return "1 to 3 lines per axis";
  if (!(tool_length_mm >= 0.0)) return "the tool length must not be negative";
  if (!(overshoot_mm >= 0.0) || !(margin_mm >= 0.0)) return "overshoot and margin must not be negative";
  if (!(feed_mm_min > 0.0) || !(dt_s > 0.0)) return "feed and time per target must be positive";
  return {};
}

bool moves_abbe_offset(const Machine& m, int j, int k) {
  const int j_work = position_in(m.workpiece_side, j), k_work = position_in(m.workpiece_side, k);
  const int j_tool = position_in(m.tool_side, j), k_tool = position_in(m.tool_side, k);
  if (j_work >= 0) return k_tool >= 0 || (k_work >= 0 && k_work < j_work);
  return k_tool >= 0 && k_tool > j_tool;
}

std::vector<double> laser_targets(const Machine& m, int j, const LaserPlanOptions& o) {
  // the overshoot before each pass must stay within the travel too
  const auto [lo, hi] = travel(m, j, o.margin_mm + o.overshoot_mm);
  std::vector<double> t;
  if (lo <= 0.0 && hi >= 0.0) {
    // a grid through home, plus the travel ends where they are more than a quarter step away
    const double q = o.rounding.linear_mm;
    for (double k = std::ceil(lo / o.step_mm - kStepSlack); k * o.step_mm <= hi + kStepSlack; k += 1.0)
      t.push_back(rounded_to_quantum(k * o.step_mm, q));
    if (t.empty() || t.front() - lo > kEndBeyondGridSteps * o.step_mm) t.insert(t.begin(), rounded_to_quantum(lo, q));
    if (t.back() < hi - kEndBeyondGridSteps * o.step_mm) t.push_back(rounded_to_quantum(hi, q));
  } else {
    const int n = static_cast<int>(std::floor((hi - lo) / o.step_mm + kStepSlack)) + 1;
    const double start = lo + 0.5 * ((hi - lo) - (n - 1) * o.step_mm);
    for (int i = 0; i < n; ++i) t.push_back(rounded_to_quantum(start + i * o.step_mm, o.rounding.linear_mm));
  }
  return t;
}

namespace {

/// The two directions other than axis j (XYZ order) and their two line coordinates each: a
/// commanded axis's (1/4 and 3/4 of its travel), else the reflector's offset on the tool.
struct LineLayout {
  std::array<int, 2> other{};
  std::array<std::array<double, 2>, 2> at{};
  std::array<bool, 2> commanded{};
};

LineLayout line_layout(const Machine& m, int j, const LaserPlanOptions& o) {
  LineLayout l;
  for (int k = 0, n = 0; k < 3; ++k) {
    if (k == j) continue;
    l.other[n] = k;
    l.commanded[n] = moves_abbe_offset(m, j, k);
    if (l.commanded[n]) {
      const auto [lo, hi] = travel(m, k, o.margin_mm);
      l.at[n] = {rounded_to_quantum(lo + 0.25 * (hi - lo), kLineGridMm),
                 rounded_to_quantum(lo + 0.75 * (hi - lo), kLineGridMm)};
    } else {
      l.at[n] = {-o.reflector_offset_mm, o.reflector_offset_mm};
    }
    ++n;
  }
  return l;
}

/// Where one measuring line lies: the other axes' commands, the reflector on the tool, and the
/// line's two coordinates as commanded.
struct LinePose {
  AxisPosition base;
  Vec3d tool_point = Vec3d::Zero();
  std::array<double, 2> line_cmd{0.0, 0.0};
};

LinePose line_pose(const LineLayout& l, int line) {
  // lines (a1, b2), (a2, b2), (a1, b1): not collinear, so pitch, yaw and roll are all seen
  const std::array<std::array<int, 2>, 3> pick{{{0, 1}, {1, 1}, {0, 0}}};
  LinePose p;
  for (int n = 0; n < 2; ++n) {
    const double v = l.at[n][static_cast<std::size_t>(pick[static_cast<std::size_t>(line)][n])];
    if (l.commanded[n]) {
      p.base[l.other[n]] = v;
      p.line_cmd[n] = v;
    } else {
      p.tool_point[l.other[n]] = v;
    }
  }
  return p;
}

/// The set of component c of axis `letter` on one line (0-based): the ISO 230-2 cycle, `runs`
/// times up and down the targets, time stamps from `t` (advanced past the set and the optics' set-up).
NamedPlan laser_set(char letter, char c, int line, const LinePose& pose, const std::vector<double>& targets,
                    const LaserPlanOptions& o, double& t) {
  const int j = letter - 'X';
  NamedPlan p;
  p.name = c == letter ? fmt::format("{}{}_pos", letter, line + 1) : fmt::format("{}{}_str{}", letter, line + 1, c);
  MeasurementSet& s = p.set;
  s.file = p.name;
  s.type = MeasurementType::laser;
  s.has_values = false;
  s.component = c;
  s.tool_point_mm = pose.tool_point;
  s.tool_length_mm = o.tool_length_mm;
  s.set_meta("axis", std::string(1, letter));
  s.set_meta("line", fmt::format("{:.4f}, {:.4f}", pose.line_cmd[0], pose.line_cmd[1]));
  s.set_meta("approach", "bidirectional");
  s.set_meta("test",
             fmt::format("laser {} of axis {}, line {} (ISO 230-2 cycle, {} runs)",
                         c == letter ? "positioning" : fmt::format("straightness in {}", c), letter, line + 1, o.runs));
  for (int run = 1; run <= o.runs; ++run) {
    for (int pass = 0; pass < 2; ++pass) {
      for (std::size_t i = 0; i < targets.size(); ++i) {
        const double x = pass == 0 ? targets[i] : targets[targets.size() - 1 - i];
        MeasurementRow r;
        r.command = pose.base;
        r.command[j] = x;
        r.run = run;
        r.approach = pass == 0 ? 1 : -1;
        r.time_s = std::round(t * kTimeStampsPerS) / kTimeStampsPerS;
        t += o.dt_s;
        s.rows.push_back(r);
      }
    }
  }
  t += kOpticsSetupS;
  return p;
}

}  // namespace

std::vector<NamedPlan> plan_laser(const Machine& m, const LaserPlanOptions& o) {
  if (const std::string why = o.validate(); !why.empty()) throw std::invalid_argument(why);
  std::vector<NamedPlan> plans;
  double t = o.t0_s;
  for (char letter : o.axes) {
    const int j = letter - 'X';
    const std::vector<double> targets = laser_targets(m, j, o);
    const LineLayout layout = line_layout(m, j, o);
    for (int line = 0; line < o.lines; ++line) {
      const LinePose pose = line_pose(layout, line);
      std::vector<char> components{letter};
      if (o.straightness)
        for (int n = 0; n < 2; ++n) components.push_back(static_cast<char>('X' + layout.other[n]));
      for (char c : components) plans.push_back(laser_set(letter, c, line, pose, targets, o, t));
    }
  }
  return plans;
}

PlanProgram laser_program(const Machine& m, const std::vector<NamedPlan>& plans, const LaserPlanOptions& o) {
  PlanProgram p;
  p.name = "ncpost plan laser";
  p.header = {"ncpost plan laser: ISO 230-2 test cycles", "machine " + m.name};
  const double dwell_s = std::max(kMinDwellS, o.dt_s - kTargetMoveS);
  for (const auto& named : plans) {
    const MeasurementSet& s = named.set;
    if (s.rows.empty()) continue;
    const int j = s.meta("axis").empty() ? 0 : s.meta("axis")[0] - 'X';
    p.comment(fmt::format("--- set {}: {} ---", named.name, s.meta("test")));
    p.comment(fmt::format("reflector at {:.1f}, {:.1f}, {:.1f} mm from the tool tip, tool length {:.1f} mm, reads {}",
                          s.tool_point_mm.x(), s.tool_point_mm.y(), s.tool_point_mm.z(), s.tool_length_mm,
                          s.component));
    AxisPosition start = s.rows.front().command;
    start[j] -= o.overshoot_mm;
    p.rapid(start);
    p.stop("set up the optics on this line, zero the laser at the first target");
    for (std::size_t k = 0; k < s.rows.size(); ++k) {
      const MeasurementRow& r = s.rows[k];
      const bool pass_start = k == 0 || r.approach != s.rows[k - 1].approach;
      if (pass_start) {  // ISO 230-2: overshoot, then approach the first target of the pass
        AxisPosition before = r.command;
        before[j] -= r.approach * o.overshoot_mm;
        p.comment(fmt::format("run {} {} pass", r.run, r.approach > 0 ? "forward" : "backward"));
        p.feed(before, o.feed_mm_min);
      }
      p.feed(r.command, o.feed_mm_min);
      p.dwell(dwell_s, fmt::format("read {}", k + 1));
    }
  }
  return p;
}

}  // namespace ncpost::comp
