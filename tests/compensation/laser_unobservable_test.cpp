// Issue 7: what a given set of laser lines cannot see is reported, and held at 0 — never given an
// invented value (style guide "Report identifiability").
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <algorithm>

#include "laser_test_support.hpp"
#include "ncpost/compensation/laser_identify.hpp"

using namespace ncpost;

namespace {

bool reported(const comp::LaserIdentifyResult& r, const std::string& what) {
  return std::any_of(r.unseen.begin(), r.unseen.end(), [&](const std::string& u) { return u.rfind(what, 0) == 0; });
}

const comp::LaserFunction& function_named(const comp::LaserIdentifyResult& r, const std::string& name) {
  for (const auto& f : r.functions)
    if (f.name() == name) return f;
  FAIL("no function " << name);
  return r.functions.front();
}

/// Every node the rank analysis left out is 0 in the model.
void check_unseen_are_zero(const comp::LaserIdentifyResult& r) {
  for (const auto& f : r.functions)
    for (std::size_t i = 0; i < f.nodes_mm.size(); ++i)
      if (!f.seen[i]) CHECK(f.values[i] == 0.0);
}

}  // namespace

TEST_CASE("laser: one straightness line per axis cannot give roll", "[laser][identifiability]") {
  const Machine m = test::vmcl600();
  comp::LaserPlanOptions plan;
  const test::LaserTruth truth = test::vmcl600_truth(m, plan);
  std::vector<comp::MeasurementSet> sets;
  for (auto& s : test::simulate_laser(m, truth.parameters, plan, 0.3)) {
    const bool straightness = s.file.find("_str") != std::string::npos;
    if (!straightness || s.file[1] == '1') sets.push_back(std::move(s));  // positioning: 3 lines; straightness: line 1
  }
  const comp::LaserIdentifyResult r = comp::identify_laser(m, sets);
  REQUIRE(r.ok);
  for (const auto& u : r.unseen) fmt::print("  unseen: {}\n", u);
  CHECK(reported(r, "EAX (roll of X)"));
  CHECK(reported(r, "EBY (roll of Y)"));
  CHECK(reported(r, "ECZ (roll of Z)"));
  // positioning on three lines still gives pitch and yaw; straightness and squareness are seen
  for (const char* seen : {"EXX", "EBX", "ECX", "EYY", "EAY", "ECY", "EZZ", "EAZ", "EBZ", "EYX", "EZX", "EXY", "EZY"})
    CHECK_FALSE(reported(r, seen));
  CHECK(r.squareness.size() == 3);
  CHECK(r.rank.rank < static_cast<int>(r.candidates.size()));
  CHECK_FALSE(function_named(r, "EAX").partly_seen());
  check_unseen_are_zero(r);
  CHECK(r.rms_fit_um < 0.4);  // the data are still explained: what is unseen has no separate effect
}

TEST_CASE("laser: a single line gives neither pitch, yaw nor roll; positioning only gives no straightness",
          "[laser][identifiability]") {
  const Machine m = test::vmcl600();
  comp::LaserPlanOptions plan;
  const test::LaserTruth truth = test::vmcl600_truth(m, plan);
  SECTION("one line per axis") {
    comp::LaserPlanOptions one = plan;
    one.lines = 1;
    const comp::LaserIdentifyResult r = comp::identify_laser(m, test::simulate_laser(m, truth.parameters, one, 0.3));
    REQUIRE(r.ok);
    for (const char* angular : {"EAX", "EBX", "ECX", "EAY", "EBY", "ECY", "EAZ", "EBZ", "ECZ"})
      CHECK(reported(r, angular));
    for (const char* seen : {"EXX", "EYY", "EZZ"}) CHECK_FALSE(reported(r, seen));
    check_unseen_are_zero(r);
  }
  SECTION("positioning only, three lines") {
    comp::LaserPlanOptions pos = plan;
    pos.straightness = false;
    const comp::LaserIdentifyResult r = comp::identify_laser(m, test::simulate_laser(m, truth.parameters, pos, 0.3));
    REQUIRE(r.ok);
    for (const char* unseen : {"EYX", "EZX", "EXY", "EZY", "EXZ", "EYZ", "EAX", "EBY", "ECZ"}) CHECK(reported(r, unseen));
    for (const char* seen : {"EXX", "EBX", "ECX", "EYY", "EAY", "ECY", "EZZ", "EAZ", "EBZ"}) CHECK_FALSE(reported(r, seen));
    CHECK(r.squareness.empty());
    CHECK(r.squareness_unseen.size() == 3);
    check_unseen_are_zero(r);
  }
}
