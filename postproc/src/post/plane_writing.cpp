// SPDX-License-Identifier: Apache-2.0
// Tilted work planes in the post (poster.hpp, PostOptions::tilted_plane, tilted_plane.hpp): a run of
// motions with one tool axis other than +Z is written in the plane's X Y Z, the rotary axes still.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "post/poster.hpp"

namespace ncpost::detail {

/// The program frame at home P = W + home_offset_ (W is parallel to M at home).
Vec3d Poster::home_offset() const {
  return solver_.with_rotary(ClPoint{Vec3d::Zero(), Vec3d::UnitZ()}, words_.home().rotary_rad, data_).linear_mm;
}

/// Before a CL motion: stay in the plane (same tool axis), leave it, or open one (a rapid, or the
/// first motion, to a tool axis other than +Z of W).
void Poster::update_plane(const cl::Motion& m, bool rapid) {
  if (!options_.tilted_plane || !writer_.dialect().tilted_plane || machine_.rotary_count() != 2 ||
      !words_.tilted_plane_capable)
    return;
  const Vec3d k = m.point.axis.normalized();
  if (plane_ && (k - plane_->axis_W).norm() <= 1e-9) return;
  close_plane();
  if (k.z() > 1.0 - 1e-12 || m.rotary_rad || !(rapid || !have_position_)) return;
  open_plane(m.point);
}

/// Opens a plane for the tool axis of `cl` at the solution nearest the previous commands.
void Poster::open_plane(const ClPoint& cl) {
  const TiltedPlaneWords& tw = *writer_.dialect().tilted_plane;
  const IkOutcome ik = solver_.solve_quiet(cl, previous_.q, data_, nullptr);
  if (!ik.ok()) return;  // the motion names the failure
  const RotaryAngles rotary = ik.position->rotary_rad;
  // the program frame's axes seen from the tilted part (W) at this solution
  const Vec3d o = solver_.with_rotary(ClPoint{Vec3d::Zero(), cl.axis}, rotary, data_).linear_mm;
  Mat3d P_from_W;
  for (int i = 0; i < 3; ++i)
    P_from_W.col(i) = solver_.with_rotary(ClPoint{Vec3d::Unit(i), cl.axis}, rotary, data_).linear_mm - o;
  const Mat3d R = plane_frame(cl.axis, P_from_W.row(0).transpose(), P_from_W.row(1).transpose());
  Plane p;
  p.words.convention = tw.angles;
  std::array<double, 3> angles = plane_angles(tw.angles, R, last_plane_angles_);
  for (double& a : angles) a = writer_.rounded(3, a);
  p.words.angles_deg = angles;
  p.words.P_R_F = plane_rotation(tw.angles, angles);
  const Vec3d origin_P = cl.tip_mm + home_offset_;
  for (int i = 0; i < 3; ++i) p.words.origin_P_mm[i] = writer_.rounded(i, origin_P[i]);
  p.axis_W = cl.axis.normalized();
  p.rotary_rad = rotary;
  const IkOutcome e = solver_.solve_quiet(ClPoint{cl.tip_mm, p.words.P_R_F.col(2)}, *ik.position, data_, nullptr);
  p.executed_rotary_rad = e.ok() ? e.position->rotary_rad : rotary;
  writer_.tilted_plane(plane_on_blocks(p, angles, rotary, plane_solution_direction(cl, rotary)), true);
  ++summary_.tilted_planes;
  last_plane_angles_ = angles;
  // where the tool stands in the plane once the rotary axes have turned (linear axes still)
  if (have_position_) {
    AxisPosition q = last_executed_;
    q.rotary_rad = p.executed_rotary_rad;
    const Vec3d at = p.words.to_plane(solver_.execute(q, data_).tip_mm + home_offset_);
    last_values_ = PerAxis<double>{writer_.rounded(0, at.x()), writer_.rounded(1, at.y()), writer_.rounded(2, at.z())};
  } else {
    last_values_.reset();
  }
  plane_ = p;
}

/// Which of the two solutions for the tool axis of `cl` the plane's words name (`{dir}`): +1 the
/// one with the larger first rotary angle.
int Poster::plane_solution_direction(const ClPoint& cl, const RotaryAngles& rotary) const {
  int dir = 1;
  for (const RotarySolution& s : rotary_solutions(machine_, cl.axis)) {
    double apart = 0.0;
    for (Eigen::Index k = 0; k < rotary.size(); ++k)
      apart += std::abs(std::remainder(s.rotary_rad[k] - rotary[k], 2.0 * kPi));
    const double d0 = rotary.size() > 0 ? std::remainder(s.rotary_rad[0] - rotary[0], 2.0 * kPi) : 0.0;
    if (apart > 1e-6 && d0 > 0.0) dir = -1;  // the other solution is larger
  }
  return dir;
}

/// The dialect's blocks that open the plane `p` (TiltedPlaneWords::on with its placeholders filled).
std::vector<std::string> Poster::plane_on_blocks(const Plane& p, const std::array<double, 3>& angles,
                                                 const RotaryAngles& rotary, int dir) const {
  std::string rotary_words;
  for (int k = 0; k < machine_.rotary_count(); ++k)
    rotary_words += (k ? " " : "") + std::string(1, writer_.letters()[static_cast<std::size_t>(3 + k)]) +
                    writer_.word_value(3 + k, rad_to_deg(rotary[k]));
  std::vector<std::string> blocks;
  for (std::string b : writer_.dialect().tilted_plane->on) {
    b = with_value(b, "{x}", writer_.word_value(0, p.words.origin_P_mm.x()));
    b = with_value(b, "{y}", writer_.word_value(1, p.words.origin_P_mm.y()));
    b = with_value(b, "{z}", writer_.word_value(2, p.words.origin_P_mm.z()));
    b = with_value(b, "{a}", writer_.word_value(3, angles[0]));
    b = with_value(b, "{b}", writer_.word_value(3, angles[1]));
    b = with_value(b, "{c}", writer_.word_value(3, angles[2]));
    b = with_value(b, "{dir}", dir > 0 ? "1" : "-1");
    b = with_value(b, "{rotary}", rotary_words);
    blocks.push_back(std::move(b));
  }
  return blocks;
}

void Poster::close_plane() {
  if (!plane_) return;
  writer_.tilted_plane(writer_.dialect().tilted_plane->off, false);
  // back in the program frame: the machine stands at the last executed commands
  if (have_position_) {
    PerAxis<double> v{};
    for (int i = 0; i < 3; ++i) v[static_cast<std::size_t>(i)] = writer_.rounded(i, last_executed_.linear_mm[i]);
    for (int k = 0; k < machine_.rotary_count(); ++k)
      v[static_cast<std::size_t>(3 + k)] = rad_to_deg(last_executed_.rotary_rad[k]);
    last_values_ = v;
  }
  plane_.reset();
}

/// The commands the control executes for the plane's words X Y Z (`in_plane`, rounded here):
/// the plane's transform into W, then the machine at the rotary angles the control turned to.
AxisPosition Poster::plane_executed(const Vec3d& in_plane) const {
  Vec3d r;
  for (int i = 0; i < 3; ++i) r[i] = writer_.rounded(i, in_plane[i]);
  return executed_in_plane(solver_, data_, plane_->words, home_offset_, plane_->executed_rotary_rad, r);
}

}  // namespace ncpost::detail
