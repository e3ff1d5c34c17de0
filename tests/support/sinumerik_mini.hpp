#pragma once
// SPDX-License-Identifier: Apache-2.0
// A small Sinumerik interpreter for the tests, independent of the product: only what the
// re-posting tests need. It gives, for each motion block of a program, where the tool tip and
// the tool axis are in W at the block's end, by the rules of the SINUMERIK 840D sl programming
// manual, with the tests' own forward kinematics (nc_executor.hpp):
//   - numbers, and DEF'd variables set to numbers (`_Z_HOME=-10`, then `Z=_Z_HOME`); N numbers, ';' comments, G0 G1 G2
//   G3 (modal), G90;
//   - without TRAORI/CYCLE800: X Y Z and the rotary words are machine axes (commands in M);
//   - TRAORI: X Y Z are the tool tip in W, the orientation the rotary words or A3= B3= C3=
//     (the unit vector in W itself); TRAORI and TRAFOOF do not move the machine: the words are
//     carried over through the kinematics;
//   - CYCLE800(_FR,_TC,_ST,_MODE,X0,Y0,Z0,A,B,C,X1,Y1,Z1,_DIR): the plane frame
//     Trans(X0) R Trans(X1), R axis by axis in _MODE's order (57: Rx(A) Ry(B) Rz(C); 27: Rz(A) Ry(B) Rx(C)); X Y Z
//     after it are the tip in that frame, the tool axis its Z; CYCLE800() and a bare CYCLE800 end it;
//     the rotary angles it turns to, its _FR retraction and where the tool stands after it:
//     sinumerik_mini_swivel.hpp;
//   - TRANS X Y Z: a shift of the programmable frame;
//   - G53 / SUPA: the named axes in machine coordinates, counted from the machine file's `reference`
//     (Z without one: the top of its travel; a rotary axis without one: its angle; X or Y without one:
//     not known until a block programs it again, the ends before that not compared); G75 FP=n: the
//     named axes to the machine file's `fixed_point` n (FP=1 without FP=), the values written ignored;
//     both at rapid traverse, for the block only, outside a CYCLE800 plane;
//   - G2/G3 under G17 with I J (from the start), I=AC() J=AC() (the centre) or CR= (negative: more
//     than a half circle): the centre in W for the between-check (sinumerik_reposted.hpp);
//   - CYCLE81 82 83 84 840 85 86 (sinumerik_mini_cycles.hpp) at the X Y where the tool stands after the
//     block, in the plane's frame; MCALL CYCLE8x(...) after every following motion block, MCALL
//     alone ends it. The cycles' motions are given as rapids (their ends are checked, not their paths).
// Other words are skipped (S F T M D ..., and text between quotes: T="name"). Lengths mm, angles deg.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "nc_executor.hpp"
#include "sinumerik_mini_cycles.hpp"
#include "sinumerik_mini_swivel.hpp"

namespace ncpost::test {

struct SinumerikEnd {
  int line = 0;
  V3 tip_W = V3::Zero();
  V3 axis_W = V3::UnitZ();
  int motion = 0;              ///< 0 rapid (G0, G53/SUPA, G75, a cycle's motions), 1 feed, 2 cw arc, 3 ccw arc (G17)
  std::optional<V3> centre_W;  ///< arcs: the centre in W (at the start's height)
  bool complete = true;        ///< X Y Z and the rotary axes have all been placed
  bool tip_straight = true;    ///< the tip moves straight in W (not: machine axes with rotary axes turning)
  /// Under TRAORI with rotary words: the machine angles the program gives (deg), the control's own.
  std::map<char, double> traori_angles_deg;
};

inline M3 sin_rot(int axis, double deg) {
  return Eigen::AngleAxisd(deg * M_PI / 180.0, V3::Unit(axis)).toRotationMatrix();
}

/// CYCLE800's axis-by-axis rotation: _MODE's bit pairs 1-0, 3-2, 5-4 give the first, second and
/// third axis (1 X, 2 Y, 3 Z); each turn about the axis as the turns before left it.
inline M3 sin_axis_by_axis(int mode, double first_deg, double second_deg, double third_deg) {
  const double deg[3] = {first_deg, second_deg, third_deg};
  M3 R = M3::Identity();
  for (int k = 0; k < 3; ++k) R = R * sin_rot(((mode >> (2 * k)) & 3) - 1, deg[k]);
  return R;
}

/// The value after `key` in `line` (e.g. "X", "A3=", "CR="); nullopt when absent.
inline std::optional<double> sin_word(const std::string& line, const std::string& key) {
  for (std::size_t at = line.find(key); at != std::string::npos; at = line.find(key, at + 1)) {
    if (at > 0 && (std::isalnum(static_cast<unsigned char>(line[at - 1])) || line[at - 1] == '_')) continue;
    const std::size_t v = at + key.size();
    if (v >= line.size() ||
        !(std::isdigit(static_cast<unsigned char>(line[v])) || line[v] == '-' || line[v] == '.' || line[v] == '+'))
      continue;
    if (key.size() == 1 && v + 1 < line.size() && line[v] != '-' && line[v] != '.' &&
        std::isdigit(static_cast<unsigned char>(line[v])) && line.find('=', v) != std::string::npos &&
        line.find('=', v) < line.find(' ', v))
      continue;  // A3=... is not A
    return std::strtod(line.c_str() + v, nullptr);
  }
  return std::nullopt;
}

/// `key=AC(v)` in `line` (an absolute value for one word, e.g. the arc centre I=AC(201)).
inline std::optional<double> sin_absolute(const std::string& line, const std::string& key) {
  const std::string pattern = key + "=AC(";
  for (std::size_t at = line.find(pattern); at != std::string::npos; at = line.find(pattern, at + 1))
    if (at == 0 || !std::isalnum(static_cast<unsigned char>(line[at - 1])))
      return std::strtod(line.c_str() + at + pattern.size(), nullptr);
  return std::nullopt;
}

/// The G numbers of a block (G0, G17, G75 ...), in order.
inline std::vector<int> sin_g_codes(const std::string& line) {
  std::vector<int> out;
  for (std::size_t k = 0; k + 1 < line.size(); ++k)
    if (line[k] == 'G' && (k == 0 || !std::isalnum(static_cast<unsigned char>(line[k - 1]))) &&
        std::isdigit(static_cast<unsigned char>(line[k + 1])))
      out.push_back(static_cast<int>(std::strtol(line.c_str() + k + 1, nullptr, 10)));
  return out;
}

/// The centre of an arc in the XY plane from `s` to `e` (program coordinates) with radius `cr`
/// (CR=: negative for more than a half circle), clockwise for G2.
inline V3 sin_centre_from_radius(const V3& s, const V3& e, double cr, bool cw) {
  const Eigen::Vector2d d(e.x() - s.x(), e.y() - s.y());
  const double half = d.norm() / 2;
  const double h = std::sqrt(std::max(0.0, cr * cr - half * half));
  const Eigen::Vector2d left = Eigen::Vector2d(-d.y(), d.x()) / d.norm();
  const double side = (cw ? -1.0 : 1.0) * (cr < 0 ? -1.0 : 1.0);  // a short ccw arc turns about a centre on the left
  const Eigen::Vector2d c = Eigen::Vector2d(s.x() + e.x(), s.y() + e.y()) / 2 + side * h * left;
  return V3(c.x(), c.y(), s.z());
}

class SinumerikMini {
 public:
  SinumerikMini(const ExecMachine& m, const ExecJob& job) : m_(m), job_(job) {
    words_ = {{'X', 0}, {'Y', 0}, {'Z', 0}};
    for (char c : m.rotary_letters) words_[c] = 0.0;
  }

  std::vector<SinumerikEnd> run(const std::string& text) {
    std::istringstream in(text);
    int line_no = 0;
    for (std::string raw; std::getline(in, raw);) {
      std::string line = cleaned(raw);
      if (variables(line))
        block(++line_no, line);
      else
        ++line_no;
    }
    return out_;
  }

 private:
  /// Upper case, without the comment after ';' and the text between quotes.
  static std::string cleaned(const std::string& raw) {
    std::string line;
    bool quoted = false;  // strings ("DRILL X8.5" of T=, MSG) are no words
    for (char c : raw.substr(0, raw.find(';'))) {
      if (c == '"')
        quoted = !quoted;
      else if (!quoted)
        line += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    }
    return line;
  }

  /// Variables: `DEF REAL a, b` declares them, a block of `a=1.5 b=-2` only (numbers) sets them, and
  /// `X=a` elsewhere is read as X1.5 (an unset or undeclared name is left as written: no word). False
  /// for a DEF or assignment block.
  bool variables(std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> tokens;
    for (std::string t; in >> t;) tokens.push_back(t);
    std::size_t first = !tokens.empty() && tokens[0].size() > 1 && tokens[0][0] == 'N' &&
                                std::all_of(tokens[0].begin() + 1, tokens[0].end(), ::isdigit)
                            ? 1
                            : 0;
    if (first < tokens.size() && tokens[first] == "DEF") {
      std::string names;
      for (std::size_t k = first + 2; k < tokens.size(); ++k) names += tokens[k];
      std::istringstream list(names);
      for (std::string n; std::getline(list, n, ',');) declared_.insert(n);
      return false;
    }
    bool assignments = first < tokens.size();
    for (std::size_t k = first; k < tokens.size() && assignments; ++k) {
      const std::size_t eq = tokens[k].find('=');
      char* end = nullptr;
      assignments = eq != std::string::npos && declared_.count(tokens[k].substr(0, eq)) &&
                    (std::strtod(tokens[k].c_str() + eq + 1, &end), *end == '\0');
    }
    if (assignments) {
      for (std::size_t k = first; k < tokens.size(); ++k)
        values_[tokens[k].substr(0, tokens[k].find('='))] =
            std::strtod(tokens[k].c_str() + tokens[k].find('=') + 1, nullptr);
      return false;
    }
    for (const auto& [name, value] : values_)
      for (std::size_t at = line.find("=" + name); at != std::string::npos; at = line.find("=" + name, at + 1)) {
        const std::size_t after = at + 1 + name.size();
        if (after < line.size() && (std::isalnum(static_cast<unsigned char>(line[after])) || line[after] == '_'))
          continue;
        std::ostringstream v;
        v.precision(17);
        v << value;
        line.replace(at, after - at, v.str());
      }
    return true;
  }

  std::map<char, double> rotary() const {
    std::map<char, double> rot;
    for (char c : m_.rotary_letters) rot[c] = words_.at(c);
    return rot;
  }
  V3 xyz() const { return V3(words_.at('X'), words_.at('Y'), words_.at('Z')); }
  void set_xyz(const V3& p) { words_['X'] = p.x(), words_['Y'] = p.y(), words_['Z'] = p.z(); }

  /// Where the tool is at the words `p` (program coordinates) with the rotary words in force.
  ExecPose pose_at(const V3& p) const {
    ExecPose e;
    if (swivel_) {
      e.tip_W = plane_ * (p + shift_);
      e.axis_W = plane_.R * V3::UnitZ();
    } else if (traori_) {
      e.tip_W = p + shift_;
      e.axis_W = vector_ ? *vector_ : forward(m_, job_, V3::Zero(), rotary()).axis_W;
    } else {
      e = forward(m_, job_, p + shift_, rotary());
    }
    return e;
  }

  void end_at(int line_no, const V3& p, int motion, std::optional<V3> centre = std::nullopt) {
    SinumerikEnd e;
    e.line = line_no;
    const ExecPose pose = pose_at(p);
    e.tip_W = pose.tip_W;
    e.axis_W = pose.axis_W;
    e.motion = motion;
    if (centre) e.centre_W = pose_at(*centre).tip_W;
    e.complete = placed_.size() == words_.size();
    e.tip_straight = traori_ || swivel_ || rotary() == last_rotary_;
    last_rotary_ = rotary();
    if (traori_ && !vector_ && !swivel_) e.traori_angles_deg = rotary();
    out_.push_back(e);
  }

  /// The machine's axes in M now (linear mm, rotary deg), outside a CYCLE800 plane.
  std::map<char, double> machine_now(int line_no) const {
    if (swivel_) throw std::runtime_error("line " + std::to_string(line_no) + ": G53/SUPA/G75 in a CYCLE800 plane");
    std::map<char, double> axes = words_;
    const V3 p = traori_ ? machine_xyz_for_tip(m_, job_, xyz() + shift_, rotary()) : V3(xyz() + shift_);
    axes['X'] = p.x(), axes['Y'] = p.y(), axes['Z'] = p.z();
    return axes;
  }

  /// The words that name the machine at `axes` (M): the inverse of machine_now.
  void words_from_machine(const std::map<char, double>& axes) {
    for (char c : m_.rotary_letters) words_[c] = axes.at(c);
    const V3 p(axes.at('X'), axes.at('Y'), axes.at('Z'));
    set_xyz(traori_ ? V3(forward(m_, job_, p, rotary()).tip_W - shift_) : V3(p - shift_));
  }

  /// G53 / SUPA (`fixed_point` 0) or G75 FP=fixed_point: the named axes in machine coordinates.
  void machine_move(int line_no, const std::string& line, int fixed_point) {
    std::map<char, double> axes = machine_now(line_no);
    for (char c : std::string("XYZ") + m_.rotary_letters) {
      const std::optional<double> v = sin_word(line, std::string(1, c));
      if (!v) continue;
      const ExecAxis& a = m_.all_axes.at(c);
      if (fixed_point > 0) {
        if (a.fixed_point.size() < static_cast<std::size_t>(fixed_point))
          throw std::runtime_error("line " + std::to_string(line_no) + ": no fixed point of " + c);
        axes[c] = a.fixed_point[static_cast<std::size_t>(fixed_point - 1)];
      } else {
        const std::optional<double> zero = a.reference ? a.reference : c == 'Z' ? a.limit_max : std::optional<double>();
        if (!zero && !a.rotary) {  // where the axis goes is the machine's: not known until programmed again
          placed_.erase(c);
          continue;
        }
        axes[c] = zero.value_or(0.0) + *v;
      }
      placed_.insert(c);
    }
    words_from_machine(axes);
    end_at(line_no, xyz(), 0);
  }

  /// TRAORI / TRAFOOF: the machine stays, the words are carried over.
  void transformation(int line_no, bool on) {
    if (on == traori_) return;
    const std::map<char, double> axes = machine_now(line_no);
    traori_ = on;
    vector_.reset();
    words_from_machine(axes);
  }

  void cycle800(const std::string& line, std::size_t at) {
    std::vector<double> a;
    const std::size_t open = line.find('(', at);
    if (open != std::string::npos) {
      std::stringstream args(line.substr(open + 1, line.find(')', open) - open - 1));
      for (std::string s; std::getline(args, s, ',');)
        a.push_back(s.empty() || s[0] == '"' ? 0.0 : std::strtod(s.c_str(), nullptr));
    }
    const V3 tip_before_W = pose_at(xyz()).tip_W;
    std::optional<Rt> new_plane;
    if (a.size() >= 14)
      new_plane = Rt{M3::Identity(), V3(a[4], a[5], a[6])} *
                  Rt{sin_axis_by_axis(static_cast<int>(a[3]), a[7], a[8], a[9]), V3::Zero()} *
                  Rt{M3::Identity(), V3(a[10], a[11], a[12])};
    const int fr = a.empty() ? 0 : static_cast<int>(a[0]), dir = a.size() >= 14 ? static_cast<int>(a[13]) : 0;
    // the angles, the _FR retraction and the words where the tool stands in the new frame
    sin_cycle800(m_, job_, new_plane, fr, dir, tip_before_W, shift_, traori_, words_);
    swivel_ = new_plane.has_value();
    if (swivel_) plane_ = *new_plane;
  }

  void run_cycle(int line_no, const std::string& call) {
    const std::size_t open = call.find('(');
    std::string name = call.substr(0, open);
    name.erase(name.find_last_not_of(' ') + 1);  // "MCALL CYCLE81 (...)": a blank before the bracket
    for (double z : sinumerik_cycle_heights(name, sin_call_args(call, open)))
      words_['Z'] = z, end_at(line_no, xyz(), 0);
  }

  /// The arc's centre (program coordinates, at the start's height) where the block gives it.
  std::optional<V3> arc_centre(const std::string& line, const V3& start, const V3& end) const {
    if (plane_g_ != 17) return std::nullopt;
    if (const auto cr = sin_word(line, "CR=")) return sin_centre_from_radius(start, end, *cr, motion_ == 2);
    const auto ai = sin_absolute(line, "I"), aj = sin_absolute(line, "J");
    const auto ii = sin_word(line, "I"), jj = sin_word(line, "J");
    if (!ai && !aj && !ii && !jj) return std::nullopt;
    return V3(ai ? *ai : start.x() + ii.value_or(0.0), aj ? *aj : start.y() + jj.value_or(0.0), start.z());
  }

  /// The block's own axis words and orientation vector: true where it programs any.
  bool take_words(const std::string& line) {
    bool moved = false;
    for (char c : std::string("XYZ") + m_.rotary_letters)
      if (auto v = sin_word(line, std::string(1, c))) words_[c] = *v, moved = true, placed_.insert(c);
    if (line.find("A3=") != std::string::npos || line.find("B3=") != std::string::npos ||
        line.find("C3=") != std::string::npos) {
      vector_ =
          V3(sin_word(line, "A3=").value_or(0), sin_word(line, "B3=").value_or(0), sin_word(line, "C3=").value_or(0))
              .normalized();
      moved = true;
    }
    return moved;
  }

  void block(int line_no, const std::string& line) {
    if (line.find("TRAORI") != std::string::npos) transformation(line_no, true);
    if (line.find("TRAFOOF") != std::string::npos) transformation(line_no, false);
    if (line.find("TRANS ") != std::string::npos) {
      shift_ = V3(sin_word(line, "X").value_or(0), sin_word(line, "Y").value_or(0), sin_word(line, "Z").value_or(0));
      return;
    }
    if (const std::size_t c8 = line.find("CYCLE800"); c8 != std::string::npos) return cycle800(line, c8);
    bool machine = line.find("SUPA") != std::string::npos;
    int fixed_point = 0;
    for (int g : sin_g_codes(line)) {
      if (g <= 3) motion_ = g;
      if (g == 17 || g == 18 || g == 19) plane_g_ = g;
      if (g == 53) machine = true;
      if (g == 75) fixed_point = static_cast<int>(sin_word(line, "FP=").value_or(1.0));
    }
    if (const std::size_t mcall = line.find("MCALL"); mcall != std::string::npos) {
      const std::size_t cycle = line.find("CYCLE", mcall);
      modal_cycle_ = cycle == std::string::npos ? "" : line.substr(cycle);
      return;
    }
    if (machine || fixed_point > 0) return machine_move(line_no, line, fixed_point);
    const V3 start = xyz();
    const bool moved = take_words(line);
    if (moved) end_at(line_no, xyz(), motion_, motion_ >= 2 ? arc_centre(line, start, xyz()) : std::nullopt);
    if (moved && !modal_cycle_.empty()) run_cycle(line_no, modal_cycle_);
    for (const char* c : {"CYCLE81(", "CYCLE82(", "CYCLE83(", "CYCLE84(", "CYCLE840(", "CYCLE85(", "CYCLE86("})
      if (const std::size_t at = line.find(c); at != std::string::npos) run_cycle(line_no, line.substr(at));
  }

  const ExecMachine& m_;
  ExecJob job_;
  std::map<char, double> words_, last_rotary_;
  std::set<char> placed_;
  std::set<std::string> declared_;        // DEF'd variables
  std::map<std::string, double> values_;  // their values where a block set them to a number
  bool traori_ = false, swivel_ = false;
  Rt plane_;  // CYCLE800's frame
  V3 shift_ = V3::Zero();
  std::optional<V3> vector_;
  int motion_ = 0, plane_g_ = 17;
  std::string modal_cycle_;  // "CYCLE83(...)" as written after MCALL
  std::vector<SinumerikEnd> out_;
};

inline std::vector<SinumerikEnd> sinumerik_block_ends(const std::string& text, const ExecMachine& m,
                                                      const ExecJob& job) {
  return SinumerikMini(m, job).run(text);
}

}  // namespace ncpost::test
