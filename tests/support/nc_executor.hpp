// SPDX-License-Identifier: Apache-2.0
#pragma once
// An executor of written NC programs for the tests, independent of the product: its own reading
// of the machine file (the few keys it needs, read line by line), its own forward kinematics (docs/conventions.md,
// "Axes and chains", "Nominal closure") and its own word reader of ISO G-code as the fanuc, haas and linuxcnc dialects
// write it. A posting test reads the *written* program with it and checks the tool tip against what the CL data meant,
// never through the product's --verify.
//
// Supported words: G0 G1 G2 G3 (G17 arcs by I J, K for helices not needed), G90 G91, G93 G94,
// G43.4 / G234 / M428 (tool tip control on: X Y Z are the tip in W) and G49 / M429 (off), G81/G83 (G98/G99
// return, as straight moves), G84/G74 (the same, fed back out to the R plane), G80, N, F, comments in ( ),
// T M S H words (ignored); G10 (an offset setting: no motion, its words ignored).
#include <Eigen/Dense>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace ncpost::test {

using V3 = Eigen::Vector3d;
using M3 = Eigen::Matrix3d;

/// One axis of a machine file.
struct ExecAxis {
  char letter = 'X';
  bool rotary = false;
  V3 direction = V3::UnitZ();
  V3 pivot = V3::Zero();
  bool workpiece_side = false;
  std::optional<double> limit_max;              ///< the top of the travel (mm, deg)
  std::optional<double> reference, reference2;  ///< G28's and G30's point in M (mm, deg)
  std::vector<double> fixed_point;              ///< Sinumerik G75 FP=1, 2, ... in M (mm, deg)
  std::optional<double> swivel_retract;         ///< where Sinumerik's CYCLE800 _FR retracts the axis (mm in M)
};

/// A machine file read by the test: the chain and its axes (rotary angles in deg in the program).
struct ExecMachine {
  std::string chain;
  std::vector<ExecAxis> tool_side;       ///< rotary axes from the bed outward
  std::vector<ExecAxis> workpiece_side;  ///< rotary axes from the bed outward
  std::string rotary_letters;            ///< in the order the chain names them
  std::map<char, ExecAxis> all_axes;     ///< every [axes.L] of the file, by letter

  static ExecMachine load(const std::string& path) {
    // [machine] chain = "..." and [axes.L] type = "rotary", direction = [..], pivot = [..]
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read " + path);
    std::map<char, ExecAxis> axes;
    std::string section;
    ExecMachine m;
    auto unquoted = [](const std::string& v) {
      const auto a = v.find('"'), b = v.rfind('"');
      return a == std::string::npos || b <= a ? v : v.substr(a + 1, b - a - 1);
    };
    auto vector_of = [](const std::string& v) {
      V3 out = V3::Zero();
      std::string inner = v.substr(v.find('[') + 1);
      inner = inner.substr(0, inner.find(']'));
      std::istringstream parts(inner);
      std::string part;
      for (int i = 0; i < 3 && std::getline(parts, part, ','); ++i) out[i] = std::stod(part);
      return out;
    };
    for (std::string line; std::getline(in, line);) {
      if (const auto hash = line.find('#'); hash != std::string::npos && line.find('"') > hash)
        line = line.substr(0, hash);
      const auto first = line.find_first_not_of(" \t\r");
      if (first == std::string::npos) continue;
      line = line.substr(first);
      if (line[0] == '[') {
        section = line.substr(1, line.find(']') - 1);
        continue;
      }
      const auto eq = line.find('=');
      if (eq == std::string::npos) continue;
      std::string key = line.substr(0, eq);
      key = key.substr(0, key.find_last_not_of(" \t") + 1);
      const std::string value = line.substr(eq + 1);
      if (section == "machine" && key == "chain") m.chain = unquoted(value);
      if (section.rfind("axes.", 0) == 0 && section.size() == 6) {
        ExecAxis& a = axes[section[5]];
        a.letter = section[5];
        if (key == "type") a.rotary = unquoted(value) == "rotary";
        if (key == "direction") a.direction = vector_of(value).normalized();
        if (key == "pivot") a.pivot = vector_of(value);
        if (key == "limits") a.limit_max = std::stod(value.substr(value.find(',') + 1));
        if (key == "reference") a.reference = std::stod(value);
        if (key == "reference2") a.reference2 = std::stod(value);
        if (key == "fixed_point") {
          std::istringstream list(value.substr(value.find('[') + 1, value.find(']') - value.find('[') - 1));
          for (std::string part; std::getline(list, part, ',');) a.fixed_point.push_back(std::stod(part));
        }
        if (key == "swivel_retract") a.swivel_retract = std::stod(value);
      }
    }
    std::istringstream words(m.chain);
    bool workpiece = true;
    std::vector<ExecAxis> wp;
    for (std::string tok; words >> tok;) {
      if (tok == "w" || tok == "t") continue;
      if (tok == "b") {
        workpiece = false;
        continue;
      }
      if (!axes.count(tok[0])) throw std::runtime_error("no [axes." + tok.substr(0, 1) + "] in " + path);
      ExecAxis a = axes.at(tok[0]);
      if (!a.rotary) continue;
      a.workpiece_side = workpiece;
      m.rotary_letters += a.letter;
      (workpiece ? wp : m.tool_side).push_back(a);
    }
    m.workpiece_side.assign(wp.rbegin(), wp.rend());  // listed from w to b: the bed outward is reversed
    m.all_axes = axes;
    return m;
  }
};

/// A rigid motion x -> R x + t.
struct Rt {
  M3 R = M3::Identity();
  V3 t = V3::Zero();
  Rt operator*(const Rt& o) const { return {R * o.R, R * o.t + t}; }
  V3 operator*(const V3& p) const { return R * p + t; }
  Rt inverse() const { return {R.transpose(), -(R.transpose() * t)}; }
};

/// Tool tip and tool axis in W.
struct ExecPose {
  V3 tip_W = V3::Zero();
  V3 axis_W = V3::UnitZ();
};

/// The job: where W is and how long the tool is.
struct ExecJob {
  V3 workpiece_origin_mm = V3::Zero();
  double tool_length_mm = 0.0;
};

/// Forward kinematics by the conventions: T_j(q) = Trans(P_j) Rot(d_j, q) Trans(-P_j), composed
/// from the bed outward on each side; head pivots + (0, 0, L); closure
/// (X, Y, Z) + T_t(q) 0 = T_w(q) (origin + p), R_t e_z = R_w u.
/// The workpiece side's and the tool side's transforms at the angles `rotary_deg`.
inline std::pair<Rt, Rt> chain_transforms(const ExecMachine& m, const ExecJob& job,
                                          const std::map<char, double>& rotary_deg) {
  auto turn = [&](const ExecAxis& a, bool tool) {
    const double q = rotary_deg.count(a.letter) ? rotary_deg.at(a.letter) * M_PI / 180.0 : 0.0;
    const V3 p = a.pivot + (tool ? V3(0, 0, job.tool_length_mm) : V3::Zero());
    Rt r;
    r.R = Eigen::AngleAxisd(q, a.direction).toRotationMatrix();
    r.t = p - r.R * p;
    return r;
  };
  Rt Tw, Tt;
  for (const ExecAxis& a : m.workpiece_side) Tw = Tw * turn(a, false);
  for (const ExecAxis& a : m.tool_side) Tt = Tt * turn(a, true);
  return {Tw, Tt};
}

inline ExecPose forward(const ExecMachine& m, const ExecJob& job, const V3& xyz_mm,
                        const std::map<char, double>& rotary_deg) {
  const auto [Tw, Tt] = chain_transforms(m, job, rotary_deg);
  ExecPose pose;
  pose.tip_W = Tw.inverse() * (xyz_mm + Tt * V3::Zero()) - job.workpiece_origin_mm;
  pose.axis_W = Tw.R.transpose() * Tt.R * V3::UnitZ();
  return pose;
}

/// The closure solved for the linear axes: where X Y Z stand (mm) with the tip at `tip_W` and the
/// rotary axes at `rotary_deg`: (X, Y, Z) = T_w(q) (origin + p) - T_t(q) 0.
inline V3 machine_xyz_for_tip(const ExecMachine& m, const ExecJob& job, const V3& tip_W,
                              const std::map<char, double>& rotary_deg) {
  const auto [Tw, Tt] = chain_transforms(m, job, rotary_deg);
  return Tw * (tip_W + job.workpiece_origin_mm) - Tt * V3::Zero();
}

/// One motion block as the control reads it.
struct ExecBlock {
  enum class Kind { rapid, linear, arc_cw, arc_ccw } kind = Kind::rapid;
  int line = 0;  ///< line of the program text (1-based)
  std::string text;
  std::map<char, double> from, to;  ///< X Y Z (mm) and rotary (deg) words in force before and after
  V3 centre_mm = V3::Zero();        ///< arcs: the centre (program frame)
  bool inverse_time = false;        ///< G93: `feed` is 1/minutes
  double feed = 0.0;
  bool rtcp = false;       ///< X Y Z are the tip in W
  bool from_known = true;  ///< every axis word was given before (else the start is where the machine happened to be)
};

/// Reads the blocks of `text` (ISO G-code). Throws on a word it does not know.
inline std::vector<ExecBlock> read_blocks(const std::string& text, const std::string& rotary_letters) {
  std::vector<ExecBlock> out;
  std::map<char, double> pos{{'X', 0}, {'Y', 0}, {'Z', 0}};
  for (char c : rotary_letters) pos[c] = 0.0;
  std::map<char, bool> known;  // axes given so far
  int motion = 0;              // 0 1 2 3
  bool absolute = true, inverse = false, rtcp = false, cycle = false, return_initial = true, tap = false;
  double feed = 0.0, cycle_r = 0.0, cycle_z = 0.0;
  std::istringstream lines(text);
  int line_no = 0;
  for (std::string raw; std::getline(lines, raw);) {
    ++line_no;
    std::string s;
    int depth = 0;
    for (char c : raw) {  // comments out
      if (c == '(')
        ++depth;
      else if (c == ')')
        --depth;
      else if (depth == 0 && c != ' ' && c != '\r')
        s += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    }
    if (s.empty() || s[0] == '%' || s[0] == 'O') continue;
    std::map<char, double> given;
    std::vector<double> gs;
    double i_word = 0, j_word = 0;
    bool has_feed = false;
    const double r_before = cycle_r;  // a G10's R is no cycle's R plane
    for (std::size_t k = 0; k < s.size();) {
      const char letter = s[k++];
      const std::size_t start = k;  // [+-]digits[.digits] (no exponent, no hex: "G0X27" is G0 X27)
      if (k < s.size() && (s[k] == '+' || s[k] == '-')) ++k;
      while (k < s.size() && (std::isdigit(static_cast<unsigned char>(s[k])) || s[k] == '.')) ++k;
      if (k == start) throw std::runtime_error("line " + std::to_string(line_no) + ": no number after " + letter);
      const double v = std::stod(s.substr(start, k - start));
      if (letter == 'G')
        gs.push_back(v);
      else if (letter == 'F')
        feed = v, has_feed = true;
      else if (letter == 'I')
        i_word = v;
      else if (letter == 'J')
        j_word = v;
      else if (letter == 'R')
        cycle_r = v;
      else if (letter == 'X' || letter == 'Y' || letter == 'Z' || rotary_letters.find(letter) != std::string::npos)
        given[letter] = v;
      else if (letter == 'M' && (std::lround(v) == 428 || std::lround(v) == 429))
        rtcp = std::lround(v) == 428;  // LinuxCNC's tool-tip kinematics on / off
      else if (std::string("NTMSHDPQL").find(letter) == std::string::npos)
        throw std::runtime_error("line " + std::to_string(line_no) + ": unknown word " + std::string(1, letter));
    }
    (void)has_feed;
    bool starts_cycle = false, reference = false;
    for (double g : gs) {
      const int c = static_cast<int>(std::lround(g * 10));
      if (c == 0 || c == 10 || c == 20 || c == 30)
        motion = c / 10, cycle = false;
      else if (c == 900)
        absolute = true;
      else if (c == 910)
        absolute = false;
      else if (c == 930)
        inverse = true;
      else if (c == 940)
        inverse = false;
      else if (c == 434 || c == 2340)
        rtcp = true;
      else if (c == 490)
        rtcp = false;
      else if (c == 810 || c == 830 || c == 840 || c == 740)
        cycle = true, starts_cycle = true, tap = c == 840 || c == 740;
      else if (c == 800)
        cycle = false;
      else if (c == 980)
        return_initial = true;
      else if (c == 990)
        return_initial = false;
      else if (c == 280 || c == 300 || c == 530)
        reference = true;
      else if (c == 100)
        reference = true, cycle_r = r_before;
    }
    // a reference return or a machine-coordinate move (the program's end): outside the tests' frame
    if (given.empty() || reference) continue;
    std::map<char, double> target = pos;
    for (const auto& [l, v] : given) target[l] = absolute ? v : pos[l] + v;
    const std::map<char, bool> known_before = known;
    for (const auto& [l, v] : given) known[l] = true;
    auto push = [&](ExecBlock::Kind kind, const std::map<char, double>& from, const std::map<char, double>& to) {
      ExecBlock b;
      b.kind = kind;
      b.line = line_no;
      b.text = raw;
      b.from = from;
      b.to = to;
      b.inverse_time = inverse;
      b.feed = feed;
      b.rtcp = rtcp;
      b.from_known = known_before.size() == pos.size();
      out.push_back(b);
    };
    if (cycle) {  // X Y of the hole, Z its bottom, R the R plane (absolute)
      if (starts_cycle || given.count('Z')) cycle_z = target['Z'];
      const double initial_z = pos['Z'];
      std::map<char, double> over = pos, r_plane, bottom;
      over['X'] = target['X'], over['Y'] = target['Y'];
      r_plane = over, r_plane['Z'] = cycle_r;
      bottom = r_plane, bottom['Z'] = cycle_z;
      push(ExecBlock::Kind::rapid, pos, over);
      push(ExecBlock::Kind::rapid, over, r_plane);
      push(ExecBlock::Kind::linear, r_plane, bottom);
      if (tap) push(ExecBlock::Kind::linear, bottom, r_plane);  // the thread followed out
      std::map<char, double> back = tap ? r_plane : bottom;
      back['Z'] = return_initial ? initial_z : cycle_r;
      push(ExecBlock::Kind::rapid, tap ? r_plane : bottom, back);
      pos = back;
      continue;
    }
    const auto kind = motion == 0   ? ExecBlock::Kind::rapid
                      : motion == 1 ? ExecBlock::Kind::linear
                      : motion == 2 ? ExecBlock::Kind::arc_cw
                                    : ExecBlock::Kind::arc_ccw;
    push(kind, pos, target);
    if (motion >= 2) out.back().centre_mm = V3(pos['X'] + i_word, pos['Y'] + j_word, pos['Z']);
    pos = target;
  }
  return out;
}

/// The program executor: machine, job and the blocks of a written program.
struct Executor {
  ExecMachine machine;
  ExecJob job;
  std::vector<ExecBlock> blocks;

  Executor(const std::string& machine_file, const ExecJob& j, const std::string& program_text)
      : machine(ExecMachine::load(machine_file)), job(j), blocks(read_blocks(program_text, machine.rotary_letters)) {}

  /// Where the tool is at the words `w` (RTCP: X Y Z are the tip in W).
  ExecPose pose(const std::map<char, double>& w, bool rtcp) const {
    const V3 xyz(w.at('X'), w.at('Y'), w.at('Z'));
    std::map<char, double> rot;
    for (char c : machine.rotary_letters) rot[c] = w.count(c) ? w.at(c) : 0.0;
    ExecPose p = forward(machine, job, rtcp ? V3::Zero() : xyz, rot);
    if (rtcp) {  // the control puts the tip on X Y Z of W at these angles
      p.tip_W = xyz;
    }
    return p;
  }

  /// The pose at parameter t in [0, 1] of block b: every axis interpolated linearly (rapids and
  /// linear moves; under RTCP the tip moves straight in W); arcs about their centre in the plane.
  ExecPose at(const ExecBlock& b, double t) const {
    std::map<char, double> w = b.from;
    if (b.kind == ExecBlock::Kind::arc_cw || b.kind == ExecBlock::Kind::arc_ccw) {
      const V3 s(b.from.at('X'), b.from.at('Y'), b.from.at('Z')), e(b.to.at('X'), b.to.at('Y'), b.to.at('Z'));
      const double a0 = std::atan2(s.y() - b.centre_mm.y(), s.x() - b.centre_mm.x());
      double a1 = std::atan2(e.y() - b.centre_mm.y(), e.x() - b.centre_mm.x());
      const bool ccw = b.kind == ExecBlock::Kind::arc_ccw;
      double sweep = a1 - a0;
      if (ccw && sweep <= 1e-12) sweep += 2 * M_PI;
      if (!ccw && sweep >= -1e-12) sweep -= 2 * M_PI;
      const double r = std::hypot(s.x() - b.centre_mm.x(), s.y() - b.centre_mm.y());
      w['X'] = b.centre_mm.x() + r * std::cos(a0 + t * sweep);
      w['Y'] = b.centre_mm.y() + r * std::sin(a0 + t * sweep);
      w['Z'] = s.z() + t * (e.z() - s.z());
      return pose(w, b.rtcp);
    }
    for (auto& [l, v] : w) v = v + t * (b.to.at(l) - v);
    return pose(w, b.rtcp);
  }

  /// The length (mm) of the tip's path in W over block b, from `samples` pieces.
  double tip_path_mm(const ExecBlock& b, int samples = 2000) const {
    double length = 0.0;
    V3 last = at(b, 0.0).tip_W;
    for (int i = 1; i <= samples; ++i) {
      const V3 p = at(b, static_cast<double>(i) / samples).tip_W;
      length += (p - last).norm();
      last = p;
    }
    return length;
  }
};

/// Distance of p from the line through `a` along unit `u`, and p's coordinate along it.
inline std::pair<double, double> from_line(const V3& p, const V3& a, const V3& u) {
  const double s = (p - a).dot(u);
  return {(p - a - s * u).norm(), s};
}

/// Distance of p from the segment a-b.
inline double from_segment(const V3& p, const V3& a, const V3& b) {
  const V3 d = b - a;
  const double len2 = d.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
  return (p - a - t * d).norm();
}

}  // namespace ncpost::test
