// SPDX-License-Identifier: Apache-2.0
#pragma once
// The re-post check of issue 24: the INPUT program executed as its control would
// (control_interpreter.hpp) against the written OUTPUT executed by nc_executor.hpp. Every input
// block end (machine coordinates minus the base work offset's value at the first motion, through
// the machine's forward kinematics) must be reached by an output block end, in order, within
// 1 µm. Block ends before every axis is programmed are left out: where the machine stood before
// the program is not in the input (the reader's start rule, gcode_cl_reader.hpp "Start").
//
// Between the ends of an input feed move (G1) the output's blocks that realise it are sampled
// (every block at 16 points, each axis interpolated linearly and through the forward kinematics,
// nc_executor.hpp Executor::at): every sample must lie within the tolerance the output's header
// states (`tolerance 0.01 mm`; `tolerance none`: 1 µm, the one-block-per-move path) of the input's
// path, the input's axis words interpolated linearly between its ends through the same
// kinematics, taken as a polyline of 256 pieces. Rapids (G0) are not sampled: the path between
// their ends is the control's own.
#include <catch2/catch.hpp>

#include <algorithm>
#include <optional>
#include <regex>
#include <string>

#include "control_interpreter.hpp"
#include "nc_executor.hpp"
#include "test_paths.hpp"

namespace ncpost::test {

/// The tolerance the written program's header states (mm); `tolerance none`: `none_mm`.
inline double stated_tolerance_mm(const std::string& output, double none_mm) {
  static const std::regex re(R"(\(model [^\n]*tolerance ([0-9.]+) mm)");
  std::smatch m;
  if (std::regex_search(output, m, re)) return std::stod(m[1].str());
  REQUIRE(output.find("tolerance none") != std::string::npos);
  return none_mm;
}

/// The distance (mm) from `p` to the input's move from machine words `a` to `b`: the tip of the
/// words interpolated linearly, as a polyline of `pieces` pieces.
inline double distance_to_input_move(const Executor& ex, const std::map<char, double>& a,
                                     const std::map<char, double>& b, const V3& p, int pieces = 256) {
  double best = 1e300;
  std::map<char, double> w = a;
  V3 last = ex.pose(a, false).tip_W;
  for (int i = 1; i <= pieces; ++i) {
    const double u = static_cast<double>(i) / pieces;
    for (auto& [axis, v] : w) v = a.at(axis) + u * (b.at(axis) - a.at(axis));
    const V3 next = ex.pose(w, false).tip_W;
    const V3 d = next - last;
    const double len2 = d.squaredNorm();
    const double s = len2 > 0.0 ? std::clamp((p - last).dot(d) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, (last + s * d - p).norm());
    last = next;
  }
  return best;
}

/// The number of input block ends reached (0 at the first one missed, with a failed CHECK); ends
/// before every axis is programmed are not counted.
inline int compare_tips(const std::string& input, const ControlSpec& spec, const std::string& base,
                        const std::string& machine, const std::string& output) {
  constexpr double kTipToleranceMm = 1e-3;
  ControlInterpreter control(input, spec);
  const std::vector<ControlEnd> ends = control.run();
  const std::map<char, double> base_value = control.value_at_first_motion(base);
  const Executor ex(source("machines/" + machine), ExecJob{}, output);
  const double between_mm = stated_tolerance_mm(output, kTipToleranceMm) + kTipToleranceMm;
  std::size_t next = 0;
  int compared = 0;
  std::optional<std::map<char, double>> previous;  // the words of the last input end reached
  for (const ControlEnd& e : ends) {
    if (!e.complete) continue;
    std::map<char, double> words;
    for (const auto& [axis, v] : e.machine) words[axis] = v - base_value.at(axis);
    const V3 tip = ex.pose(words, false).tip_W;
    const std::size_t first_block = next;
    bool found = false;
    for (; next < ex.blocks.size() && !found; ++next)
      found = (ex.at(ex.blocks[next], 1.0).tip_W - tip).norm() < kTipToleranceMm;
    INFO("input line " << e.line << " tip " << tip.transpose());
    CHECK(found);
    if (!found) return 0;
    ++compared;
    if (previous && !e.rapid)
      for (std::size_t b = first_block; b < next; ++b)
        for (int k = 1; k < 16; ++k) {
          const V3 p = ex.at(ex.blocks[b], k / 16.0).tip_W;
          const double d = distance_to_input_move(ex, *previous, words, p);
          INFO("output line " << ex.blocks[b].line << " at " << k << "/16: " << d
                              << " mm from the input's path (allowed " << between_mm << " mm)");
          CHECK(d <= between_mm);
          if (d > between_mm) return 0;
        }
    previous = words;
  }
  return compared;
}

}  // namespace ncpost::test
