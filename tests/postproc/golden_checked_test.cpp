// SPDX-License-Identifier: Apache-2.0
// The golden programs (tests/data/golden) are checked, not only compared (issue 27.8): each ISO
// program is executed with the tests' own executor (nc_executor.hpp) and its motion held against
// the CL data of tests/data/golden/sample.apt, written out here by hand:
//  - every point of every feed block (and arc) within the header's tolerance (0.01 mm) of the
//    CL path: the plunge, the circle, the two drilled holes, the two five-axis moves;
//  - every feed word by its rule: per minute the CL feed; G93 F = CL feed / executed tip path.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "nc_executor.hpp"
#include "test_paths.hpp"
#include "text_file.hpp"

using namespace ncpost::test;

namespace {

/// A feed element of the CL path (W): a segment, or the circle of radius 20 about Z at z = 0.
struct ClElement {
  V3 a, b;
  bool circle = false;
  double feed_mm_min = 0.0;
};

/// sample.apt: the plunge to (20, 0, 0) at 500, CIRCLE/0,0,0,0,0,1,20 to (0, 20, 0) at 500, the
/// holes at (10, 20) and (30, 20) from the R plane (3 above) to 5 deep at 100, then at 800
/// (30, 20, 40) -> (30, 20, 30) -> (30, 0, 30).
std::vector<ClElement> sample_path() {
  return {{V3(20, 0, 50), V3(20, 0, 0), false, 500},    {V3(20, 0, 0), V3(0, 20, 0), true, 500},
          {V3(10, 20, 3), V3(10, 20, -5), false, 100},  {V3(30, 20, 3), V3(30, 20, -5), false, 100},
          {V3(30, 20, 40), V3(30, 20, 30), false, 800}, {V3(30, 20, 30), V3(30, 0, 30), false, 800}};
}

double distance_to(const ClElement& e, const V3& p) {
  if (!e.circle) return from_segment(p, e.a, e.b);
  const double r = std::hypot(p.x(), p.y());
  const double angle = std::atan2(p.y(), p.x());
  if (angle >= -1e-9 && angle <= M_PI / 2 + 1e-9) return std::hypot(r - 20.0, p.z());
  return std::min((p - e.a).norm(), (p - e.b).norm());
}

}  // namespace

TEST_CASE("the golden ISO programs cut the CL path of the sample, with feeds by their rule", "[golden][executor]") {
  const std::vector<ClElement> path = sample_path();
  for (const std::string name : {"fanuc", "haas", "linuxcnc", "fanuc_rtcp", "haas_rtcp", "linuxcnc_rtcp"}) {
    CAPTURE(name);
    const std::string text = read_text_file(data("golden/" + name + ".nc"));
    REQUIRE(!text.empty());
    const bool rtcp = name.find("rtcp") != std::string::npos;
    const Executor ex(source("machines/ac-trunnion.toml"), ExecJob{V3(0, 0, rtcp ? 0 : 80), 0.0}, text);
    int feed_blocks = 0;
    for (const ExecBlock& b : ex.blocks) {
      if (b.kind == ExecBlock::Kind::rapid) continue;
      ++feed_blocks;
      CAPTURE(b.line, b.text);
      // the nearest CL element of the block's middle: the block belongs to it
      const V3 mid = ex.at(b, 0.5).tip_W;
      const ClElement* on = &path.front();
      for (const ClElement& e : path)
        if (distance_to(e, mid) < distance_to(*on, mid)) on = &e;
      double worst = 0.0;
      for (int i = 0; i <= 50; ++i) worst = std::max(worst, distance_to(*on, ex.at(b, i / 50.0).tip_W));
      CHECK(worst <= 0.01 + 1e-6);
      if (b.inverse_time) {
        // G93: the block runs for (executed tip path) / (CL feed) minutes
        CHECK(b.feed * ex.tip_path_mm(b) == Approx(on->feed_mm_min).epsilon(2e-4));
      } else {
        CHECK(b.feed == Approx(on->feed_mm_min));
      }
    }
    CHECK(feed_blocks >= 6);
  }
}
