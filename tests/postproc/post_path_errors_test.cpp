// SPDX-License-Identifier: Apache-2.0
// The path of the 3D view in post_report.html: each CL end point of the "before" program with
// its error, and the largest "after" error of the written blocks of the same CL line; bounded.
#include <catch2/catch.hpp>

#include "ncpost/postproc/verify/post_report.hpp"

using ncpost::PathErrors;
using ncpost::Vec3d;

TEST_CASE("after errors are matched to the before points by CL line", "[post][report]") {
  PathErrors p;
  p.add_after(10, 0.001);  // line 10 written as three blocks
  p.add_after(10, 0.003);
  p.add_after(10, 0.002);
  p.add_after(11, 0.004);
  p.add_after(14, 0.005);  // 12 and 13 not re-executed (e.g. rapids)
  p.add_before(10, Vec3d(1, 2, 3), 0.05);
  p.add_before(11, Vec3d(2, 2, 3), 0.06);
  p.add_before(12, Vec3d(3, 2, 3), 0.07);
  p.add_before(14, Vec3d(4, 2, 3), 0.08);
  const auto pts = p.points();
  REQUIRE(pts.size() == 4);
  CHECK(pts[0].after_mm == 0.003);
  CHECK(pts[1].after_mm == 0.004);
  CHECK(pts[2].after_mm < 0);
  CHECK(pts[3].after_mm == 0.005);
  CHECK(pts[3].tip_mm.x() == 4);
  CHECK(pts[2].before_mm == 0.07);
}

TEST_CASE("the path stays bounded and keeps the largest errors", "[post][report]") {
  PathErrors p(1000);
  for (int line = 1; line <= 100000; ++line) {
    p.add_after(line, line == 77777 ? 0.5 : 0.001);
    p.add_before(line, Vec3d(line, 0, 0), line == 55555 ? 2.0 : 0.01);
  }
  const auto pts = p.points();
  CHECK(pts.size() <= 1000);
  CHECK(pts.size() >= 500);
  double before = 0, after = 0;
  for (const auto& q : pts) before = std::max(before, q.before_mm), after = std::max(after, q.after_mm);
  CHECK(before == 2.0);
  CHECK(after == 0.5);
  CHECK(pts.back().tip_mm.x() == 100000);  // the path still ends where it ends
}
