// SPDX-License-Identifier: Apache-2.0
// The re-post check's sampling between block ends (tests/support/input_output_tips.hpp): the
// distance from an output sample to the input's move, worked out by hand on a straight move and
// on a turn of the AC trunnion's C table, and the tolerance read from a written program's header.
#include <catch2/catch.hpp>

#include <cmath>

#include "input_output_tips.hpp"

using namespace ncpost::test;

TEST_CASE("re-post check: the distance to the input's move between its ends") {
  const Executor vmc(source("machines/vmcl600.toml"), ExecJob{}, "G0 X0 Y0 Z0\n");
  const std::map<char, double> a{{'X', 0}, {'Y', 0}, {'Z', 10}}, b{{'X', 10}, {'Y', 0}, {'Z', 10}};
  CHECK(distance_to_input_move(vmc, a, b, V3(5, 3, 10)) == Approx(3.0).margin(1e-9));   // beside the middle
  CHECK(distance_to_input_move(vmc, a, b, V3(13, 4, 10)) == Approx(5.0).margin(1e-9));  // beyond the end: 3-4-5
  CHECK(distance_to_input_move(vmc, a, b, V3(2.5, 0, 10)) == Approx(0.0).margin(1e-9));

  // C turns 90 deg with the tool off the table's axis: the tip runs on a quarter circle in W of
  // radius r = chord / sqrt(2), so the chord's middle lies r (1 - cos 45 deg) inside it, and a
  // point of the circle lies on the path (within the 256-piece polyline's sagitta r (1 - cos(pi/1024)))
  const Executor ac(source("machines/ac-trunnion.toml"), ExecJob{}, "G0 X0 Y0 Z0 A0 C0\n");
  const std::map<char, double> c0{{'X', 100}, {'Y', 0}, {'Z', 0}, {'A', 0}, {'C', 0}};
  std::map<char, double> c90 = c0;
  c90['C'] = 90;
  const V3 start = ac.pose(c0, false).tip_W, end = ac.pose(c90, false).tip_W;
  const double r = (start - end).norm() / std::sqrt(2.0);
  REQUIRE(r > 10.0);
  const V3 chord_middle = 0.5 * (start + end);
  CHECK(distance_to_input_move(ac, c0, c90, chord_middle) == Approx(r * (1 - std::cos(M_PI / 4))).margin(1e-3));
  std::map<char, double> c30 = c0;
  c30['C'] = 30;
  CHECK(distance_to_input_move(ac, c0, c90, ac.pose(c30, false).tip_W) < r * (1 - std::cos(M_PI / 1024)) + 1e-9);
}

TEST_CASE("re-post check: the tolerance the written program states") {
  CHECK(stated_tolerance_mm("%\n(model none [nominal machine], tolerance 0.01 mm [adaptive, the default])\n", 1e-3) ==
        0.01);
  CHECK(stated_tolerance_mm("%\n(model none [nominal machine], tolerance none)\n", 1e-3) == 1e-3);
}
