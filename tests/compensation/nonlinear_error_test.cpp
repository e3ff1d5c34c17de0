// SPDX-License-Identifier: Apache-2.0
// The exact nonlinear error of a block against a dense independent simulation (issue 4: within
// 3% per block), on random blocks of several machines, nominal and with geometric errors.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "ncpost/compensation/nonlinear_bound.hpp"
#include "ncpost/compensation/nonlinear_error.hpp"
#include "nonlinear_test_support.hpp"

using namespace ncpost;
using namespace ncpost::nonlinear;

namespace {

/// Independent simulation: the public `tool_pose` at many points, distance to the segment by
/// its own projection, then a fine grid around the best sample.
template <class Errors>
std::pair<double, double> dense_max(const Machine& m, const Setup& s, const ClBlock& b, const Errors& errors,
                                    int samples) {
  auto position_error = [&](double t) {
    AxisPosition q = home_of(m);
    q.linear_mm = (1 - t) * b.from.linear_mm + t * b.to.linear_mm;
    q.rotary_rad = (1 - t) * b.from.rotary_rad + t * b.to.rotary_rad;
    const Vec3d x = tool_pose<double>(m, q, s, errors).tip_mm;
    const Vec3d d = b.end.tip_mm - b.start.tip_mm;
    double u = d.squaredNorm() > 0 ? (x - b.start.tip_mm).dot(d) / d.squaredNorm() : 0.0;
    u = std::min(1.0, std::max(0.0, u));
    return (x - (b.start.tip_mm + u * d)).norm();
  };
  auto orientation_error = [&](double t) {
    AxisPosition q = home_of(m);
    q.linear_mm = (1 - t) * b.from.linear_mm + t * b.to.linear_mm;
    q.rotary_rad = (1 - t) * b.from.rotary_rad + t * b.to.rotary_rad;
    const Vec3d a = tool_pose<double>(m, q, s, errors).axis.normalized();
    const Vec3d r = ((1 - t) * b.start.axis + t * b.end.axis).normalized();
    return std::acos(std::min(1.0, std::max(-1.0, a.dot(r))));
  };
  double best = 0, best_t = 0, best_o = 0;
  for (int i = 0; i <= samples; ++i) {
    const double t = double(i) / samples;
    const double e = position_error(t);
    if (e > best) best = e, best_t = t;
    best_o = std::max(best_o, orientation_error(t));
  }
  for (int i = -200; i <= 200; ++i) {
    const double t = best_t + i * (1.0 / samples) / 200;
    if (t >= 0 && t <= 1) best = std::max(best, position_error(t));
  }
  return {best, best_o};
}

struct RandomBlocks {
  std::mt19937 rng{20240601};
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }

  ClBlock next(const Machine& m, const Setup& s) {
    ClBlock b;
    b.from = b.to = home_of(m);
    for (int i = 0; i < 3; ++i) b.from.linear_mm[i] = uniform(-150, 150);
    const bool big = uniform(0, 1) < 0.15;
    for (int k = 0; k < m.rotary_count(); ++k) {
      const Axis& a = m.rotary(k);
      double lo = a.limits ? a.limits->min : -kPi, hi = a.limits ? a.limits->max : kPi;
      b.from.rotary_rad[k] = uniform(lo, hi);
      const double step = deg_to_rad(big ? uniform(-150, 150) : uniform(-25, 25));
      b.to.rotary_rad[k] = std::clamp(b.from.rotary_rad[k] + step, lo, hi);
    }
    for (int i = 0; i < 3; ++i) b.to.linear_mm[i] = b.from.linear_mm[i] + uniform(-40, 40);
    // CL end points from the nominal machine (so that model errors count in the deviation)
    const auto p0 = forward(m, b.from, s), p1 = forward(m, b.to, s);
    b.start = {p0.tip_mm, p0.axis};
    b.end = {p1.tip_mm, p1.axis};
    return b;
  }
};

template <class Errors>
void check_random_blocks(const std::string& machine, const Errors& errors, int count,
                         const NonlinearErrorOptions& options = {}) {
  const Machine m = test::machine_file(machine);
  Setup s;
  s.workpiece_origin_mm = Vec3d(20, -30, 60);
  s.tool_length_mm = m.rotary(0).side == Side::tool ? 150.0 : 0.0;
  RandomBlocks random;
  double worst_relative = 0, worst_orientation = 0;
  int evaluations = 0;
  for (int i = 0; i < count; ++i) {
    const ClBlock b = random.next(m, s);
    const NonlinearError exact = nonlinear_error(m, s, b, errors, options);
    const auto [dense, dense_o] = dense_max(m, s, b, errors, 4000);
    evaluations += exact.evaluations;
    INFO(fmt::format("{} block {}: exact {:.6f} mm at t={:.4f}, dense {:.6f} mm", machine, i, exact.max_error_mm,
                     exact.at_t, dense));
    CHECK(exact.max_error_mm == Approx(dense).epsilon(0.03).margin(1e-9));
    CHECK(exact.max_error_mm >= dense * (1 - 1e-6) - 1e-9);  // a maximisation never reports less
    if (options.orientation) CHECK(exact.max_orientation_rad == Approx(dense_o).epsilon(0.03).margin(1e-9));
    if (dense > 1e-6) worst_relative = std::max(worst_relative, std::abs(exact.max_error_mm - dense) / dense);
    if (dense_o > 1e-9)
      worst_orientation = std::max(worst_orientation, std::abs(exact.max_orientation_rad - dense_o) / dense_o);
  }
  fmt::print(
      "nonlinear_error{} vs dense simulation, {} ({} blocks): worst relative difference {:.2e} (position), "
      "{:.2e} (orientation), {:.1f} FK evaluations per block\n",
      options.orientation ? "" : " (fast options)", machine, count, worst_relative, worst_orientation,
      double(evaluations) / count);
}

}  // namespace

TEST_CASE("exact nonlinear error agrees with a dense simulation (nominal machines)", "[nonlinear]") {
  check_random_blocks("ac-trunnion.toml", NominalErrors{}, 120);
  check_random_blocks("bv100.toml", NominalErrors{}, 100);
  check_random_blocks("haas-umc750.toml", NominalErrors{}, 100);
  check_random_blocks("gantry-bc-head.toml", NominalErrors{}, 100);
}

TEST_CASE("exact nonlinear error agrees with a dense simulation (machine with errors)", "[nonlinear]") {
  check_random_blocks("ac-trunnion.toml", test::LocationErrors{}, 150);
}

TEST_CASE("the fast options of the compensation agree with a dense simulation too", "[nonlinear]") {
  check_random_blocks("ac-trunnion.toml", NominalErrors{}, 100, fast_error_options());
  check_random_blocks("gantry-bc-head.toml", NominalErrors{}, 60, fast_error_options());
  check_random_blocks("ac-trunnion.toml", test::LocationErrors{}, 60, fast_error_options());
}

TEST_CASE("a block with no rotary motion has no nominal nonlinear error", "[nonlinear]") {
  const Machine m = test::machine_file("ac-trunnion.toml");
  Setup s;
  ClBlock b;
  b.from.rotary_rad = Eigen::Vector2d(0.3, 1.0);
  b.to = b.from;
  b.from.linear_mm = Vec3d(10, 20, 30);
  b.to.linear_mm = Vec3d(50, -20, 0);
  const auto p0 = forward(m, b.from, s), p1 = forward(m, b.to, s);
  b.start = {p0.tip_mm, p0.axis};
  b.end = {p1.tip_mm, p1.axis};
  const NonlinearError e = nonlinear_error(m, s, b);
  CHECK(e.max_error_mm < 1e-9);
  CHECK(e.max_orientation_rad < 1e-9);
}

TEST_CASE("Brent's method finds the maximum of a smooth function", "[nonlinear]") {
  const Maximum m = maximise_bracketed([](double t) { return std::sin(3.0 * t) * std::exp(-t); }, 0.0, 2.0);
  // d/dt: 3cos3t − sin3t = 0 → t = atan(3)/3
  CHECK(m.t == Approx(std::atan(3.0) / 3.0).margin(1e-6));
}

TEST_CASE("the cheap bound is never below the exact error", "[nonlinear][bound]") {
  for (const char* name : {"ac-trunnion.toml", "bv100.toml", "haas-umc750.toml", "gantry-bc-head.toml"}) {
    const Machine m = test::machine_file(name);
    Setup s;
    s.workpiece_origin_mm = Vec3d(20, -30, 60);
    s.tool_length_mm = m.rotary(0).side == Side::tool ? 150.0 : 0.0;
    RandomBlocks random;
    double tightest = 1e9, loosest = 0;
    for (int i = 0; i < 300; ++i) {
      ClBlock b = random.next(m, s);
      if (i % 2) {  // short blocks, as on dense paths
        b.to.linear_mm = b.from.linear_mm + 0.02 * (b.to.linear_mm - b.from.linear_mm);
        b.to.rotary_rad = b.from.rotary_rad + 0.02 * (b.to.rotary_rad - b.from.rotary_rad);
        const auto p1 = forward(m, b.to, s);
        b.end = {p1.tip_mm, p1.axis};
      }
      const ExecutedBlock<> executed(m, s, b);
      const NonlinearError exact = nonlinear_error(executed);
      const NonlinearBound bound = nonlinear_bound(executed, m, s);
      INFO(name << " block " << i << ": exact " << exact.max_error_mm << " bound " << bound.error_mm);
      CHECK(bound.error_mm >= exact.max_error_mm * (1 - 1e-9));
      CHECK(bound.orientation_rad >= exact.max_orientation_rad * (1 - 1e-9));
      if (exact.max_error_mm > 1e-6) {
        tightest = std::min(tightest, bound.error_mm / exact.max_error_mm);
        loosest = std::max(loosest, bound.error_mm / exact.max_error_mm);
      }
    }
    fmt::print("nonlinear_bound / exact on {}: {:.2f} .. {:.2f}\n", name, tightest, loosest);
  }
}
