#pragma once
// SPDX-License-Identifier: Apache-2.0
// A small Sinumerik interpreter for the tests, independent of the product: only what the
// re-posting tests need. It gives, for each motion block of a program, where the tool tip and
// the tool axis are in W at the block's end, by the rules of the SINUMERIK 840D sl programming
// manual, with the tests' own forward kinematics (nc_executor.hpp):
//   - numbers only (no variables); N numbers, ';' comments, G0 G1 G2 G3 (end points only), G90;
//   - without TRAORI/CYCLE800: X Y Z and the rotary words are machine axes;
//   - TRAORI: X Y Z are the tool tip in W, the orientation the rotary words or A3= B3= C3=
//     (the unit vector in W itself);
//   - CYCLE800(_FR,_TC,_ST,_MODE,X0,Y0,Z0,A,B,C,X1,Y1,Z1,_DIR): the plane frame
//     Trans(X0) R Trans(X1), R axis by axis in _MODE's order (57: Rx(A) Ry(B) Rz(C); 27: Rz(A) Ry(B) Rx(C)); X Y Z
//     after it are the tip in that frame, the tool axis its Z; CYCLE800() (or a bare CYCLE800) ends it;
//     the rotary angles it turns to, its _FR retraction and where the tool stands after it, and G53/SUPA
//     blocks (machine coordinates): sinumerik_mini_swivel.hpp;
//   - TRANS X Y Z: a shift of the programmable frame;
//   - CYCLE81 82 83 84 840 85 86 (sinumerik_mini_cycles.hpp) at the X Y where the tool stands after the
//     block, in the plane's frame; MCALL CYCLE8x(...) after every following motion block, MCALL
//     alone ends it.
// Other words are skipped (S F T M D ..., and text between quotes: T="name"). Lengths mm, angles deg.
#include <cmath>
#include <map>
#include <optional>
#include <sstream>
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

/// The value after `key` in `line` (e.g. "X", "A3="); nullopt when absent.
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

inline std::vector<SinumerikEnd> sinumerik_block_ends(const std::string& text, const ExecMachine& m,
                                                      const ExecJob& job) {
  std::vector<SinumerikEnd> out;
  std::map<char, double> words{{'X', 0}, {'Y', 0}, {'Z', 0}};
  for (char c : m.rotary_letters) words[c] = 0.0;
  bool traori = false, swivel = false;
  Rt plane;  // CYCLE800's frame
  V3 shift = V3::Zero();
  std::optional<V3> vector;
  std::string modal_cycle;  // "MCALL CYCLE83(...)" as written, without MCALL
  const auto end_at = [&](int line_no, const V3& p) {
    SinumerikEnd e;
    e.line = line_no;
    std::map<char, double> rot;
    for (char c : m.rotary_letters) rot[c] = words[c];
    if (swivel) {
      e.tip_W = plane * (p + shift);
      e.axis_W = plane.R * V3::UnitZ();
    } else if (traori) {
      e.tip_W = p + shift;
      e.axis_W = vector ? *vector : forward(m, job, V3::Zero(), rot).axis_W;
    } else {
      const ExecPose pose = forward(m, job, p + shift, rot);
      e.tip_W = pose.tip_W;
      e.axis_W = pose.axis_W;
    }
    return e;
  };
  const auto run_cycle = [&](int line_no, const std::string& call) {
    const std::size_t open = call.find('(');
    for (double z : sinumerik_cycle_heights(call.substr(0, open), sin_call_args(call, open)))
      out.push_back(end_at(line_no, V3(words['X'], words['Y'], z))), words['Z'] = z;
  };
  std::istringstream in(text);
  int line_no = 0;
  for (std::string raw; std::getline(in, raw);) {
    ++line_no;
    std::string line;
    bool quoted = false;  // strings ("DRILL X8.5" of T=, MSG) are no words
    for (char c : raw.substr(0, raw.find(';'))) {
      if (c == '"')
        quoted = !quoted;
      else if (!quoted)
        line += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    }
    if (line.find("TRAORI") != std::string::npos) traori = true;
    if (line.find("TRAFOOF") != std::string::npos) traori = false;
    if (line.find("TRANS ") != std::string::npos) {
      shift = V3(sin_word(line, "X").value_or(0), sin_word(line, "Y").value_or(0), sin_word(line, "Z").value_or(0));
      continue;
    }
    if (const std::size_t c8 = line.find("CYCLE800"); c8 != std::string::npos) {  // a bare CYCLE800 too: the reset
      std::vector<double> a;
      std::stringstream args(line.find('(', c8) == c8 + 8 ? line.substr(c8 + 9, line.find(')') - c8 - 9) : "");
      for (std::string s; std::getline(args, s, ',');)
        a.push_back(s.empty() || s[0] == '"' ? 0.0 : std::strtod(s.c_str(), nullptr));
      const V3 tip_before = end_at(line_no, V3(words['X'], words['Y'], words['Z'])).tip_W;
      std::optional<Rt> new_plane;
      if (a.size() >= 14)
        new_plane = Rt{M3::Identity(), V3(a[4], a[5], a[6])} *
                    Rt{sin_axis_by_axis(static_cast<int>(a[3]), a[7], a[8], a[9]), V3::Zero()} *
                    Rt{M3::Identity(), V3(a[10], a[11], a[12])};
      const int fr = a.empty() ? 0 : static_cast<int>(a[0]), dir = a.size() >= 14 ? static_cast<int>(a[13]) : 0;
      sin_cycle800(m, job, new_plane, fr, dir, tip_before, shift, traori, words);  // sinumerik_mini_swivel.hpp
      swivel = new_plane.has_value();
      if (swivel) plane = *new_plane;
      continue;
    }
    if (sin_is_machine_block(line)) {  // G53 / SUPA (sinumerik_mini_swivel.hpp)
      std::map<char, double> given;
      for (char c : std::string("XYZ") + m.rotary_letters)
        if (auto v = sin_word(line, std::string(1, c))) given[c] = *v;
      sin_machine_words(m, given, shift, words);
      if (!given.empty()) out.push_back(end_at(line_no, V3(words['X'], words['Y'], words['Z'])));
      continue;
    }
    bool moved = false;
    for (char c : std::string("XYZ") + m.rotary_letters)
      if (auto v = sin_word(line, std::string(1, c))) words[c] = *v, moved = true;
    std::optional<V3> vec;
    if (line.find("A3=") != std::string::npos || line.find("B3=") != std::string::npos ||
        line.find("C3=") != std::string::npos)
      vec = V3(sin_word(line, "A3=").value_or(0), sin_word(line, "B3=").value_or(0), sin_word(line, "C3=").value_or(0))
                .normalized();
    if (vec) vector = vec, moved = true;
    if (const std::size_t mcall = line.find("MCALL"); mcall != std::string::npos) {
      const std::size_t cycle = line.find("CYCLE", mcall);
      modal_cycle = cycle == std::string::npos ? "" : line.substr(cycle);
      continue;
    }
    if (moved) out.push_back(end_at(line_no, V3(words['X'], words['Y'], words['Z'])));
    if (moved && !modal_cycle.empty()) run_cycle(line_no, modal_cycle);
    for (const char* c : {"CYCLE81(", "CYCLE82(", "CYCLE83(", "CYCLE84(", "CYCLE840(", "CYCLE85(", "CYCLE86("})
      if (const std::size_t at = line.find(c); at != std::string::npos) run_cycle(line_no, line.substr(at));
  }
  return out;
}

}  // namespace ncpost::test
