// SPDX-License-Identifier: Apache-2.0
#include "ncpost/compensation/plans.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "ncpost/kinematics/inverse.hpp"
#include "ncpost/machines/formatters.hpp"

namespace ncpost::comp {
namespace {

constexpr double kTimeQuantumS = 0.01;  ///< the rows' time stamps are written to 1/100 s
/// |z| of a unit axis direction below which the axis lies in the XY plane (it meets no height)
constexpr double kInXyPlane = 1e-6;
/// |z| of a unit axis direction above which the axis is taken as parallel to Z (within 2.6°)
constexpr double kParallelToZ = 0.999;
/// slack of the floating-point comparisons of angles in degrees (counts of steps in 360°)
constexpr double kAngleSlackDeg = 1e-9;

double round_to(double v, double quantum) {
  const double r = std::round(v / quantum) * quantum;
  return r == 0.0 ? 0.0 : r;  // no negative zero
}

/// A row holding the tool point on `target` (mm, M at home, table frame) at the rotary angles
/// (the linear axes from the exact angles, then each command rounded: the public scenarios' rows).
MeasurementRow row_at(const Machine& m, double t, const Eigen::Vector2d& rotary_deg, const Vec3d& target,
                      double tool_length_mm, const CommandRounding& rounding) {
  MeasurementRow r;
  r.time_s = round_to(t, kTimeQuantumS);
  Eigen::Vector2d exact, rounded;
  for (int k = 0; k < 2; ++k) {
    exact[k] = deg_to_rad(rotary_deg[k]);
    rounded[k] = deg_to_rad(round_to(rotary_deg[k], rounding.angle_deg));
  }
  Setup setup;
  setup.tool_length_mm = tool_length_mm;
  const Vec3d lin = linear_for(m, exact, target, setup);
  for (int i = 0; i < 3; ++i) r.command.linear_mm[i] = round_to(lin[i], rounding.linear_mm);
  r.command.rotary_rad = rounded;
  return r;
}

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
  if (std::abs(c_axis.direction.z()) < kInXyPlane)
    throw std::invalid_argument("ballbar-4axis: the rotary axis must not lie in the XY plane");
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
                  {"table_ball", fmt::format("{:.4f}", s.table_ball_mm)},
                  {"tool_ball", fmt::format("{:.4f}", s.tool_ball_mm)},
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
        s.rows.push_back(row_at(m, t, deg, c0, 0.0, o.rounding));
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
  if (o.step_deg <= 0.0 || o.step_deg > 180.0)
    throw std::invalid_argument("sphere: --step must be in (0, 180] degrees");
  // the swept axis is the one parallel to Z at home (C); the other one takes the levels
  int sweep = std::abs(m.rotary(1).direction.z()) > kParallelToZ
                  ? 1
                  : (std::abs(m.rotary(0).direction.z()) > kParallelToZ ? 0 : 1);
  const int level_axis = 1 - sweep;
  MeasurementSet s;
  s.type = MeasurementType::sphere;
  s.has_values = false;
  s.sphere_mm = o.sphere_mm;
  s.metadata = {
      {"type", "sphere"}, {"sphere", fmt::format("{:.4f}", o.sphere_mm)}, {"test", "sphere (KinematicsOpt style)"}};
  const int n = static_cast<int>(std::floor(360.0 / o.step_deg + kAngleSlackDeg));
  std::vector<double> sweep_deg;
  for (int i = 0; i < n; ++i) sweep_deg.push_back(i * o.step_deg);
  if (sweep_deg.back() >= 360.0 - kAngleSlackDeg) sweep_deg.pop_back();
  for (int i = static_cast<int>(sweep_deg.size()) - 2; i >= 0; --i)
    sweep_deg.push_back(sweep_deg[static_cast<std::size_t>(i)]);
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
      s.rows.push_back(row_at(m, t, deg, o.sphere_mm, 0.0, o.rounding));
      t += o.dt_s;
    }
  }
  if (s.rows.empty()) throw std::invalid_argument("sphere: no level within the axis limits");
  s.file = "sphere";
  return {{"sphere", s}};
}

std::vector<NamedPlan> plan_bc_head(const Machine& m, const BcHeadPlanOptions& o) {
  const int b = m.index_of('B'), c = m.index_of('C');
  if (b < 0 || c < 0 || m.axes[static_cast<std::size_t>(b)].side != Side::tool ||
      m.axes[static_cast<std::size_t>(c)].side != Side::tool)
    throw std::invalid_argument("bc-head needs a machine with B and C head axes");
  if (o.tool_lengths_mm.empty()) throw std::invalid_argument("bc-head: give at least one --tool-length");
  struct Test {
    const char* name;
    char moving;
    std::vector<double> angles;
    char direction;
  };
  std::vector<Test> tests = {
      {"c_x", 'C', {0, 90, 180}, 'X'}, {"c_y", 'C', {0, 90, 180}, 'Y'}, {"b_x", 'B', {0, 90, -90}, 'X'}};
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
                    {"table_ball", fmt::format("{:.4f}", s.table_ball_mm)},
                    {"tool_ball", fmt::format("{:.4f}", s.tool_ball_mm)},
                    {"bar_length", fmt_num(o.bar_length_mm)},
                    {"tool_length", fmt_num(tl)},
                    {"test", fmt::format("bc-head {} test, bar along {} (seed 002)", test.moving, test.direction)}};
      for (double a : test.angles) {
        Eigen::Vector2d deg = Eigen::Vector2d::Zero();
        deg[(test.moving == 'B' ? b : c) - 3] = a;
        s.rows.push_back(row_at(m, t, deg, o.point_mm, tl, o.rounding));
        t += o.dt_s;
      }
      t += o.gap_s - o.dt_s;
      s.file = o.tool_lengths_mm.size() > 1 ? fmt::format("{}_L{}", test.name, fmt_num(tl)) : test.name;
      out.push_back({s.file, s});
    }
  return out;
}

}  // namespace ncpost::comp
