// SPDX-License-Identifier: Apache-2.0
// PLANE: the plane's frame and its rotary angles (klartext_plane.hpp).
#include "read/klartext/klartext_plane.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <cmath>
#include <map>

#include "ncpost/kinematics/inverse.hpp"

namespace ncpost::klartext {
namespace {

Mat3d rot(const Vec3d& d, double angle_rad) { return Eigen::AngleAxisd(angle_rad, d).toRotationMatrix(); }

/// The angle words each kind of plane takes, in order.
const std::map<std::string, std::vector<std::string>>& angle_words() {
  static const std::map<std::string, std::vector<std::string>> k = {
      {"PLANE SPATIAL", {"SPA", "SPB", "SPC"}},
      {"PLANE EULER", {"EULPR", "EULNU", "EULROT"}},
      {"PLANE PROJECTED", {"PROPR", "PROMIN", "ROT", "PROROT"}},
      {"PLANE VECTOR", {"BX", "BY", "BZ", "NX", "NY", "NZ"}},
      {"PLANE AXIAL", {"A", "B", "C"}},
      {"PLANE POINTS", {"P1X", "P1Y", "P1Z", "P2X", "P2Y", "P2Z", "P3X", "P3Y", "P3Z"}},
      {"PLANE RESET", {}},
  };
  return k;
}

/// PLANE POINTS: X along P1 -> P2, Z = X x (P3 - P1) (P3 on the plane's +Y side); the datum stays.
std::variant<Mat3d, std::string> points_frame(const std::map<std::string, double>& v) {
  const auto point = [&](char n) {
    const auto get = [&](char axis) {
      const auto it = v.find(fmt::format("P{}{}", n, axis));
      return it == v.end() ? 0.0 : it->second;
    };
    return Vec3d(get('X'), get('Y'), get('Z'));
  };
  const Vec3d x = point('2') - point('1'), to3 = point('3') - point('1');
  const Vec3d z = x.cross(to3);
  if (x.norm() < 1e-9 || z.norm() < 1e-9 * std::max(1.0, x.norm() * to3.norm()))
    return std::string("PLANE POINTS: the three points lie on one line (or two coincide): they define no plane");
  Mat3d r;
  r.col(0) = x.normalized();
  r.col(2) = z.normalized();
  r.col(1) = r.col(2).cross(r.col(0));
  return r;
}

/// PLANE PROJECTED: the plane's traces in the ZX plane (along Ry(PROPR)·e_x) and in the YZ plane
/// (along Rx(PROMIN)·e_y); its X along the first trace, Z = first × second, then ROT (PROROT) about Z.
std::variant<Mat3d, std::string> projected_frame(double principal_rad, double minor_rad, double rotation_rad) {
  const Vec3d in_zx = rot(Vec3d::UnitY(), principal_rad) * Vec3d::UnitX();
  const Vec3d in_yz = rot(Vec3d::UnitX(), minor_rad) * Vec3d::UnitY();
  const Vec3d z = in_zx.cross(in_yz);
  if (z.norm() < 1e-9 || std::abs(std::cos(principal_rad)) < 1e-9 || std::abs(std::cos(minor_rad)) < 1e-9)
    return std::string("PLANE PROJECTED: a projection angle of 90 deg gives no plane (its trace is along Z)");
  Mat3d r;
  r.col(2) = z.normalized();
  r.col(0) = in_zx;
  r.col(1) = r.col(2).cross(r.col(0));
  return Mat3d(rot(r.col(2), rotation_rad) * r);
}

std::variant<Mat3d, std::string> frame_of(const std::string& kind, const std::map<std::string, double>& v) {
  const auto get = [&](const char* n) { return v.count(n) ? v.at(n) : 0.0; };
  const auto deg = [&](const char* n) { return deg_to_rad(get(n)); };
  if (kind == "PLANE SPATIAL")
    return Mat3d(rot(Vec3d::UnitZ(), deg("SPC")) * rot(Vec3d::UnitY(), deg("SPB")) * rot(Vec3d::UnitX(), deg("SPA")));
  if (kind == "PLANE EULER")
    return Mat3d(rot(Vec3d::UnitZ(), deg("EULPR")) * rot(Vec3d::UnitX(), deg("EULNU")) *
                 rot(Vec3d::UnitZ(), deg("EULROT")));
  if (kind == "PLANE POINTS") return points_frame(v);
  if (kind == "PLANE PROJECTED") {
    // the sign of the projection angles is the manual's figure, not confirmed on a control: a
    // mirrored plane would be a wrong program, so only the rotation alone is read
    if (get("PROPR") != 0.0 || get("PROMIN") != 0.0)
      return std::string(
          "PLANE PROJECTED with a projection angle (PROPR, PROMIN) is not read: the sign convention of those "
          "angles is not confirmed against a control; have the CAM system write PLANE SPATIAL or PLANE VECTOR");
    if (v.count("ROT") && v.count("PROROT"))
      return std::string("PLANE PROJECTED with both ROT and PROROT (the rotation about the tilted tool axis)");
    return projected_frame(deg("PROPR"), deg("PROMIN"), deg(v.count("ROT") ? "ROT" : "PROROT"));
  }
  if (kind == "PLANE VECTOR") {
    const Vec3d n(get("NX"), get("NY"), get("NZ"));
    const Vec3d base(get("BX"), get("BY"), get("BZ"));
    if (n.norm() < 1e-9) return std::string("PLANE VECTOR: the normal vector NX NY NZ is zero");
    const Vec3d z = n.normalized();
    const Vec3d x_part = base - base.dot(z) * z;
    if (x_part.norm() < 1e-6 * std::max(1.0, base.norm()))
      return std::string("PLANE VECTOR: the base vector BX BY BZ is zero or along the normal NX NY NZ");
    Mat3d r;
    r.col(0) = x_part.normalized();
    r.col(2) = z;
    r.col(1) = z.cross(r.col(0));
    return r;
  }
  return Mat3d(Mat3d::Identity());
}

/// SEQ+, TABLE ROT, COORD ROT, MB MAX, FMAX, F.., DIST.., STAY, MOVE, TURN: false when `w` is none of them.
bool motion_word(const Block& b, std::size_t& i, PlaneRequest& r, std::string& error) {
  const Word& w = b.words[i];
  const auto next_is = [&](const char* n) { return i + 1 < b.words.size() && b.words[i + 1].name == n; };
  if (w.name == "STAY")
    r.motion = PlaneRequest::Motion::stay;
  else if (w.name == "MOVE")
    r.motion = PlaneRequest::Motion::move;
  else if (w.name == "TURN")
    r.motion = PlaneRequest::Motion::turn;
  else if (w.name == "SEQ" && w.sign && !w.value)
    r.seq = w.sign == '+' ? 1 : -1;
  else if ((w.name == "TABLE" || w.name == "COORD") && next_is("ROT"))
    r.table_rot = w.name == "TABLE", ++i;
  else if (w.name == "FMAX")
    r.rapid = true;
  else if (w.name == "F" && w.value && *w.value > 0.0)
    r.feed = w.value;
  else if (w.name == "MB")
    r.retract = true, i += next_is("MAX") ? 1 : 0;
  else if (w.name == "DIST" || w.name == "ABST") {
    error = fmt::format(
        "{} MOVE {}: a swivel about a point at a distance from the tool tip is not read; program STAY "
        "and position the rotary axes with L (L A+Q120 B+Q121 C+Q122)",
        b.statement, w.name);
  } else {
    return false;
  }
  return true;
}

/// Index of the master axis (klartext_plane.hpp) among the rotary axes, or -1.
int master_rotary(const Machine& m) {
  int master = -1;
  for (int i : m.tool_side)
    if (m.axes[static_cast<std::size_t>(i)].is_rotary()) master = i - 3;
  if (master >= 0) return master;
  for (int i : m.workpiece_side)
    if (m.axes[static_cast<std::size_t>(i)].is_rotary()) return i - 3;
  return -1;
}

double travel(const RotaryAngles& a, const RotaryAngles& b) { return (a - b).cwiseAbs().sum(); }

/// TABLE ROT with the tool axis along the free axis: the free axis's angle that turns the tool
/// frame onto the plane's X axis (the table takes the plane's rotation, no coordinate rotation left).
double frame_angle(const Machine& m, const Mat3d& W_R_plane, RotaryAngles a, int free_axis) {
  a[free_axis] = 0.0;
  const Mat3d f0 = tool_frame_W(m, a);
  const Vec3d u = W_R_plane.col(2);
  const double phi = std::atan2(u.dot(f0.col(0).cross(W_R_plane.col(0))), f0.col(0).dot(W_R_plane.col(0)));
  for (const double theta : {phi, -phi}) {
    a[free_axis] = theta;
    if ((tool_frame_W(m, a).col(0) - W_R_plane.col(0)).norm() < 1e-9) return theta;
  }
  return phi;  // (not reached for a free axis along the tool axis)
}

}  // namespace

std::variant<PlaneRequest, std::string> plane_request(const Block& b, const Machine& m) {
  const auto kind = angle_words().find(b.statement);
  if (kind == angle_words().end())
    return fmt::format(
        "{} is not read (PLANE SPATIAL, PROJECTED, EULER, VECTOR, POINTS, AXIAL and RESET are); have the CAM system "
        "write PLANE SPATIAL",
        b.statement);
  PlaneRequest r;
  r.reset = b.statement == "PLANE RESET";
  std::map<std::string, double> values;
  bool motion = false;
  for (std::size_t i = 0; i < b.words.size(); ++i) {
    const Word& w = b.words[i];
    const auto& names = kind->second;
    if (std::find(names.begin(), names.end(), w.name) != names.end() && w.value) {
      if (b.statement == "PLANE AXIAL" && m.index_of(w.name[0]) < 3)
        return fmt::format("{} {}: the machine {} has no {} axis", b.statement, w.name, m.name, w.name);
      values[w.name] = *w.value;
      continue;
    }
    std::string error;
    const bool known = motion_word(b, i, r, error);
    if (!error.empty()) return error;
    if (!known) return fmt::format("'{}' in {} is not read", w.name, b.statement);
    motion = motion || w.name == "STAY" || w.name == "MOVE" || w.name == "TURN";
  }
  if (!motion) return fmt::format("{} without STAY, MOVE or TURN (how the rotary axes move)", b.statement);
  if (b.statement == "PLANE AXIAL") {
    RotaryAngles a = RotaryAngles::Zero(m.rotary_count());
    for (int k = 0; k < m.rotary_count(); ++k)
      if (const auto it = values.find(std::string(1, m.rotary(k).letter)); it != values.end())
        a[k] = deg_to_rad(it->second);
    r.axial_rad = a;
    r.W_R_plane = tool_frame_W(m, a);
    return r;
  }
  auto frame = frame_of(b.statement, values);
  if (const std::string* why = std::get_if<std::string>(&frame)) return *why;
  r.W_R_plane = std::get<Mat3d>(frame);
  return r;
}

Mat3d tool_frame_W(const Machine& m, const RotaryAngles& rotary_rad) {
  const auto side = [&](const std::vector<int>& indices) {
    Mat3d r = Mat3d::Identity();
    for (int i : indices) {
      const Axis& a = m.axes[static_cast<std::size_t>(i)];
      if (a.is_rotary()) r = r * rot(a.direction, rotary_rad[i - 3]);
    }
    return r;
  };
  return side(m.workpiece_side).transpose() * side(m.tool_side);
}

std::variant<RotaryAngles, std::string> plane_rotary(const Machine& m, const PlaneRequest& r,
                                                     const RotaryAngles& current_rad) {
  if (r.axial_rad) {
    if (const auto a = admissible_candidate(m, *r.axial_rad, *r.axial_rad)) return a->rotary_rad;
    return fmt::format("PLANE AXIAL: the angles are beyond the rotary travel of machine {}", m.name);
  }
  const Vec3d axis_W = r.W_R_plane.col(2);
  const auto solutions = rotary_solutions(m, axis_W, 1e-9);
  if (solutions.empty())
    return fmt::format("the plane's tool axis ({:.4f}, {:.4f}, {:.4f}) is out of reach of machine {}", axis_W.x(),
                       axis_W.y(), axis_W.z(), m.name);
  const int master = master_rotary(m);
  std::optional<RotaryAngles> best;
  bool beyond_limits = false;
  for (const RotarySolution& s : solutions) {
    RotaryAngles a = s.rotary_rad;
    if (s.free_axis >= 0)
      a[s.free_axis] = r.table_rot ? frame_angle(m, r.W_R_plane, a, s.free_axis) : current_rad[s.free_axis];
    const auto admissible = admissible_candidate(m, a, current_rad);
    if (!admissible) {
      beyond_limits = true;
      continue;
    }
    const double master_rad = master >= 0 ? admissible->rotary_rad[master] : 0.0;
    if (r.seq != 0 && master_rad * r.seq < -1e-9) continue;
    if (!best || travel(admissible->rotary_rad, current_rad) < travel(*best, current_rad))
      best = admissible->rotary_rad;
  }
  if (!best)
    return fmt::format("no solution for the plane{} within the rotary travel of machine {}{}",
                       r.seq ? fmt::format(" with SEQ{}", r.seq > 0 ? '+' : '-') : "", m.name,
                       beyond_limits ? " (a solution lies beyond the limits)" : "");
  return *best;
}

}  // namespace ncpost::klartext
