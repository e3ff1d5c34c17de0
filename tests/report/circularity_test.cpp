// SPDX-License-Identifier: Apache-2.0
// ISO 230-4 figures on circles whose answers are known by construction.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "ncpost/report/circularity.hpp"

using ncpost::report::iso230_4_circularity;

namespace {
constexpr double kPi = 3.141592653589793;
}

TEST_CASE("circular deviation G of an off-centre circle with a 2-lobe form error", "[report][circularity]") {
  // r = 5 + 20 cos θ − 10 sin θ (centre offset 20, −10 µm) + 3 cos 2θ: about the LSC centre the
  // path lies between −3 and +3 µm around the mean radius, so G = 6 µm; F from the raw r.
  std::vector<double> a, r;
  for (int k = 0; k < 360; ++k) {
    const double t = 2 * kPi * k / 360.0;
    a.push_back(t);
    r.push_back(5 + 20 * std::cos(t) - 10 * std::sin(t) + 3 * std::cos(2 * t));
  }
  const auto f = iso230_4_circularity(a, r);
  REQUIRE(f.ok);
  CHECK(f.G_um == Approx(6.0).margin(1e-9));
  CHECK(f.centre_x_um == Approx(20.0).margin(1e-9));
  CHECK(f.centre_y_um == Approx(-10.0).margin(1e-9));
  double fmax = -1e9, fmin = 1e9;
  for (double v : r) fmax = std::max(fmax, v), fmin = std::min(fmin, v);
  CHECK(f.F_max_um == Approx(fmax));
  CHECK(f.F_min_um == Approx(fmin));
  CHECK(f.direction == 1);
  CHECK(f.arc_deg == Approx(359.0));
  CHECK(f.H_um < 0);  // one direction only
}

TEST_CASE("circular hysteresis H between the two directions", "[report][circularity]") {
  // counter-clockwise 0→359°, then clockwise back (every angle once each way), the clockwise path 2 µm further out at
  // every angle
  std::vector<double> a, r;
  for (int k = 0; k < 360; ++k) {
    a.push_back(2 * kPi * k / 360.0);
    r.push_back(1.5 * std::sin(3 * a.back()));
  }
  for (int k = 359; k >= 0; --k) {
    a.push_back(2 * kPi * k / 360.0);
    r.push_back(1.5 * std::sin(3 * a.back()) + 2.0);
  }
  const auto f = iso230_4_circularity(a, r);
  REQUIRE(f.ok);
  CHECK(f.direction == 0);
  CHECK(f.H_um == Approx(2.0).margin(1e-9));
  CHECK(f.G_um == Approx(5.0).margin(1e-6));  // −1.5 … +3.5 about the common centre
}

TEST_CASE("a short arc or too few points gives no figures", "[report][circularity]") {
  std::vector<double> a, r;
  for (int k = 0; k < 40; ++k) a.push_back(k * 0.02), r.push_back(1.0);
  CHECK_FALSE(iso230_4_circularity(a, r).ok);
  CHECK_FALSE(iso230_4_circularity({0, 1, 2}, {0, 0, 0}).ok);
}

TEST_CASE("ISO 230-4 G of each direction: counter-clockwise and clockwise runs with their own G",
          "[report][circularity]") {
  // counter-clockwise 0 → 359°: r = 2 cos 2θ (G_ccw = 4 µm about the LSC centre, which the 2θ lobe
  // does not move); then clockwise 359° → 0: r = 3 cos 2θ + 10 cos θ (a centre 10 µm off in x that
  // the clockwise LSC removes: G_cw = 6 µm). Both together: neither centre fits both, G > 6.
  std::vector<double> a, r;
  for (int k = 0; k < 360; ++k) {
    const double t = 2 * kPi * k / 360.0;
    a.push_back(t);
    r.push_back(2 * std::cos(2 * t));
  }
  for (int k = 359; k >= 0; --k) {
    const double t = 2 * kPi * k / 360.0;
    a.push_back(t);
    r.push_back(3 * std::cos(2 * t) + 10 * std::cos(t));
  }
  const auto f = ncpost::report::iso230_4_by_direction(a, r);
  REQUIRE(f.ccw.ok);
  REQUIRE(f.cw.ok);
  CHECK(f.ccw.direction == 1);
  CHECK(f.cw.direction == -1);
  CHECK(f.ccw.G_um == Approx(4.0).margin(1e-9));
  // the clockwise run's first point (359°, reached by a standstill) counts for neither direction:
  // 359 points, the 2θ lobe no longer exactly orthogonal to the centre's cos θ, sin θ
  CHECK(f.cw.G_um == Approx(6.0).margin(0.1));
  CHECK(f.cw.centre_x_um == Approx(10.0).margin(0.1));
  CHECK(f.ccw.centre_x_um == Approx(0.0).margin(1e-9));
  REQUIRE(f.both.ok);
  CHECK(f.both.direction == 0);
  CHECK(f.both.G_um > 6.0);
  CHECK(f.both.H_um > 0.0);
  // one direction only: the other says so
  const auto one = ncpost::report::iso230_4_by_direction(std::vector<double>(a.begin(), a.begin() + 360),
                                                         std::vector<double>(r.begin(), r.begin() + 360));
  CHECK(one.ccw.ok);
  CHECK_FALSE(one.cw.ok);
  CHECK(one.cw.message == "no clockwise run");
}
