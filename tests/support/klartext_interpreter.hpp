// SPDX-License-Identifier: Apache-2.0
#pragma once
// A small interpreter of Heidenhain Klartext for the tests, independent of the product's reader:
// it runs only what the tests' programs use and reports where the tool tip is (in W) at the end of
// each L block, by the TNC's rules as the tests read them from the TNC 640 manual:
//   - CC X Y (the pole) and LP PR PA / IPR IPA (a line to polar coordinates about it);
//   - RND R / CHF s between two L blocks in X Y (the rounding arc tangent to both, the chamfer s
//     from the corner along each; the corner not reached);
//   - L X Y Z A B C (n, +n, -n, +Qn, -Qn; IX IY IZ incremental), FMAX / F / R0 / M words (M128 [F..] /
//     M129 switch tool-tip programming on and off, the F of M128 the limit of the control's compensating
//     moves; others ignored, also in blocks of their own); TOOL CALL, TOOL DEF, BLK FORM and END PGM
//     hold no position; a decimal comma between digits (X241,781) is the decimal point;
//   - M91 / M92 in an L block (outside M128 and planes): its absolute X Y Z are machine axes counted
//     from the machine file's `reference` (M91, the machine datum) or `reference2` (M92, the
//     additional machine datum), as ExecMachine reads them;
//   - CYCL DEF 7.1 X / 7.2 Y / 7.3 Z (the datum shift, added to later absolute X Y Z and CC words);
//   - C X Y DR±, CR X Y R± DR±, CP IPA± IZ± DR± (klartext_arc_geometry.hpp; the path every 1/4°);
//   - Qn = a [op b] (op + - * /, operands numbers or Q), FN 0: Qn = v; Qn = MAX (a cycle's feed as FMAX);
//   - LBL n, LBL 0, CALL LBL n (subprogram: runs to LBL 0, returns), CALL LBL n REP m (the lines
//     from LBL n to the call run m more times);
//   - PLANE SPATIAL SPA SPB SPC STAY [SEQ+|SEQ-]: X Y Z are then the tip in the plane,
//     W_R_plane = Rz(SPC) Ry(SPB) Rx(SPA), and Q120 .. Q122 are set from `angles` (the test's own
//     computation of the control's angles); PLANE POINTS P1X.. P3Z.. STAY [SEQ±] (X along P1 -> P2,
//     Y toward P3, the datum kept); PLANE PROJECTED PROPR PROMIN PROROT STAY [SEQ±] (the plane
//     z = p x + q y whose trace in ZX falls by PROPR along +X, whose trace in YZ rises by PROMIN
//     along +Y: p = -tan PROPR, q = tan PROMIN; X along its ZX trace (1, 0, p), then turned by
//     ROT (PROROT) about the plane's normal); PLANE RESET STAY;
//   - without M128 and PLANE, X Y Z are machine axes (the tip by nc_executor.hpp's forward
//     kinematics); a block with rotary words alone keeps the machine's linear axes (the tip moves);
//   - CYCL DEF 200 / 201 / 203 / 206 / 207 / 208 / 209 / 240 / 241 with their Q parameters on the `~` lines (set as Q
//     parameters, as the TNC does), called by CYCL CALL or M99 on an L block (M89: on it and on every
//     later L block until M99) (klartext_cycles.hpp:
//     an end after each of the cycle's moves); M3 / M4 for the direction of 208.
// `path()` is the tip's path: every block end and, along arcs, points every degree (C, CR, CP: every
// quarter degree), each flagged whether the move into it cuts (at a feed) or not (FMAX). Each end says
// whether X, Y and Z had all been programmed by then (before that the machine stood where the
// program does not say), and the rotary axes' angles there.
// Anything else throws, so a test cannot pass by skipping a statement.
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "klartext_arc_geometry.hpp"
#include "klartext_cycles.hpp"
#include "nc_executor.hpp"

namespace ncpost::test {

/// The tool tip and axis (W) after each L block of the input, with its line.
struct KlartextEnd {
  int line = 0;
  V3 tip_W = V3::Zero();
  V3 axis_W = V3::UnitZ();
  std::map<char, double> rotary_deg;  ///< the machine's rotary axes there (deg)
  bool xyz_known = true;              ///< X, Y and Z have all been programmed by then
  std::size_t path_index = 0;         ///< its point in path()
};

/// A point of the tip's path and whether the move into it cuts.
struct KlartextPathPoint {
  V3 tip_W = V3::Zero();
  bool cut = false;
};

/// The control's rotary angles (deg, by letter) for a plane and its SEQ (+1, -1, 0).
using PlaneAnglesFn = std::function<std::map<char, double>(const M3& W_R_plane, int seq)>;

class KlartextInterpreter {
 public:
  KlartextInterpreter(const ExecMachine& m, const ExecJob& job, PlaneAnglesFn angles)
      : m_(m), job_(job), angles_(std::move(angles)) {
    for (char c : m_.rotary_letters) rot_[c] = 0.0;
  }

  /// The tool's diameter for CYCL DEF 208.
  void set_tool_diameter(double mm) { tool_diameter_mm_ = mm; }
  const std::vector<KlartextPathPoint>& path() const { return path_; }

  std::vector<KlartextEnd> run(const std::string& text) {
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) lines_.push_back(strip(l));
    for (std::size_t i = 0; i < lines_.size(); ++i)
      if (lines_[i].rfind("LBL ", 0) == 0) labels_[lines_[i].substr(4)] = i;
    std::vector<std::pair<std::size_t, std::size_t>> returns;  // (return index, -)
    std::map<std::size_t, int> repeats;
    for (std::size_t i = 0; i < lines_.size();) {
      const std::string& s = lines_[i];
      if (s.rfind("CALL LBL ", 0) == 0) {
        std::istringstream w(s.substr(9));
        std::string label, rep;
        int count = 0;
        w >> label >> rep >> count;
        if (rep == "REP") {
          if (!repeats.count(i)) repeats[i] = count;
          if (repeats[i]-- > 0) {
            i = labels_.at(label) + 1;
            continue;
          }
          repeats.erase(i);
          ++i;
          continue;
        }
        returns.push_back({i + 1, 0});
        i = labels_.at(label) + 1;
        continue;
      }
      if (s == "LBL 0") {
        if (!returns.empty()) {
          i = returns.back().first;
          returns.pop_back();
          continue;
        }
        ++i;
        continue;
      }
      if (s == "M30" || s.rfind("END PGM", 0) == 0) break;
      statement(s, static_cast<int>(i + 1));
      ++i;
    }
    return ends_;
  }

 private:
  static std::string strip(std::string l) {
    if (const auto c = l.find(';'); c != std::string::npos) l = l.substr(0, c);
    while (!l.empty() && (l.back() == ' ' || l.back() == '\r')) l.pop_back();
    std::size_t p = 0;
    while (p < l.size() && std::isdigit(static_cast<unsigned char>(l[p]))) ++p;
    while (p < l.size() && l[p] == ' ') ++p;
    l = l.substr(p);
    for (std::size_t i = 1; i + 1 < l.size(); ++i)  // a decimal comma (X241,781): the decimal point
      if (l[i] == ',' && std::isdigit(static_cast<unsigned char>(l[i - 1])) &&
          std::isdigit(static_cast<unsigned char>(l[i + 1])))
        l[i] = '.';
    return l;
  }

  double value_of(const std::string& v) const {
    const double sign = v[0] == '-' ? -1.0 : 1.0;
    const std::string body = v[0] == '+' || v[0] == '-' ? v.substr(1) : v;
    if (body[0] == 'Q') return sign * q_.at(body);
    return sign * std::stod(body);
  }

  void statement(const std::string& s, int line) {
    static const std::regex assign(R"(^(?:FN 0: ?)?(Q\d+) ?= ?([-+]?Q?[\d.]+)(?: ([-+*/]) ([-+]?Q?[\d.]+))?$)");
    std::smatch m;
    if (s.empty() || s[0] == '*' || s.rfind("BEGIN PGM", 0) == 0 || s.rfind("TOOL CALL", 0) == 0 ||
        s.rfind("TOOL DEF", 0) == 0 || s.rfind("BLK FORM", 0) == 0 || s.rfind("LBL ", 0) == 0)
      return;
    static const std::regex as_rapid(R"(^(Q\d+) ?= ?F?MAX$)");  // Q208=MAX: the retraction at FMAX (its path the same)
    if (s[0] == 'Q' && std::regex_match(s, m, as_rapid)) {
      q_[m[1]] = std::numeric_limits<double>::infinity();
      return;
    }
    if ((s[0] == 'Q' || s[0] == 'F') && std::regex_match(s, m, assign)) {
      double v = value_of(m[2]);
      if (m[3].matched) {
        const double b = value_of(m[4]);
        const char op = m[3].str()[0];
        v = op == '+' ? v + b : op == '-' ? v - b : op == '*' ? v * b : v / b;
      }
      q_[m[1]] = v;
      return;
    }
    if (s.rfind("PLANE ", 0) == 0) return plane(s);
    if (s.rfind("CYCL DEF 7.", 0) == 0) return datum_shift(s);
    if (s.rfind("CYCL DEF ", 0) == 0) {
      cycle_ = std::stoi(s.substr(9));
      return;
    }
    if (s == "CYCL CALL") return call_cycle(line);
    spindle_words(s);
    if (s == "M128" || s == "M129" || s.rfind("M128 F", 0) == 0) return set_rtcp(s[3] == '8');  // (F: its limit)
    static const std::regex m_alone(R"(^M\d+( M\d+)*$)");
    if ((s[0] == 'M' && std::regex_match(s, m_alone)) || s.rfind("END PGM", 0) == 0)
      return;                                              // spindle, coolant, end: no position
    if (s.size() > 1 && s[0] == 'Q' && s.back() == '~') {  // a cycle's parameter line without a comment
      std::string t = s.substr(0, s.size() - 1);
      while (!t.empty() && t.back() == ' ') t.pop_back();
      return statement(t, line);
    }
    if (s.rfind("CC ", 0) == 0) return pole(s);
    if (s.rfind("RND R", 0) == 0 || s.rfind("CHF ", 0) == 0) {  // the length: the first number after the statement
      std::istringstream w(s.substr(s[0] == 'R' ? 5 : 4));
      std::string length;
      w >> length;
      corner_ = Corner{s[0] == 'R', value_of(length), line};
      return;
    }
    if (s.rfind("C ", 0) == 0 || s.rfind("CR ", 0) == 0 || s.rfind("CP ", 0) == 0) return arc(s, line);
    if (s.rfind("LP ", 0) == 0) return motion(polar_as_cartesian(s), line);
    if (s.rfind("L ", 0) == 0) return motion(s, line);
    throw std::runtime_error("the test interpreter does not read: " + s);
  }

  void plane(const std::string& s) {
    if (s == "PLANE RESET STAY") {
      keep_tip([&] { plane_.reset(); });
      return;
    }
    static const std::regex points(
        R"(^PLANE POINTS P1X([-+][\d.]+) P1Y([-+][\d.]+) P1Z([-+][\d.]+) P2X([-+][\d.]+) P2Y([-+][\d.]+) )"
        R"(P2Z([-+][\d.]+) P3X([-+][\d.]+) P3Y([-+][\d.]+) P3Z([-+][\d.]+) STAY(?: SEQ([-+]))?(?: COORD ROT)?$)");
    std::smatch p;
    if (std::regex_match(s, p, points)) {  // X from P1 to P2; Y the part of P1 -> P3 square to X; Z = X x Y
      const auto at = [&](int i) { return V3(std::stod(p[i]), std::stod(p[i + 1]), std::stod(p[i + 2])); };
      const V3 x = (at(4) - at(1)).normalized();
      const V3 y = ((at(7) - at(1)) - (at(7) - at(1)).dot(x) * x).normalized();
      M3 R;
      R << x, y, x.cross(y);
      const int seq = !p[10].matched ? 0 : p[10].str() == "+" ? 1 : -1;
      set_plane_parameters(R, seq);
      keep_tip([&] { plane_ = R; });
      return;
    }
    static const std::regex projected(
        R"(^PLANE PROJECTED PROPR([-+][\d.]+) PROMIN([-+][\d.]+) (?:PRO)?ROT([-+][\d.]+) STAY(?: SEQ([-+]))?$)");
    std::smatch pr;
    if (std::regex_match(s, pr, projected)) {
      const double p = -std::tan(std::stod(pr[1]) * M_PI / 180.0), q = std::tan(std::stod(pr[2]) * M_PI / 180.0);
      const V3 normal = V3(-p, -q, 1.0).normalized();
      const V3 x0 = V3(1.0, 0.0, p).normalized();
      const Eigen::AngleAxisd turn(std::stod(pr[3]) * M_PI / 180.0, normal);
      M3 R;
      R << turn * x0, turn * normal.cross(x0), normal;
      const int seq = !pr[4].matched ? 0 : pr[4].str() == "+" ? 1 : -1;
      set_plane_parameters(R, seq);
      keep_tip([&] { plane_ = R; });
      return;
    }
    static const std::regex spatial(
        R"(^PLANE SPATIAL SPA([-+]?[\d.]+) SPB([-+]?[\d.]+) SPC([-+]?[\d.]+) STAY(?: SEQ([-+]))?(?: COORD ROT)?$)");
    std::smatch m;
    if (!std::regex_match(s, m, spatial)) throw std::runtime_error("the test interpreter does not read: " + s);
    const auto rad = [](const std::string& t) { return std::stod(t) * M_PI / 180.0; };
    const M3 R = (Eigen::AngleAxisd(rad(m[3]), V3::UnitZ()) * Eigen::AngleAxisd(rad(m[2]), V3::UnitY()) *
                  Eigen::AngleAxisd(rad(m[1]), V3::UnitX()))
                     .toRotationMatrix();
    const int seq = !m[4].matched ? 0 : m[4].str() == "+" ? 1 : -1;
    set_plane_parameters(R, seq);
    keep_tip([&] { plane_ = R; });
  }

  /// Q120 .. Q122 from the test's own computation of the control's angles (none given: not set).
  void set_plane_parameters(const M3& R, int seq) {
    if (!angles_) return;
    for (const auto& [letter, deg] : angles_(R, seq)) q_["Q" + std::to_string(120 + (letter - 'A'))] = deg;
  }

  /// CYCL DEF 7.0 (the header), 7.1 X / 7.2 Y / 7.3 Z: the datum shift added to absolute X Y Z words.
  void datum_shift(const std::string& s) {
    if (s.rfind("CYCL DEF 7.0", 0) == 0) return;
    std::istringstream w(s.substr(13));
    std::string word;
    w >> word;
    if (word.empty() || word[0] < 'X' || word[0] > 'Z' || word.size() < 2)
      throw std::runtime_error("the test interpreter does not read: " + s);
    shift_[word[0] - 'X'] = value_of(word.substr(1));
  }

  /// C, CR, CP in the program's X Y (klartext_arc_geometry.hpp): the path every quarter degree.
  void arc(const std::string& s, int line) {
    std::istringstream w(s.substr(s[1] == ' ' ? 2 : 3));
    Eigen::Vector2d to(xyz_.x(), xyz_.y());
    double r_signed = 0.0, ipa_deg = 0.0, dz = 0.0;
    bool ccw = false, rapid = false;
    for (std::string word; w >> word;) {
      const bool inc = word.size() > 2 && word[0] == 'I' && (word[1] == 'X' || word[1] == 'Y');
      if (word[0] == 'X' || word[0] == 'Y' || inc) {
        const int i = (inc ? word[1] : word[0]) - 'X';
        to[i] = inc ? xyz_[i] + value_of(word.substr(2)) : shift_[i] + value_of(word.substr(1));
      } else if (word.rfind("DR", 0) == 0) {
        ccw = word == "DR+";
      } else if (word.rfind("IPA", 0) == 0) {
        ipa_deg = value_of(word.substr(3));
      } else if (word.rfind("IZ", 0) == 0) {
        dz = value_of(word.substr(2));
      } else if (word[0] == 'R' && s[1] == 'R' && word.size() > 1 && word[1] != 'L' && word[1] != 'R') {
        r_signed = value_of(word.substr(1));
      } else if (word == "FMAX") {
        rapid = true;
      } else if (word[0] != 'F' && word[0] != 'M' && word != "R0") {
        throw std::runtime_error("the test interpreter does not read " + word + " in: " + s);
      }
    }
    const Eigen::Vector2d from(xyz_.x(), xyz_.y());
    const KlartextArc a = s[1] == ' '   ? arc_about_pole(from, pole_.value(), to, ccw)
                          : s[1] == 'R' ? arc_by_radius(from, to, r_signed, ccw)
                                        : arc_polar_step(from, pole_.value(), ipa_deg, dz);
    const int n = std::max(2, static_cast<int>(std::ceil(std::abs(a.sweep_rad) * 4 * 180 / M_PI)));
    const double z0 = xyz_.z();
    for (int i = 1; i < n; ++i) path_.push_back({tip_at(a.at(static_cast<double>(i) / n, z0)), !rapid});
    xyz_ = a.at(1.0, z0);
    if (s[1] != 'P') xyz_.head<2>() = to;  // (C, CR: the programmed end)
    path_.push_back({tip_W(), !rapid});
    end_here(line);
  }

  /// The end of a block where the tool stands now.
  void end_here(int line) {
    ends_.push_back({line, tip_W(), forward(m_, job_, V3::Zero(), rot_).axis_W, rot_,
                     programmed_[0] && programmed_[1] && programmed_[2], path_.size() - 1});
  }

  /// CC X Y (IX IY from the current position; a coordinate left out: the current one).
  void pole(const std::string& s) {
    std::istringstream w(s.substr(3));
    pole_ = Eigen::Vector2d(xyz_.x(), xyz_.y());
    for (std::string word; w >> word;) {
      const bool inc = word[0] == 'I';
      const int i = (inc ? word[1] : word[0]) - 'X';
      (*pole_)[i] = (inc ? xyz_[i] : shift_[i]) + value_of(word.substr(inc ? 2 : 1));
    }
  }

  /// LP PR PA (IPR IPA: added to the current position's polar radius and angle about CC; left out:
  /// the current ones) as the L block to the same point; its other words as written.
  std::string polar_as_cartesian(const std::string& s) const {
    const Eigen::Vector2d d = Eigen::Vector2d(xyz_.x(), xyz_.y()) - pole_.value();
    double r = d.norm(), a_deg = std::atan2(d.y(), d.x()) * 180.0 / M_PI;
    std::istringstream w(s.substr(3));
    std::string rest;
    for (std::string word; w >> word;) {
      if (word.rfind("PR", 0) == 0)
        r = value_of(word.substr(2));
      else if (word.rfind("IPR", 0) == 0)
        r += value_of(word.substr(3));
      else if (word.rfind("PA", 0) == 0)
        a_deg = value_of(word.substr(2));
      else if (word.rfind("IPA", 0) == 0)
        a_deg += value_of(word.substr(3));
      else
        rest += " " + word;
    }
    const Eigen::Vector2d end =
        *pole_ + r * Eigen::Vector2d(std::cos(a_deg * M_PI / 180.0), std::sin(a_deg * M_PI / 180.0));
    std::ostringstream l;
    l.precision(17);
    l << "L X" << (end.x() < 0 ? "-" : "+") << std::abs(end.x()) << " Y" << (end.y() < 0 ? "-" : "+")
      << std::abs(end.y()) << rest;
    return l.str();
  }

  /// The tip of the program point `p` in the current mode.
  V3 tip_at(const V3& p) const {
    if (plane_) return *plane_ * p;
    if (rtcp_) return p;
    return forward(m_, job_, p, rot_).tip_W;
  }

  /// RND / CHF between the line just run (from line_from_ to the corner xyz_) and the line to `to`:
  /// the centre of the rounding lies on the corner's bisector, R / sin(half the corner's angle) from
  /// the corner; the arc touches the lines where the perpendiculars from the centre meet them. A
  /// chamfer cuts each line `length` from the corner. The last line's end moves there; the arc (points
  /// every degree) or the chamfer follow, ending on the next line there (returned).
  V3 round_or_chamfer(const V3& to) {
    const Corner c = *corner_;
    corner_.reset();
    const V3 p1 = xyz_;
    V3 a = line_from_ - p1, b = to - p1;
    a.z() = b.z() = 0;
    a.normalize(), b.normalize();
    const double half = std::acos(std::clamp(a.dot(b), -1.0, 1.0)) / 2.0;
    const double along = c.rounding ? c.length / std::tan(half) : c.length;
    const V3 t1 = p1 + along * a, t2 = p1 + along * b;
    ends_.back().tip_W = tip_at(t1);
    path_.back().tip_W = tip_at(t1);
    if (c.rounding) {
      const V3 centre = p1 + (a + b).normalized() * (c.length / std::sin(half));
      const double a0 = std::atan2(t1.y() - centre.y(), t1.x() - centre.x());
      const double sweep = std::remainder(std::atan2(t2.y() - centre.y(), t2.x() - centre.x()) - a0, 2 * M_PI);
      const int n = std::max(2, static_cast<int>(std::ceil(std::abs(sweep) * 180 / M_PI)));
      for (int i = 1; i < n; ++i) {
        const double ang = a0 + sweep * i / n;
        path_.push_back(
            {tip_at(V3(centre.x() + c.length * std::cos(ang), centre.y() + c.length * std::sin(ang), p1.z())), true});
      }
    }
    path_.push_back({tip_at(t2), true});
    ends_.push_back({c.line, tip_at(t2), forward(m_, job_, V3::Zero(), rot_).axis_W, rot_, true, path_.size() - 1});
    return t2;
  }

  void set_rtcp(bool on) {
    keep_tip([&] { rtcp_ = on; });
  }

  /// A change of mode keeps the machine where it is: the program's X Y Z follow.
  template <class F>
  void keep_tip(F change) {
    const V3 tip = tip_W();
    change();
    xyz_ = program_of(tip);
  }

  V3 tip_W() const {
    if (plane_) return *plane_ * xyz_;
    if (rtcp_) return xyz_;
    return forward(m_, job_, xyz_, rot_).tip_W;
  }
  V3 program_of(const V3& tip) const {
    if (plane_) return plane_->transpose() * tip;
    if (rtcp_) return tip;
    return machine_xyz(tip, rot_);
  }
  /// X Y Z of the machine that put the tip on `tip` at `rot` (the forward kinematics is affine in X Y Z).
  V3 machine_xyz(const V3& tip, const std::map<char, double>& rot) const {
    const V3 t0 = forward(m_, job_, V3::Zero(), rot).tip_W;
    M3 A;
    for (int i = 0; i < 3; ++i) A.col(i) = forward(m_, job_, V3::Unit(i), rot).tip_W - t0;
    return A.inverse() * (tip - t0);
  }

  /// M91 / M92 in an L block: its X Y Z words count from the machine file's reference (M91, the
  /// machine datum) or reference2 (M92, the additional machine datum), read by the test's own parse.
  std::optional<int> machine_datum(const std::string& s) const {
    for (const char* code : {" M91", " M92"}) {
      const auto at = s.find(code);
      if (at != std::string::npos && (at + 4 == s.size() || s[at + 4] == ' ')) {
        if (rtcp_ || plane_) throw std::runtime_error("the test interpreter reads M91 / M92 outside M128 and planes");
        return code[3] - '0';
      }
    }
    return std::nullopt;
  }
  double datum_of(char letter, int code) const {
    const ExecAxis& a = m_.all_axes.at(letter);
    const std::optional<double>& d = code == 1 ? a.reference : a.reference2;
    if (!d) throw std::runtime_error(std::string("the test machine has no reference for M9") + char('0' + code));
    return *d;
  }

  static bool is_number_start(const std::string& v) {
    return !v.empty() && (v[0] == '+' || v[0] == '-' || std::isdigit(static_cast<unsigned char>(v[0])) || v[0] == 'Q');
  }

  void motion(const std::string& s, int line) {
    std::istringstream w(s.substr(2));
    V3 xyz = xyz_;
    std::map<char, double> rot = rot_;
    bool linear = false, rapid = false;
    const std::optional<int> datum = machine_datum(s);
    for (std::string word; w >> word;) {
      const bool inc = word.size() > 2 && word[0] == 'I' && std::string("XYZ").find(word[1]) != std::string::npos;
      const char letter = inc ? word[1] : word[0];
      const std::string v = inc ? word.substr(2) : word.substr(1);
      if (std::string("XYZ").find(letter) != std::string::npos && is_number_start(v)) {
        const int i = letter - 'X';
        if (datum && inc) throw std::runtime_error("the test interpreter reads absolute M91 / M92 words only");
        xyz[i] = (inc ? xyz_[i] : datum ? datum_of(letter, *datum) : shift_[i]) + value_of(v);
        programmed_[i] = linear = true;
      } else if (m_.rotary_letters.find(letter) != std::string::npos && is_number_start(v)) {
        if (datum) throw std::runtime_error("the test interpreter reads M91 / M92 with X Y Z only");
        rot[letter] = value_of(v);
      } else if (word == "FMAX" || word == "MAX") {  // (FMAX or F MAX)
        rapid = true;
      }  // F, R0, M words: no position
    }
    line_from_ = corner_ ? round_or_chamfer(xyz) : xyz_;  // (after a corner the line starts where it joined)
    if (!linear && !rtcp_) {                              // rotary axes alone: the machine's linear axes stay
      const V3 machine = plane_ ? machine_xyz(tip_W(), rot_) : xyz_;
      rot_ = rot;
      const V3 tip = forward(m_, job_, machine, rot_).tip_W;
      xyz_ = program_of(tip);
    } else {
      xyz_ = xyz;
      rot_ = rot;
    }
    path_.push_back({tip_W(), !rapid});
    end_here(line);
    const bool m89 = s.find(" M89") != std::string::npos, m99 = s.find(" M99") != std::string::npos;
    if (m89 || m99) every_positioning_ = m89;  // M89: the cycle after this and every later L block, until M99
    if (m89 || m99 || every_positioning_) call_cycle(line);
  }

  /// M3 / M4 / M5 anywhere in a block.
  void spindle_words(const std::string& s) {
    std::istringstream w(s);
    for (std::string word; w >> word;)
      if (word == "M3" || word == "M4" || word == "M5" || word == "M13" || word == "M14")
        m3_ = word == "M3" || word == "M13";
  }

  /// The defined cycle at the tool's X Y (no plane, no M128): its moves from the hole's top.
  void call_cycle(int line) {
    if (plane_ || rtcp_) throw std::runtime_error("the test interpreter calls cycles outside planes and M128 only");
    const V3 top(xyz_.x(), xyz_.y(), q_.at("Q203"));
    for (const CycleMove& c : cycle_moves(cycle_, q_, m3_, tool_diameter_mm_)) {
      if (c.arc) {
        const V3 from = xyz_, centre = top + c.centre;
        const double a0 = std::atan2(from.y() - centre.y(), from.x() - centre.x());
        const double r = std::hypot(from.x() - centre.x(), from.y() - centre.y());
        const int n = std::max(2, static_cast<int>(std::ceil(std::abs(c.sweep_rad) * 180 / M_PI)));
        for (int i = 1; i <= n; ++i) {
          const double t = static_cast<double>(i) / n, a = a0 + t * c.sweep_rad;
          xyz_ = V3(centre.x() + r * std::cos(a), centre.y() + r * std::sin(a),
                    from.z() + t * (top.z() + c.to.z() - from.z()));
          path_.push_back({tip_W(), true});
        }
      }
      xyz_ = top + c.to;
      path_.push_back({tip_W(), c.cut});
      end_here(line);
    }
  }

  const ExecMachine& m_;
  ExecJob job_;
  PlaneAnglesFn angles_;
  std::vector<std::string> lines_;
  std::map<std::string, std::size_t> labels_;
  std::map<std::string, double> q_;
  V3 xyz_ = V3::Zero();
  V3 shift_ = V3::Zero();             ///< CYCL DEF 7
  std::array<bool, 3> programmed_{};  ///< X Y Z programmed so far
  std::map<char, double> rot_;
  std::optional<M3> plane_;
  std::optional<Eigen::Vector2d> pole_;  ///< CC
  struct Corner {
    bool rounding = true;
    double length = 0.0;  ///< RND R, CHF side
    int line = 0;
  };
  std::optional<Corner> corner_;  ///< RND / CHF read, for the next L
  V3 line_from_ = V3::Zero();     ///< where the last L started
  bool rtcp_ = false;
  std::vector<KlartextEnd> ends_;
  std::vector<KlartextPathPoint> path_;
  int cycle_ = 0;
  bool every_positioning_ = false;  ///< M89 in force
  bool m3_ = true;
  double tool_diameter_mm_ = 0.0;
};

}  // namespace ncpost::test
