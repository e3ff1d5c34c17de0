// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/plans.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "ncpost/compensation/plan_moves.hpp"
#include "ncpost/kinematics/forward.hpp"
#include "ncpost/kinematics/inverse.hpp"

namespace ncpost::comp {
namespace {

double round_to(double v, double quantum) {
  const double r = std::round(v / quantum) * quantum;
  return r == 0.0 ? 0.0 : r;  // no negative zero
}

/// A row holding the tool point on `target` (mm, M at home, table frame) at the rotary angles.
MeasurementRow row_at(const Machine& m, double t, const Eigen::Vector2d& rotary_deg, const Vec3d& target,
                      double tool_length_mm) {
  MeasurementRow r;
  r.time_s = round_to(t, 0.01);
  Eigen::Vector2d exact, rounded;
  for (int k = 0; k < 2; ++k) {
    exact[k] = deg_to_rad(rotary_deg[k]);
    rounded[k] = deg_to_rad(round_to(rotary_deg[k], 1e-5));
  }
  Setup setup;
  setup.tool_length_mm = tool_length_mm;
  const Vec3d lin = linear_for(m, exact, target, setup);
  for (int i = 0; i < 3; ++i) r.command.linear_mm[i] = round_to(lin[i], 1e-5);
  r.command.rotary_rad = rounded;
  return r;
}

std::string fmt_vec(const Vec3d& v) { return fmt::format("{:.4f}, {:.4f}, {:.4f}", v.x(), v.y(), v.z()); }

std::string fmt_num(double v) { return fmt::format("{:g}", v); }

}  // namespace

std::vector<NamedPlan> plan_ballbar_4axis(const Machine& m, const BallbarPlanOptions& o) {
  if (m.rotary_count() != 2 || m.rotary(0).side != Side::workpiece || m.rotary(1).side != Side::workpiece)
    throw std::invalid_argument("ballbar-4axis needs a table-table machine (two rotary axes on the workpiece side)");
  if (o.points < 4 || o.points % 2 != 0) throw std::invalid_argument("--points must be even and at least 4");
  // tilt = the rotary axis nearer the bed, rotary = the one carrying the workpiece
  int tilt = -1, rot = -1;
  for (int i : m.workpiece_side)
    if (m.axes[static_cast<std::size_t>(i)].is_rotary()) (tilt < 0 ? tilt : rot) = i - 3;
  const Axis& c_axis = m.rotary(rot);
  if (std::abs(c_axis.direction.z()) < 1e-6) throw std::invalid_argument("ballbar-4axis: the rotary axis must not lie in the XY plane");
  std::vector<NamedPlan> out;
  double t = o.t0_s;
  for (std::size_t h = 0; h < o.heights_mm.size(); ++h) {
    const double height = o.heights_mm[h];
    const Vec3d c0 = c_axis.pivot_mm + ((height - c_axis.pivot_mm.z()) / c_axis.direction.z()) * c_axis.direction;
    MeasurementSet s;
    s.type = MeasurementType::ballbar;
    s.has_values = false;
    s.table_ball_mm = c0 + o.bar_length_mm * Vec3d(0, -1, 0);
    s.tool_ball_mm = Vec3d::Zero();
    s.bar_length_mm = o.bar_length_mm;
    s.metadata = {{"type", "ballbar"},
                  {"table_ball", fmt_vec(s.table_ball_mm)},
                  {"tool_ball", fmt_vec(s.tool_ball_mm)},
                  {"bar_length", fmt_num(o.bar_length_mm)},
                  {"test", "ballbar-4axis (seed 000)"},
                  {"height", fmt_num(height)}};
    const int half = o.points / 2;
    for (int part = 0; part < 2; ++part)
      for (int i = 0; i < half; ++i) {
        const double f = double(i) / double(half - 1);
        Eigen::Vector2d deg;
        deg[tilt] = part == 0 ? 90.0 * f : 90.0 * (1.0 - f);
        deg[rot] = part == 0 ? 180.0 * f : 180.0 + 180.0 * f;
        s.rows.push_back(row_at(m, t, deg, c0, 0.0));
        t += o.dt_s;
      }
    t += o.gap_s - o.dt_s;
    s.file = fmt::format("h{}", fmt_num(height));
    out.push_back({s.file, s});
  }
  return out;
}

std::vector<NamedPlan> plan_sphere(const Machine& m, const SpherePlanOptions& o) {
  if (m.rotary_count() != 2) throw std::invalid_argument("sphere: the machine needs two rotary axes");
  if (o.step_deg <= 0.0 || o.step_deg > 180.0) throw std::invalid_argument("sphere: --step must be in (0, 180] degrees");
  // the swept axis is the one parallel to Z at home (C); the other one takes the levels
  int sweep = std::abs(m.rotary(1).direction.z()) > 0.999 ? 1 : (std::abs(m.rotary(0).direction.z()) > 0.999 ? 0 : 1);
  const int level_axis = 1 - sweep;
  MeasurementSet s;
  s.type = MeasurementType::sphere;
  s.has_values = false;
  s.sphere_mm = o.sphere_mm;
  s.metadata = {{"type", "sphere"}, {"sphere", fmt_vec(o.sphere_mm)}, {"test", "sphere (KinematicsOpt style)"}};
  const int n = static_cast<int>(std::floor(360.0 / o.step_deg + 1e-9));
  std::vector<double> sweep_deg;
  for (int i = 0; i < n; ++i) sweep_deg.push_back(i * o.step_deg);
  if (sweep_deg.back() >= 360.0 - 1e-9) sweep_deg.pop_back();
  for (int i = static_cast<int>(sweep_deg.size()) - 2; i >= 0; --i) sweep_deg.push_back(sweep_deg[static_cast<std::size_t>(i)]);
  const Axis& la = m.rotary(level_axis);
  const Axis& sa = m.rotary(sweep);
  double t = o.t0_s;
  for (double level : o.levels_deg) {
    if (la.limits && !la.limits->contains(deg_to_rad(level))) continue;
    for (double c : sweep_deg) {
      if (sa.limits && !sa.limits->contains(deg_to_rad(c))) continue;
      Eigen::Vector2d deg;
      deg[level_axis] = level;
      deg[sweep] = c;
      s.rows.push_back(row_at(m, t, deg, o.sphere_mm, 0.0));
      t += o.dt_s;
    }
  }
  if (s.rows.empty()) throw std::invalid_argument("sphere: no level within the axis limits");
  s.file = "sphere";
  return {{"sphere", s}};
}

std::vector<NamedPlan> plan_bc_head(const Machine& m, const BcHeadPlanOptions& o) {
  const int b = m.index_of('B'), c = m.index_of('C');
  if (b < 0 || c < 0 || m.axes[static_cast<std::size_t>(b)].side != Side::tool || m.axes[static_cast<std::size_t>(c)].side != Side::tool)
    throw std::invalid_argument("bc-head needs a machine with B and C head axes");
  if (o.tool_lengths_mm.empty()) throw std::invalid_argument("bc-head: give at least one --tool-length");
  struct Test {
    const char* name;
    char moving;
    std::vector<double> angles;
    char direction;
  };
  std::vector<Test> tests = {{"c_x", 'C', {0, 90, 180}, 'X'}, {"c_y", 'C', {0, 90, 180}, 'Y'},
                             {"b_x", 'B', {0, 90, -90}, 'X'}};
  if (o.b_test_along_y) tests.push_back({"b_y", 'B', {0, 90, -90}, 'Y'});
  tests.push_back({"b_z", 'B', {0, 90, -90}, 'Z'});
  std::vector<NamedPlan> out;
  double t = o.t0_s;
  for (double tl : o.tool_lengths_mm)
    for (const Test& test : tests) {
      Vec3d dir = Vec3d::Zero();
      dir[test.direction - 'X'] = test.direction == 'Z' ? -1.0 : 1.0;  // the table ball below for Z
      MeasurementSet s;
      s.type = MeasurementType::ballbar;
      s.has_values = false;
      s.table_ball_mm = o.point_mm + o.bar_length_mm * dir;
      s.bar_length_mm = o.bar_length_mm;
      s.tool_length_mm = tl;
      s.metadata = {{"type", "ballbar"},
                    {"table_ball", fmt_vec(s.table_ball_mm)},
                    {"tool_ball", fmt_vec(s.tool_ball_mm)},
                    {"bar_length", fmt_num(o.bar_length_mm)},
                    {"tool_length", fmt_num(tl)},
                    {"test", fmt::format("bc-head {} test, bar along {} (seed 002)", test.moving, test.direction)}};
      for (double a : test.angles) {
        Eigen::Vector2d deg = Eigen::Vector2d::Zero();
        deg[(test.moving == 'B' ? b : c) - 3] = a;
        s.rows.push_back(row_at(m, t, deg, o.point_mm, tl));
        t += o.dt_s;
      }
      t += o.gap_s - o.dt_s;
      s.file = o.tool_lengths_mm.size() > 1 ? fmt::format("{}_L{}", test.name, fmt_num(tl)) : test.name;
      out.push_back({s.file, s});
    }
  return out;
}

namespace {

/// The words of a pose: every axis, mm and degrees.
std::string axis_words(const Machine& m, const AxisPosition& q) {
  std::string w;
  for (std::size_t a = 0; a < m.axes.size(); ++a) {
    const double v = q[static_cast<int>(a)];
    w += fmt::format(" {}{:.5f}", m.axes[a].letter, m.axes[a].is_rotary() ? rad_to_deg(v) : v);
  }
  return w;
}

std::string dwell(const MeasurementSet& s, std::size_t k) {
  const auto& r = s.rows[k];
  const double seconds = k + 1 < s.rows.size() ? std::max(0.0, s.rows[k + 1].time_s - r.time_s - 1.0) : 1.0;
  return fmt::format("G4 X{:.1f} (dwell s, read point {})\n", seconds, k + 1);
}

/// G93 G1 blocks through guided poses, half a second each.
std::string guided_blocks(const Machine& m, const std::vector<AxisPosition>& poses) {
  std::string out;
  for (const auto& q : poses) out += "G93 G1" + axis_words(m, q) + " F120.000\n";
  return out + "G94\n";
}

/// Static ballbar set: read each row, turn between rows holding the tool ball.
std::string ballbar_static_moves(const Machine& m, const MeasurementSet& s, const PlanProgramOptions& o) {
  Setup setup;
  setup.tool_length_mm = s.tool_length_mm;
  std::string out;
  for (std::size_t k = 0; k < s.rows.size(); ++k) {
    if (k > 0) {
      const Vec3d from = forward(m, s.rows[k - 1].command, setup).tip_mm;
      const Vec3d to = forward(m, s.rows[k].command, setup).tip_mm;
      if ((from - to).norm() > o.guide_tolerance_mm)
        throw std::invalid_argument("a static ballbar set must hold the tool ball on one point");
      auto poses = guided_turn(m, s.rows[k - 1].command.rotary_rad, s.rows[k].command.rotary_rad,
                               [&](const Eigen::Vector2d&) { return from; }, setup, o.guide_tolerance_mm);
      poses.back() = s.rows[k].command;  // the row as planned (rounded as in the CSV)
      out += guided_blocks(m, poses);
    }
    out += dwell(s, k);
  }
  return out;
}

/// Sphere set: approach along the probe axis, read, retract along it, turn at the clearance.
std::string sphere_moves(const Machine& m, const MeasurementSet& s, const PlanProgramOptions& o) {
  const Setup setup;  // the rows put the gauge point (tool length 0) on the centre
  const double away = o.clearance_mm + o.turn_tolerance_mm;
  const auto clear_of = [&](const Eigen::Vector2d& rotary) {
    AxisPosition q;
    q.rotary_rad = rotary;
    return Vec3d(s.sphere_mm + away * forward(m, q, setup).axis);
  };
  const auto retracted = [&](const MeasurementRow& r) {
    AxisPosition q = r.command;
    q.linear_mm = linear_for(m, q.rotary_rad, clear_of(q.rotary_rad), setup);
    return q;
  };
  std::string out;
  for (std::size_t k = 0; k < s.rows.size(); ++k) {
    if (k > 0) {
      auto poses = guided_turn(m, s.rows[k - 1].command.rotary_rad, s.rows[k].command.rotary_rad, clear_of, setup,
                               o.turn_tolerance_mm);
      poses.back() = retracted(s.rows[k]);
      out += guided_blocks(m, poses);
    }
    out += "G1" + axis_words(m, s.rows[k].command) + " F1000. (approach along the probe axis)\n";
    out += dwell(s, k);
    out += "G1" + axis_words(m, retracted(s.rows[k])) + " (retract along the probe axis)\n";
  }
  return out;
}

}  // namespace

std::string plan_program(const Machine& m, const std::vector<NamedPlan>& plans, const std::string& title,
                         const PlanProgramOptions& o) {
  std::string out = "%\nO1000 (" + title + ")\n(written by ncpost plan; rows of the plan CSV in order)\nG90 G21 G17\n";
  for (const auto& p : plans) {
    const auto& s = p.set;
    out += fmt::format("(--- set {}: {} ---)\n", p.name, s.meta("test"));
    if (s.type == MeasurementType::ballbar)
      out += fmt::format("(table ball at {} mm, bar {} mm, tool length {} mm)\n", fmt_vec(s.table_ball_mm),
                         fmt_num(s.bar_length_mm), fmt_num(s.tool_length_mm));
    if (s.type == MeasurementType::sphere)
      out += fmt::format("(sphere centre at {} mm; the stylus turns {} mm from it, moves to it along the probe axis only)\n",
                         fmt_vec(s.sphere_mm), fmt_num(o.clearance_mm));
    if (s.rows.empty()) continue;
    AxisPosition start = s.rows.front().command;
    if (s.type == MeasurementType::sphere) {
      const Setup setup;
      start.linear_mm = linear_for(m, start.rotary_rad,
                                   s.sphere_mm + (o.clearance_mm + o.turn_tolerance_mm) * forward(m, start, setup).axis, setup);
    }
    out += "G94 G0" + axis_words(m, start) + "\n";
    out += "M0 (mount the instrument, start recording)\n";
    if (s.type == MeasurementType::sphere) {
      out += sphere_moves(m, s, o);
    } else if (o.continuous) {
      for (std::size_t k = 1; k < s.rows.size(); ++k) {
        const double dt = s.rows[k].time_s - s.rows[k - 1].time_s;
        out += fmt::format("G93 G1{} F{:.3f}\n", axis_words(m, s.rows[k].command), dt > 0 ? 60.0 / dt : 600.0);
      }
      out += "G94\n";
    } else {
      out += ballbar_static_moves(m, s, o);
    }
    out += "M0 (stop recording, remove the instrument)\n";
  }
  out += "M30\n%\n";
  return out;
}

}  // namespace ncpost::comp
