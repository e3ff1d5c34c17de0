// SPDX-License-Identifier: Apache-2.0
#include "ncpost/kinematics/inverse.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "ncpost/kinematics/forward.hpp"

namespace ncpost {
namespace {

/// Unit vectors v with v·a_dir = a and v·b_dir = b (a_dir, b_dir unit, not parallel).
SmallList<Vec3d, 2> sphere_plane_plane(const Vec3d& a_dir, double a, const Vec3d& b_dir, double b, double tolerance) {
  const double c = a_dir.dot(b_dir);
  const double det = 1.0 - c * c;
  assert(det > 1e-12);
  const double alpha = (a - c * b) / det;
  const double beta = (b - c * a) / det;
  const Vec3d base = alpha * a_dir + beta * b_dir;
  const Vec3d normal = a_dir.cross(b_dir);
  const double rest = 1.0 - base.squaredNorm();
  SmallList<Vec3d, 2> out;
  if (rest < -tolerance) return out;
  const double gamma = std::sqrt(std::max(0.0, rest) / normal.squaredNorm());
  if (gamma == 0.0) {
    out.push_back(base.normalized());
    return out;
  }
  out.push_back((base + gamma * normal).normalized());
  out.push_back((base - gamma * normal).normalized());
  return out;
}

double wrap_pi(double a) {
  if (a > -kPi && a <= kPi) return a;  // (what remainder() returns for these: atan2's results are)
  a = std::remainder(a, 2.0 * kPi);
  return a <= -kPi ? a + 2.0 * kPi : a;
}

/// The two rotary axes in the order of the chain, and how their rotations relate u and e_z.
struct RotaryLayout {
  int outer = 0;  ///< rotary index (0/1) nearer the bed in the composition R1(q1)·R2(q2)
  int inner = 1;
  enum Kind { table_table, head_head, head_table } kind = table_table;
};

RotaryLayout layout_of(const Machine& m) {
  RotaryLayout l;
  const int r0 = 3, r1 = 4;
  auto position_in = [](const std::vector<int>& side, int idx) {
    auto it = std::find(side.begin(), side.end(), idx);
    return it == side.end() ? -1 : static_cast<int>(it - side.begin());
  };
  const bool r0_tool = m.axes[r0].side == Side::tool;
  const bool r1_tool = m.axes[r1].side == Side::tool;
  if (r0_tool == r1_tool) {
    l.kind = r0_tool ? RotaryLayout::head_head : RotaryLayout::table_table;
    const auto& side = r0_tool ? m.tool_side : m.workpiece_side;
    const bool zero_first = position_in(side, r0) < position_in(side, r1);
    l.outer = zero_first ? 0 : 1;
    l.inner = zero_first ? 1 : 0;
  } else {
    l.kind = RotaryLayout::head_table;
    l.outer = r0_tool ? 0 : 1;  // the head axis
    l.inner = r0_tool ? 1 : 0;  // the table axis
  }
  return l;
}

/// The vectors the outer (d1) and inner (d2) rotations relate to the tool axis v between them:
/// v·d1 = plane1·d1 and v·d2 = plane2·d2 (see the header).
struct LayoutPlanes {
  Vec3d plane1, plane2;
};
LayoutPlanes planes_of(const RotaryLayout& l, const Vec3d& u) {
  const Vec3d ez = Vec3d::UnitZ();
  switch (l.kind) {
    case RotaryLayout::head_head:  // R1 R2 e_z = u ; v = R2 e_z = R1^T u
      return {u, ez};
    case RotaryLayout::table_table:  // R1 R2 u = e_z ; v = R2 u = R1^T e_z
    case RotaryLayout::head_table:   // Rt e_z = Rw u ; v = Rt e_z = Rw u (outer = head, inner = table)
      break;
  }
  return {ez, u};
}

}  // namespace

std::optional<double> angle_about(const Vec3d& d, const Vec3d& from, const Vec3d& to, double tolerance) {
  const Vec3d f = from - from.dot(d) * d;
  const Vec3d t = to - to.dot(d) * d;
  if (f.norm() < tolerance || t.norm() < tolerance) return std::nullopt;
  return std::atan2(d.dot(f.cross(t)), f.dot(t));
}

namespace {

/// One rotary axis (direction d): its rotation keeps the component along d, so the tool axis u
/// is within reach when u·d = e_z·d; then one angle turns e_z onto u (a head) or u onto e_z (a
/// table). u along d (and so e_z along d): every angle fits, the axis is free.
SmallList<RotarySolution, 2> single_axis_solutions(const Axis& axis, const Vec3d& u, double tolerance) {
  const Vec3d ez = Vec3d::UnitZ();
  const Vec3d& d = axis.direction;
  SmallList<RotarySolution, 2> out;
  if (std::abs(u.dot(d) - ez.dot(d)) > std::sqrt(tolerance)) return out;
  const double free_tol = 1e-9;
  const std::optional<double> q =
      axis.side == Side::tool ? angle_about(d, ez, u, free_tol) : angle_about(d, u, ez, free_tol);
  RotarySolution s;
  s.rotary_rad = RotaryAngles::Zero(1);
  if (q)
    s.rotary_rad[0] = wrap_pi(*q);
  else
    s.free_axis = 0;
  out.push_back(s);
  return out;
}

}  // namespace

SmallList<RotarySolution, 2> rotary_solutions(const Machine& m, const Vec3d& axis_W, double tolerance) {
  const Vec3d u = axis_W.normalized();
  const Vec3d ez = Vec3d::UnitZ();
  SmallList<RotarySolution, 2> out;
  if (m.rotary_count() == 0) {
    if ((u - ez).norm() <= std::sqrt(tolerance)) out.push_back(RotarySolution{});
    return out;
  }
  if (m.rotary_count() == 1) return single_axis_solutions(m.rotary(0), u, tolerance);
  const RotaryLayout l = layout_of(m);
  const Vec3d d1 = m.rotary(l.outer).direction;
  const Vec3d d2 = m.rotary(l.inner).direction;
  // Tool-axis direction v between the rotations, and the vectors it relates (see header).
  const LayoutPlanes p = planes_of(l, u);
  const auto vs = sphere_plane_plane(d2, p.plane2.dot(d2), d1, p.plane1.dot(d1), tolerance);
  const double free_tol = 1e-9;
  for (const Vec3d& v : vs) {
    RotarySolution s;
    s.rotary_rad = RotaryAngles::Zero(2);
    std::optional<double> q_inner, q_outer;
    switch (l.kind) {
      case RotaryLayout::table_table:
        q_inner = angle_about(d2, u, v, free_tol);
        q_outer = angle_about(d1, v, ez, free_tol);
        break;
      case RotaryLayout::head_head:
        q_inner = angle_about(d2, ez, v, free_tol);
        q_outer = angle_about(d1, v, u, free_tol);
        break;
      case RotaryLayout::head_table:
        q_outer = angle_about(d1, ez, v, free_tol);  // head: e_z -> v
        q_inner = angle_about(d2, u, v, free_tol);   // table: u -> v
        break;
    }
    if (!q_inner) s.free_axis = l.inner;
    if (!q_outer) s.free_axis = l.outer;
    s.rotary_rad[l.inner] = q_inner ? wrap_pi(*q_inner) : 0.0;
    s.rotary_rad[l.outer] = q_outer ? wrap_pi(*q_outer) : 0.0;
    out.push_back(s);
  }
  return out;
}

bool may_have_free_rotary(const Machine& m, const Vec3d& axis_W, double clear_rad) {
  // An angle is free where angle_about() gets a projection under 1e-9: one of its two vectors along
  // its axis. Per layout these are (plane1 or v along d1) and (plane2 or v along d2), and v
  // makes the same angle with d1 (d2) as plane1 (plane2) does, up to the reach tolerance's
  // rounding (< 1e-9 in the cosine): the default 1 mrad leaves a wide margin.
  const Vec3d& u = axis_W;  // (unnormalised: the test divides by the lengths)
  const Vec3d ez = Vec3d::UnitZ();
  auto along = [clear_rad](const Vec3d& a, const Vec3d& d) {
    return a.cross(d).squaredNorm() < clear_rad * clear_rad * a.squaredNorm() * d.squaredNorm();
  };
  if (m.rotary_count() == 0) return false;
  if (m.rotary_count() == 1) return along(ez, m.rotary(0).direction) || along(u, m.rotary(0).direction);
  const RotaryLayout l = layout_of(m);
  const LayoutPlanes p = planes_of(l, u);
  return along(p.plane1, m.rotary(l.outer).direction) || along(p.plane2, m.rotary(l.inner).direction);
}

Vec3d linear_for(const Machine& m, const RotaryAngles& rotary_rad, const Vec3d& tip_W, const Setup& setup) {
  const AxisPosition q(Vec3d::Zero(), rotary_rad);
  const ChainPose<double> pose = chain_pose<double>(m, q, setup.tool_length_mm, NominalErrors{});
  // With X = Y = Z = 0 the tool tip sits at bed_T_tool·0; the linear axes add (X, Y, Z) to it.
  const Vec3d target = pose.bed_T_table.apply(setup.workpiece_origin_mm + tip_W);
  return target - pose.bed_T_tool.t;
}

std::optional<AxisPosition> admissible_candidate(const Machine& m, const RotaryAngles& rotary_rad,
                                                 const RotaryAngles& previous_rad) {
  AxisPosition q = home_of(m);
  for (int k = 0; k < m.rotary_count(); ++k) {
    const Axis& axis = m.rotary(k);
    const double base = rotary_rad[k];
    // the 2π shift nearest the previous angle, then its neighbours when limits exclude it
    const double nearest = base + 2.0 * kPi * std::round((previous_rad[k] - base) / (2.0 * kPi));
    std::optional<double> best;
    for (int shift : {0, -1, 1, -2, 2}) {
      const double value = nearest + 2.0 * kPi * shift;
      if (axis.limits && !axis.limits->contains(value)) continue;
      if (!best || std::abs(value - previous_rad[k]) < std::abs(*best - previous_rad[k])) best = value;
    }
    if (!best) return std::nullopt;
    q.rotary_rad[k] = *best;
  }
  return q;
}

std::optional<double> unlimited_rotary_travel(const Machine& m, const Vec3d& axis_W, const RotaryAngles& previous_rad,
                                              const IkPolicy& policy) {
  std::optional<double> best;
  for (const RotarySolution& s : rotary_solutions(m, axis_W, policy.reach_tolerance)) {
    if (s.free_axis >= 0) return std::nullopt;
    double travel = 0.0;
    for (int k = 0; k < m.rotary_count(); ++k) {
      const double nearest =
          s.rotary_rad[k] + 2.0 * kPi * std::round((previous_rad[k] - s.rotary_rad[k]) / (2.0 * kPi));
      travel += std::abs(nearest - previous_rad[k]);
    }
    if (!best || travel < *best) best = travel;
  }
  return best;
}

namespace {

/// The admissible solutions among the rotary solutions `raw`, best first (only the best with
/// `best_only`: the linear axes of the others are not computed).
SmallList<AxisPosition, 2> admissible_of(const Machine& m, const SmallList<RotarySolution, 2>& raw, const ClPoint& cl,
                                         const Setup& setup, const AxisPosition& previous_given, bool best_only) {
  const RotaryAngles previous = rotary_of(previous_given, m.rotary_count());  // AxisPosition{}: home
  SmallList<std::pair<double, AxisPosition>, 2> ranked;
  for (RotarySolution s : raw) {
    if (s.free_axis >= 0) {
      // Singular: keep the free angle, solve the other one for it.
      s.rotary_rad[s.free_axis] = previous[s.free_axis];
    }
    auto candidate = admissible_candidate(m, s.rotary_rad, previous);
    if (!candidate) continue;
    const double cost = (candidate->rotary_rad - previous).cwiseAbs().sum();
    ranked.push_back({cost, *candidate});
  }
  // the cheaper first; equal costs (within 1e-12) keep the order of the rotary solutions
  if (ranked.size() == 2 && ranked[1].first < ranked[0].first - 1e-12) std::swap(ranked[0], ranked[1]);
  SmallList<AxisPosition, 2> out;
  for (auto& r : ranked) {
    AxisPosition& candidate = r.second;
    candidate.linear_mm = linear_for(m, candidate.rotary_rad, cl.tip_mm, setup);
    bool within = true;
    for (int i = 0; i < 3; ++i)
      if (m.axes[i].limits && !m.axes[i].limits->contains(candidate.linear_mm[i], 1e-6)) within = false;
    if (within) out.push_back(candidate);
    if (best_only && !out.empty()) break;
  }
  return out;
}

}  // namespace

SmallList<AxisPosition, 2> admissible_solutions(const Machine& m, const ClPoint& cl, const Setup& setup,
                                                const AxisPosition& previous, const IkPolicy& policy) {
  return admissible_of(m, rotary_solutions(m, cl.axis, policy.reach_tolerance), cl, setup, previous, false);
}

IkOutcome solve(const Machine& m, const ClPoint& cl, const Setup& setup, const AxisPosition& previous,
                const IkPolicy& policy) {
  IkOutcome outcome;
  if (!cl.axis.allFinite() || cl.axis.norm() < 1e-12 || !cl.tip_mm.allFinite()) {
    outcome.failure.message = "tool axis is zero or not finite";
    return outcome;
  }
  const auto raw = rotary_solutions(m, cl.axis, policy.reach_tolerance);
  if (raw.empty()) {
    outcome.failure.message = "tool orientation is out of the reach of the rotary axes";
    return outcome;
  }
  for (const auto& s : raw) outcome.singular = outcome.singular || s.free_axis >= 0;
  const auto all = admissible_of(m, raw, cl, setup, previous, true);
  if (all.empty()) {
    outcome.failure.message = "no solution within the axis limits";
    return outcome;
  }
  outcome.position = all.front();
  return outcome;
}

}  // namespace ncpost
