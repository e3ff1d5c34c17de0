// SPDX-License-Identifier: Apache-2.0
// The NC program of the ballbar and sphere plans (plans.hpp) as neutral records (plan_program.hpp).
#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "ncpost/compensation/plan_moves.hpp"
#include "ncpost/compensation/plans.hpp"
#include "ncpost/kinematics/forward.hpp"
#include "ncpost/kinematics/inverse.hpp"
#include "ncpost/machines/formatters.hpp"

namespace ncpost::comp {
namespace {

/// A guided step (plan_moves.hpp) takes this long: slow enough for the instrument, and its
/// timing is not part of the measurement.
constexpr double kGuidedStepS = 0.5;
/// The sphere probe comes to and leaves each probing pose along its axis at this feed (mm/min).
constexpr double kProbeAxisFeedMmMin = 1000.0;
/// A continuous ballbar move between two rows with the same time stamp takes this long (s).
constexpr double kUntimedRowS = 0.1;
/// The reading of a static set takes this long; the dwell before the next row is the rest of the
/// rows' time step, and the last row is read for this long too (s).
constexpr double kReadingS = 1.0;

std::string short_text(double v) { return fmt::format("{:g}", v); }

/// The dwell that reads row k of the set.
void read_row(PlanProgram& p, const MeasurementSet& s, std::size_t k) {
  const auto& r = s.rows[k];
  const double seconds = k + 1 < s.rows.size() ? std::max(0.0, s.rows[k + 1].time_s - r.time_s - kReadingS) : kReadingS;
  p.dwell(seconds, fmt::format("read point {}", k + 1));
}

/// Inverse-time moves through guided poses, kGuidedStepS each.
void guided_moves(PlanProgram& p, const std::vector<AxisPosition>& poses) {
  for (const auto& q : poses) p.inverse_time(q, 60.0 / kGuidedStepS, false);
}

/// Static ballbar set: read each row, turn between rows holding the tool ball.
void ballbar_static_moves(PlanProgram& p, const Machine& m, const MeasurementSet& s, const PlanProgramOptions& o) {
  Setup setup;
  setup.tool_length_mm = s.tool_length_mm;
  for (std::size_t k = 0; k < s.rows.size(); ++k) {
    if (k > 0) {
      const Vec3d from = forward(m, s.rows[k - 1].command, setup).tip_mm;
      const Vec3d to = forward(m, s.rows[k].command, setup).tip_mm;
      if ((from - to).norm() > o.guide_tolerance_mm)
        throw std::invalid_argument("a static ballbar set must hold the tool ball on one point");
      auto poses = guided_turn(
          m, s.rows[k - 1].command.rotary_rad, s.rows[k].command.rotary_rad,
          [&](const Eigen::Vector2d&) { return from; }, setup, o.guide_tolerance_mm);
      poses.back() = s.rows[k].command;  // the row as planned (rounded as in the CSV)
      guided_moves(p, poses);
    }
    read_row(p, s, k);
  }
}

/// Continuous ballbar set: one inverse-time move to each row, taking the rows' time step.
void ballbar_continuous_moves(PlanProgram& p, const MeasurementSet& s) {
  for (std::size_t k = 1; k < s.rows.size(); ++k) {
    const double dt = s.rows[k].time_s - s.rows[k - 1].time_s;
    p.inverse_time(s.rows[k].command, 60.0 / (dt > 0 ? dt : kUntimedRowS), true);
  }
}

/// Where the stylus is `away_mm` from the sphere centre along the probe axis at the rotary angles.
AxisPosition clear_of_sphere(const Machine& m, const MeasurementSet& s, const Eigen::Vector2d& rotary_rad,
                             double away_mm) {
  const Setup setup;  // the rows put the gauge point (tool length 0) on the centre
  AxisPosition q;
  q.rotary_rad = rotary_rad;
  q.linear_mm = linear_for(m, rotary_rad, s.sphere_mm + away_mm * forward(m, q, setup).axis, setup);
  return q;
}

/// Sphere set: approach along the probe axis, read, retract along it, turn at the clearance.
void sphere_moves(PlanProgram& p, const Machine& m, const MeasurementSet& s, const PlanProgramOptions& o) {
  const Setup setup;
  const double away = o.clearance_mm + o.turn_tolerance_mm;
  const auto clear_of = [&](const Eigen::Vector2d& rotary) {
    AxisPosition q;
    q.rotary_rad = rotary;
    return Vec3d(s.sphere_mm + away * forward(m, q, setup).axis);
  };
  for (std::size_t k = 0; k < s.rows.size(); ++k) {
    const AxisPosition retracted = clear_of_sphere(m, s, s.rows[k].command.rotary_rad, away);
    if (k > 0) {
      auto poses = guided_turn(m, s.rows[k - 1].command.rotary_rad, s.rows[k].command.rotary_rad, clear_of, setup,
                               o.turn_tolerance_mm);
      poses.back() = retracted;
      guided_moves(p, poses);
    }
    p.feed(s.rows[k].command, kProbeAxisFeedMmMin, "approach along the probe axis");
    read_row(p, s, k);
    p.feed(retracted, kProbeAxisFeedMmMin, "retract along the probe axis");
  }
}

/// The comments that open a set.
void describe_set(PlanProgram& p, const NamedPlan& named, const PlanProgramOptions& o) {
  const MeasurementSet& s = named.set;
  p.comment(fmt::format("--- set {}: {} ---", named.name, s.meta("test")));
  if (s.type == MeasurementType::ballbar)
    p.comment(fmt::format("table ball at {:.4f} mm, bar {} mm, tool length {} mm", s.table_ball_mm,
                          short_text(s.bar_length_mm), short_text(s.tool_length_mm)));
  if (s.type == MeasurementType::sphere)
    p.comment(
        fmt::format("sphere centre at {:.4f} mm: the stylus turns {} mm from it, moves to it along the probe axis only",
                    s.sphere_mm, short_text(o.clearance_mm)));
}

}  // namespace

PlanProgram plan_program(const Machine& m, const std::vector<NamedPlan>& plans, const std::string& title,
                         const PlanProgramOptions& o) {
  PlanProgram p;
  p.name = title;
  p.header = {title, "machine " + m.name, "written by ncpost plan: rows of the plan CSV in order"};
  for (const auto& named : plans) {
    const auto& s = named.set;
    describe_set(p, named, o);
    if (s.rows.empty()) continue;
    p.rapid(s.type == MeasurementType::sphere
                ? clear_of_sphere(m, s, s.rows.front().command.rotary_rad, o.clearance_mm + o.turn_tolerance_mm)
                : s.rows.front().command);
    p.stop("mount the instrument, start recording");
    if (s.type == MeasurementType::sphere)
      sphere_moves(p, m, s, o);
    else if (o.continuous)
      ballbar_continuous_moves(p, s);
    else
      ballbar_static_moves(p, m, s, o);
    p.stop("stop recording, remove the instrument");
  }
  return p;
}

}  // namespace ncpost::comp
