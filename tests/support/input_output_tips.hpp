// SPDX-License-Identifier: Apache-2.0
#pragma once
// The re-post check of issue 24: the INPUT program executed as its control would
// (control_interpreter.hpp) against the written OUTPUT executed by nc_executor.hpp. Every input
// block end (machine coordinates minus the base work offset's value at the first motion, through
// the machine's forward kinematics) must be reached by an output block end, in order, within
// 1 µm. Block ends before every axis is programmed are left out: where the machine stood before
// the program is not in the input (the reader's start rule, gcode_cl_reader.hpp "Start").
#include <catch2/catch.hpp>

#include <string>

#include "control_interpreter.hpp"
#include "nc_executor.hpp"
#include "test_paths.hpp"

namespace ncpost::test {

/// The number of input block ends reached (0 at the first one missed, with a failed CHECK); ends
/// before every axis is programmed are not counted.
inline int compare_tips(const std::string& input, const ControlSpec& spec, const std::string& base,
                        const std::string& machine, const std::string& output) {
  constexpr double kTipToleranceMm = 1e-3;
  ControlInterpreter control(input, spec);
  const std::vector<ControlEnd> ends = control.run();
  const std::map<char, double> base_value = control.value_at_first_motion(base);
  const Executor ex(source("machines/" + machine), ExecJob{}, output);
  std::size_t next = 0;
  int compared = 0;
  for (const ControlEnd& e : ends) {
    if (!e.complete) continue;
    std::map<char, double> words;
    for (const auto& [axis, v] : e.machine) words[axis] = v - base_value.at(axis);
    const V3 tip = ex.pose(words, false).tip_W;
    bool found = false;
    for (; next < ex.blocks.size() && !found; ++next) found = (ex.at(ex.blocks[next], 1.0).tip_W - tip).norm() < kTipToleranceMm;
    INFO("input line " << e.line << " tip " << tip.transpose());
    CHECK(found);
    if (!found) return 0;
    ++compared;
  }
  return compared;
}

}  // namespace ncpost::test
