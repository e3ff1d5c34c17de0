// SPDX-License-Identifier: Apache-2.0
// The curve a laser error function carries between its targets (laser_smooth.hpp, issue 25 item 6):
// the not-a-knot spline reproduces any cubic, the Legendre fit any polynomial of its degree, and
// leave-one-out cross-validation picks a curve for smooth node values and keeps every node.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "ncpost/compensation/laser_smooth.hpp"

using namespace ncpost;

namespace {

std::vector<double> targets_x() {  // the VMCL600's X targets with home
  std::vector<double> x{-295.0};
  for (double t = -250.0; t <= 250.0; t += 50.0) x.push_back(t);
  x.push_back(295.0);
  return x;
}

}  // namespace

TEST_CASE("laser smooth: the not-a-knot spline and the Legendre fit reproduce polynomials", "[laser][smooth]") {
  const std::vector<double> x = targets_x();
  auto cubic = [](double t) {
    return 1e-3 * (0.5 * t / 300 - 2.0 * std::pow(t / 300, 2) + 1.5 * std::pow(t / 300, 3));
  };
  auto quintic = [](double t) { return 2e-5 * (std::pow(t / 300, 5) - 0.7 * std::pow(t / 300, 2)); };
  std::vector<double> yc, yq;
  for (double t : x) yc.push_back(cubic(t)), yq.push_back(quintic(t));
  for (double t : {-290.0, -137.5, -12.0, 33.0, 218.0, 292.5, 310.0}) {
    CHECK(comp::spline_at(x, yc, t) == Approx(cubic(t)).margin(1e-12));  // between, beyond the ends too
    CHECK(comp::legendre_fit_at(x, yq, 5, {t})[0] == Approx(quintic(t)).margin(1e-14));
  }
  // the spline is not the table: between targets it departs from the chord
  const double chord = 0.5 * (cubic(100.0) + cubic(150.0));
  REQUIRE(std::abs(cubic(125.0) - chord) > 5e-7);
  CHECK(comp::spline_at(x, yc, 125.0) - chord == Approx(cubic(125.0) - chord).margin(1e-12));
}

TEST_CASE("laser smooth: cross-validation picks a curve for smooth values, never worse than the table",
          "[laser][smooth]") {
  const std::vector<double> x = targets_x();
  std::mt19937_64 rng(5);
  std::normal_distribution<double> noise(0.0, 0.2e-3);  // 0.2 µm
  // a sine of period 410 mm (no harmonic of the travel), 12 µm, with noise
  std::vector<double> y;
  for (double t : x)
    y.push_back(t == 0.0 ? 0.0 : 12e-3 * (std::sin(2 * M_PI * t / 410.0 + 0.3) - std::sin(0.3)) + noise(rng));
  const comp::LaserCurve smooth = comp::choose_laser_curve(x, y, 5.0, comp::kMaxLegendreDegree);
  CHECK(smooth.basis != comp::LaserBasis::linear);
  CHECK(smooth.cv_rms < smooth.cv_linear_rms);
  // through the nodes only (the default): the spline
  CHECK(comp::choose_laser_curve(x, y).basis == comp::LaserBasis::spline);
  // the dense table: every target and a node every 5 mm, through home, on the sine within 1 µm
  CHECK(smooth.nodes_mm.size() >= (295 + 295) / 5);
  for (double t : x) CHECK(std::count(smooth.nodes_mm.begin(), smooth.nodes_mm.end(), t) == 1);
  for (std::size_t i = 0; i < smooth.nodes_mm.size(); ++i) {
    const double t = smooth.nodes_mm[i];
    if (t == 0.0) CHECK(smooth.values[i] == 0.0);
    CHECK(std::abs(smooth.values[i] - 12e-3 * (std::sin(2 * M_PI * t / 410.0 + 0.3) - std::sin(0.3))) < 1e-3);
  }
  // a V (a kink at 100 mm): whatever is chosen predicts left-out nodes no worse than the table
  // (within the tie), and a curve through the nodes keeps every node's value
  std::vector<double> v;
  for (double t : x) v.push_back(1e-4 * std::abs(t - 100.0) - 1e-4 * 100.0);
  const comp::LaserCurve kink = comp::choose_laser_curve(x, v);
  CHECK(kink.cv_rms <= kink.cv_linear_rms * (1.0 + comp::kCvTie));
  for (std::size_t i = 0; i < x.size(); ++i) {
    const auto at = std::find(kink.nodes_mm.begin(), kink.nodes_mm.end(), x[i]);
    REQUIRE(at != kink.nodes_mm.end());
    CHECK(kink.values[static_cast<std::size_t>(at - kink.nodes_mm.begin())] == Approx(v[i]).margin(1e-12));
  }
}
