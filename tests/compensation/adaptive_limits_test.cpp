// SPDX-License-Identifier: Apache-2.0
// Adaptive subdivision near the singular cone and at axis limits: no rotary flips inside a block,
// and a clear failure (not a wrong program) when an inserted point has no admissible solution.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "ncpost/compensation/adaptive_subdivision.hpp"
#include "nonlinear_test_support.hpp"

using namespace ncpost;
using namespace ncpost::nonlinear;

namespace {

ClBlock solved_block(const Machine& m, const Setup& s, const ClPoint& a, const ClPoint& b, AxisPosition previous = {}) {
  const IkOutcome o0 = solve(m, a, s, previous);
  REQUIRE(o0.ok());
  const IkOutcome o1 = solve(m, b, s, *o0.position);
  REQUIRE(o1.ok());
  return {a, b, *o0.position, *o1.position};
}

double largest_rotary_step(const ClBlock& b, const SplitBlock& split) {
  double step = 0;
  AxisPosition from = b.from;
  for (const BlockNode& n : split.nodes) {
    step = std::max(step, max_abs_step(n.q.rotary_rad, from.rotary_rad));
    from = n.q;
  }
  return step;
}

}  // namespace

TEST_CASE("a block passing near the singular orientation (u = +Z on an AC table)", "[adaptive][limits]") {
  const Machine m = test::machine_file("ac-trunnion.toml");
  Setup s;
  s.workpiece_origin_mm = Vec3d(0, 0, 50);
  const double tilt = deg_to_rad(2.0), side = deg_to_rad(0.2);
  const ClPoint a{Vec3d(40, 10, 5), Vec3d(std::sin(tilt), std::sin(side), 1).normalized()};
  const ClPoint b{Vec3d(42, 14, 5), Vec3d(-std::sin(tilt), std::sin(side), 1).normalized()};
  const ClBlock block = solved_block(m, s, a, b);
  const double c_travel = std::abs(block.to.rotary_rad[1] - block.from.rotary_rad[1]);
  AdaptiveOptions o;
  o.tolerance_mm = 0.005;
  const SplitBlock split = subdivide_adaptive(m, s, block, o);
  fmt::print(
      "near-singular block: A {:.3f} -> {:.3f} deg, C travels {:.1f} deg, error {:.3f} mm -> {} output blocks, "
      "{:.5f} mm {}\n",
      rad_to_deg(block.from.rotary_rad[0]), rad_to_deg(block.to.rotary_rad[0]), rad_to_deg(c_travel),
      split.input_error_mm, split.output_blocks(), split.max_error_mm, split.failure);
  REQUIRE(split.ok());
  CHECK(split.max_error_mm <= o.tolerance_mm);
  CHECK(split.rotary_kept_nodes == split.inserted_blocks());  // end points on different branches
  // C turns one way through the cone, never back: every step is a part of the block's own travel
  CHECK(largest_rotary_step(block, split) <= c_travel + 1e-9);
  double c = block.from.rotary_rad[1];
  const double sign = block.to.rotary_rad[1] > c ? 1.0 : -1.0;
  for (const BlockNode& n : split.nodes) {
    CHECK(sign * (n.q.rotary_rad[1] - c) >= -1e-12);
    c = n.q.rotary_rad[1];
  }
}

TEST_CASE("an inserted point out of the axis limits fails with a message", "[adaptive][limits]") {
  Machine m = test::machine_file("ac-trunnion.toml");
  const Setup s;
  // a long reorientation whose middle needs an X beyond a tight travel
  const ClPoint a{Vec3d(0, -150, 0), Vec3d(0, std::sin(0.6), std::cos(0.6))};
  const ClPoint b{Vec3d(0, 150, 0), Vec3d(0, -std::sin(0.6), std::cos(0.6))};
  const ClBlock block = solved_block(m, s, a, b);
  Axis& z = m.axes[2];
  const double hi = std::max(block.from.linear_mm.z(), block.to.linear_mm.z());
  z.limits = AxisLimits{-1000.0, hi + 0.01};  // the end points fit; points between go above
  AdaptiveOptions o;
  o.tolerance_mm = 0.005;
  const SplitBlock split = subdivide_adaptive(m, s, block, o);
  fmt::print("limits: {}\n", split.failure);
  CHECK_FALSE(split.ok());
  CHECK_THAT(split.failure, Catch::Contains("limits"));
}
