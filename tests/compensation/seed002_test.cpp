// SPDX-License-Identifier: Apache-2.0
// Seed 002 (Gao et al.): ballbar tests of a BC swivel head. With the two positioning errors
// (zero errors of B and C) given, the remaining eight location errors of B and C are unique when
// the C test is read at two tool lengths and the B test also along Y; with the seed's single tool length, the offset
// and the tilt of the C line are seen only as the combination at the ball (as seed 000's heights). The seed's αSB +
// αBC: in the home-referenced model the spindle is the reference (the tool axis is +Z at home), so the tilt of the B
// line about X relative to the spindle is one parameter, EA0B — the sum — and it is identified.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

#include "ncpost/compensation/identify.hpp"
#include "ncpost/compensation/plans.hpp"
#include "ncpost/compensation/simulate.hpp"
#include "ncpost/machines/machine_file.hpp"

using namespace ncpost;
using namespace ncpost::comp;

namespace {

const std::vector<std::pair<std::string, double>> kTruth = {
    {"EX0C", 0.012},  {"EY0C", -0.018}, {"EA0C", 2.5e-5}, {"EB0C", -3e-5}, {"EX0B", 0.02},
    {"EZ0B", -0.015}, {"EA0B", 4e-5},   {"EC0B", -2e-5},  {"EB0B", 3e-5},  {"EC0C", -2e-5}};
const std::vector<std::string> kEight = {"EX0C", "EY0C", "EA0C", "EB0C", "EX0B", "EZ0B", "EA0B", "EC0B"};

std::vector<MeasurementSet> measure(const Machine& m, const BcHeadPlanOptions& o) {
  ErrorParameters truth;
  for (const auto& [n, v] : kTruth) truth.set(n, v);
  std::vector<MeasurementSet> sets;
  std::uint64_t seed = 3;
  for (const auto& p : plan_bc_head(m, o)) sets.push_back(simulate(m, p.set, truth, {0.3, seed++}));
  return sets;
}

IdentifyOptions positioning_given() {
  IdentifyOptions o;
  o.fixed.set("EB0B", 3e-5);
  o.fixed.set("EC0C", -2e-5);
  return o;
}

}  // namespace

TEST_CASE("seed 002: the eight BC-head errors are unique with the positioning errors given") {
  const Machine m = load_machine(std::string(NCPOST_SOURCE_DIR) + "/machines/gantry-bc-head.toml");
  const auto sets = measure(m, BcHeadPlanOptions{});
  const IdentifyResult r = identify(m, sets, kEight, positioning_given());
  REQUIRE(r.converged);
  CHECK(r.identifiability.rank == 8);
  CHECK(r.identifiability.null_space.empty());
  for (const auto& [n, v] : kTruth) {
    if (n == "EB0B" || n == "EC0C") continue;
    INFO(n << ": " << *r.parameters.get(n) << " +- " << *r.uncertainty.get(n) << ", truth " << v);
    CHECK(std::abs(*r.parameters.get(n) - v) < 4.0 * *r.uncertainty.get(n));
    CHECK(*r.uncertainty.get(n) < (n[1] == 'A' || n[1] == 'B' || n[1] == 'C' ? 5e-6 : 1e-3));  // truly seen
  }
  printf("seed 002, two tool lengths: rank %d of %d\n", r.identifiability.rank, r.identifiability.parameters);
}

TEST_CASE("seed 002: the seed's single tool length couples offset and tilt of the C line") {
  const Machine m = load_machine(std::string(NCPOST_SOURCE_DIR) + "/machines/gantry-bc-head.toml");
  BcHeadPlanOptions o;
  o.tool_lengths_mm = {100.0};
  const IdentifyResult r = identify(m, measure(m, o), kEight, positioning_given());
  CHECK(r.identifiability.rank == 6);
  for (const auto& c : r.identifiability.combinations) printf("  seed 002, one tool length: %s\n", c.c_str());
  REQUIRE(r.identifiability.pinned.size() == 2);
  CHECK(r.identifiability.pinned[0] == "EA0C");
  CHECK(r.identifiability.pinned[1] == "EB0C");
  // EY0C − L·EA0C and EX0C + L·EB0C with L = 100 mm, the tool length (the C pivot is at the gauge point)
  CHECK(r.identifiability.combinations[0].find("100") != std::string::npos);
}

TEST_CASE("seed 002: read along X and Z only, the B test does not see the tilts of the B line") {
  const Machine m = load_machine(std::string(NCPOST_SOURCE_DIR) + "/machines/gantry-bc-head.toml");
  BcHeadPlanOptions o;
  o.b_test_along_y = false;  // the seed's directions
  const IdentifyResult r = identify(m, measure(m, o), kEight, positioning_given());
  for (const auto& c : r.identifiability.combinations) printf("  seed 002, seed directions: %s\n", c.c_str());
  CHECK(r.identifiability.rank == 6);
  CHECK(r.identifiability.pinned == std::vector<std::string>{"EA0B", "EC0B"});
}
