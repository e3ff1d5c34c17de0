// SPDX-License-Identifier: Apache-2.0
// nonlinear::slerp (nonlinear_block.hpp), the one great-circle interpolation of tool axes (the post's
// CIRCLE expansion, the tolerance subdividers of every machine): the angle from the start grows
// linearly with t, also between opposite axes (where the sin-ratio formula divides by sin π = 0).
#include <catch2/catch.hpp>

#include <cmath>

#include "ncpost/compensation/nonlinear_block.hpp"

using namespace ncpost;

TEST_CASE("slerp: on the great circle, the angle linear in t, also between opposite axes") {
  const Vec3d a = Vec3d(0.3, -0.2, 1.0).normalized();
  const Vec3d b = Vec3d(-0.5, 0.4, 0.8).normalized();
  const double omega = nonlinear::angle_between(a, b);
  for (double t : {0.0, 0.25, 0.5, 0.8, 1.0}) {
    const Vec3d u = nonlinear::slerp(a, b, t);
    CHECK(u.norm() == Approx(1.0).margin(1e-12));
    CHECK(nonlinear::angle_between(a, u) == Approx(t * omega).margin(1e-12));
    CHECK(u.dot(a.cross(b)) == Approx(0.0).margin(1e-12));  // in the plane of a and b
    const Vec3d sin_ratio = (std::sin((1 - t) * omega) * a + std::sin(t * omega) * b) / std::sin(omega);
    CHECK((u - sin_ratio).norm() < 1e-12);  // the textbook formula where it is defined
  }
  const Vec3d z = Vec3d::UnitZ();
  for (double t : {0.1, 0.5, 0.9}) {
    const Vec3d u = nonlinear::slerp(z, -z, t);
    REQUIRE(u.allFinite());
    CHECK(u.norm() == Approx(1.0).margin(1e-12));
    CHECK(nonlinear::angle_between(z, u) == Approx(t * kPi).margin(1e-9));
  }
  CHECK((nonlinear::slerp(z, z, 0.3) - z).norm() < 1e-15);
}
