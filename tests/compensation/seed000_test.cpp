// SPDX-License-Identifier: Apache-2.0
// Seed 000 (Tsutsumi & Saito 2003): simultaneous four-axis ballbar test of an AC tilting-rotary
// table. Single-deviation trajectories (0.005° and 0.01 mm, bar 100 mm, height 250 mm), their
// growth with height, the couplings at one height and full rank at two.
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

const std::string kMachine = std::string(NCPOST_SOURCE_DIR) + "/machines/tsutsumi-zxfyac.toml";
// The seed's eight deviations in ISO 230-1 names (docs/conventions.md), with the seed's own names.
const std::vector<std::pair<std::string, std::string>> kSeed = {
    {"EA0C", "alphaAY"},  {"EB0A", "betaAY"},   {"EC0A", "gammaAY"},  {"EB0C", "betaCA"},
    {"EX0C", "deltaxAY"}, {"EY0A", "deltayAY"}, {"EZ0A", "deltazAY"}, {"EY0C", "deltayCA"}};
const double kAngle = deg_to_rad(0.005);
const double kOffset = 0.01;

bool is_angle(const std::string& n) { return n[1] == 'A' || n[1] == 'B' || n[1] == 'C'; }

/// ΔL (µm) along the trajectory for one deviation.
std::vector<double> trajectory(const Machine& m, const std::string& name, double size, double height) {
  BallbarPlanOptions o;
  o.heights_mm = {height};
  const MeasurementSet plan = plan_ballbar_4axis(m, o).front().set;
  ErrorParameters p;
  p.set(name, size);
  const MeasurementSet s = simulate(m, plan, p);
  std::vector<double> dl;
  for (const auto& r : s.rows) dl.push_back(1e3 * (r.value[0] - plan.bar_length_mm));
  return dl;
}

double peak(const std::vector<double>& v) {
  double p = 0.0;
  for (double x : v) p = std::abs(x) > std::abs(p) ? x : p;
  return p;
}

}  // namespace

TEST_CASE("seed 000: single-deviation trajectories, peaks and growth with height") {
  const Machine m = load_machine(kMachine);
  printf("seed 000 single-deviation trajectories (bar 100 mm): peak dL in um\n");
  printf("  %-5s %-9s %-9s %9s %9s %9s %9s  %s\n", "ISO", "seed", "size", "h=250", "min", "max", "h=300", "halves");
  for (const auto& [name, seed] : kSeed) {
    const double size = is_angle(name) ? kAngle : kOffset;
    const auto t250 = trajectory(m, name, size, 250.0);
    const auto t300 = trajectory(m, name, size, 300.0);
    const double p250 = peak(t250), p300 = peak(t300);
    double lo = 1e9, hi = -1e9, asym = 0.0;
    const std::size_t n = t250.size();
    for (std::size_t k = 0; k < n; ++k) {
      lo = std::min(lo, t250[k]);
      hi = std::max(hi, t250[k]);
      asym = std::max(asym, std::abs(t250[k] - t250[n - 1 - k]));  // mirror of the other half
    }
    const bool symmetric = asym < 0.05 * std::abs(p250);
    printf("  %-5s %-9s %-9s %9.2f %9.2f %9.2f %9.2f  %s\n", name.c_str(), seed.c_str(),
           is_angle(name) ? "0.005deg" : "0.01mm", p250, lo, hi, p300, symmetric ? "symmetric" : "asymmetric");
    CHECK(std::abs(p250) > 1.0);  // every deviation shows
    const double ratio = p300 / p250;
    if (is_angle(name)) {
      INFO(name << " grows with the height: ratio " << ratio);
      CHECK(std::abs(ratio) > 1.1);
    } else {
      INFO(name << " does not grow with the height: ratio " << ratio);
      CHECK(std::abs(ratio - 1.0) < 0.02);
    }
  }
  // The bar length does not change the shape much: the offset trajectory for bar 150.
}

TEST_CASE("seed 000: at one height EY0C ~ EA0C and EX0C ~ EB0C give identical trajectories") {
  const Machine m = load_machine(kMachine);
  const double h = 250.0;
  const auto y = trajectory(m, "EY0C", kOffset, h);
  const auto a = trajectory(m, "EA0C", -kOffset / h, h);  // conventions: EY0C − h·EA0C is what is seen
  const auto x = trajectory(m, "EX0C", kOffset, h);
  const auto b = trajectory(m, "EB0C", kOffset / h, h);
  double dy = 0.0, dx = 0.0, py = 0.0, px = 0.0;
  for (std::size_t k = 0; k < y.size(); ++k) {
    dy = std::max(dy, std::abs(y[k] - a[k]));
    dx = std::max(dx, std::abs(x[k] - b[k]));
    py = std::max(py, std::abs(y[k]));
    px = std::max(px, std::abs(x[k]));
  }
  INFO("EY0C vs EA0C: " << dy << " um of " << py << "; EX0C vs EB0C: " << dx << " um of " << px);
  CHECK(dy < 1e-3 * py);
  CHECK(dx < 1e-3 * px);
}

TEST_CASE("seed 000: null space at one height, full rank at two") {
  const Machine m = load_machine(kMachine);
  std::vector<std::string> names;
  for (const auto& p : kSeed) names.push_back(p.first);
  ErrorParameters truth;
  truth.set("EY0A", 0.018);
  truth.set("EZ0A", -0.012);
  truth.set("EB0A", 4e-5);
  truth.set("EC0A", -2.5e-5);
  truth.set("EX0C", 0.015);
  truth.set("EY0C", -0.022);
  truth.set("EA0C", 3e-5);
  truth.set("EB0C", -3.5e-5);
  BallbarPlanOptions o;
  o.heights_mm = {250.0, 300.0};
  std::vector<MeasurementSet> sets;
  std::uint64_t seed = 7;
  for (const auto& p : plan_ballbar_4axis(m, o)) sets.push_back(simulate(m, p.set, truth, {0.5, seed++}));

  SECTION("one height: two coupled pairs") {
    const IdentifyResult r = identify(m, {sets[0]}, names);
    CHECK(r.identifiability.rank == 6);
    REQUIRE(r.identifiability.null_space.size() == 2);
    auto weight = [](const NullDirection& d, const std::string& n) {
      for (const auto& [k, v] : d)
        if (k == n) return std::abs(v);
      return 0.0;
    };
    const auto& n0 = r.identifiability.null_space[0];  // EB0C pinned, with EX0C
    const auto& n1 = r.identifiability.null_space[1];  // EY0C ... order of kSeed: EA0C first
    // one direction couples EY0C and EA0C, the other EX0C and EB0C (column-scaled weights ~0.7)
    const bool ya = weight(n0, "EY0C") > 0.5 && weight(n0, "EA0C") > 0.5;
    const bool xb = weight(n1, "EX0C") > 0.5 && weight(n1, "EB0C") > 0.5;
    const bool ya1 = weight(n1, "EY0C") > 0.5 && weight(n1, "EA0C") > 0.5;
    const bool xb0 = weight(n0, "EX0C") > 0.5 && weight(n0, "EB0C") > 0.5;
    CHECK(((ya && xb) || (ya1 && xb0)));
    for (const auto& c : r.identifiability.combinations) printf("  one height: %s\n", c.c_str());
  }
  SECTION("two heights: full rank, truth recovered") {
    const IdentifyResult r = identify(m, sets, names);
    CHECK(r.identifiability.rank == 8);
    CHECK(r.identifiability.null_space.empty());
    for (const auto& n : names) {
      INFO(n << " " << *r.parameters.get(n) << " +- " << *r.uncertainty.get(n) << " truth " << *truth.get(n));
      CHECK(std::abs(*r.parameters.get(n) - *truth.get(n)) < 4.0 * *r.uncertainty.get(n));
    }
  }
}
