// SPDX-License-Identifier: Apache-2.0
// Acceptance on the public clean scenario: identification from the two ballbar heights and the
// sphere recovers the truth, and the identified model predicts the truth's tool-tip deviations
// within 1 µm over the working space.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

#include "ncpost/compensation/identify.hpp"
#include "ncpost/compensation/measurement_csv.hpp"
#include "ncpost/compensation/machine_model.hpp"
#include "ncpost/compensation/model_json.hpp"
#include "ncpost/machines/machine_file.hpp"

using namespace ncpost;
using namespace ncpost::comp;

namespace {
const std::string kClean = std::string(NCPOST_SOURCE_DIR) + "/tests/data/scenarios/public-clean/";

void print(const IdentifyResult& r) {
  printf("rank %d of %d, %s\n", r.identifiability.rank, r.identifiability.parameters, r.message.c_str());
  printf("singular values:");
  for (Eigen::Index i = 0; i < r.rank.singular_values.size(); ++i) printf(" %.3g", r.rank.singular_values[i]);
  printf("\n");
  for (std::size_t i = 0; i < r.parameters.size(); ++i)
    printf("  %-8s %12.6g +- %.3g\n", r.parameters.names()[i].c_str(), r.parameters.values()[i],
           r.uncertainty.value_or(r.parameters.names()[i], 0.0));
  for (const auto& c : r.identifiability.combinations) printf("  %s\n", c.c_str());
  printf("rms %.3f um (nominal %.3f)\n", r.rms_after_um, r.rms_nominal_um);
}
}  // namespace

TEST_CASE("identify public-clean: diagnostics", "[.diag]") {
  const Machine m = load_machine(kClean + "machine.toml");
  std::vector<MeasurementSet> one{read_measurement_csv(kClean + "ballbar_h250.csv", m)};
  std::vector<MeasurementSet> two = one;
  two.push_back(read_measurement_csv(kClean + "ballbar_h300.csv", m));
  std::vector<MeasurementSet> all = two;
  all.push_back(read_measurement_csv(kClean + "sphere.csv", m));
  for (auto* sets : {&one, &two, &all}) print(identify(m, *sets, basic_parameters(m)));
}

TEST_CASE("identify public-clean: truth recovered, tool-tip prediction within 1 um") {
  const Machine m = load_machine(kClean + "machine.toml");
  const ModelFile truth = read_model_json(kClean + "truth.json", &m);
  std::vector<MeasurementSet> sets;
  for (const char* f : {"ballbar_h250.csv", "ballbar_h300.csv", "sphere.csv"})
    sets.push_back(read_measurement_csv(kClean + f, m));
  const IdentifyResult r = identify(m, sets, basic_parameters(m));
  REQUIRE(r.converged);
  // EA0A ≡ EA0C (exactly, through the set-up at home) and EC0C (invisible) are pinned.
  CHECK(r.identifiability.rank == 8);
  CHECK(r.identifiability.parameters == 10);
  CHECK(r.identifiability.pinned == std::vector<std::string>{"EA0A", "EC0C"});
  CHECK_FALSE(r.parameters.contains("EA0A"));
  CHECK_FALSE(r.parameters.contains("EC0C"));
  // every truth parameter within 4 standard uncertainties, and the residual at the noise
  for (const auto& name : truth.parameters.names()) {
    const double t = *truth.parameters.get(name);
    REQUIRE(r.parameters.contains(name));
    const double v = *r.parameters.get(name), u = *r.uncertainty.get(name);
    INFO(name << ": identified " << v << " +- " << u << ", truth " << t);
    CHECK(std::abs(v - t) < 4.0 * u + 1e-9);
  }
  CHECK(r.rms_after_um < 0.8);

  // Tool-tip deviations (actual − nominal) over the working space: truth vs identified model.
  const MachineModel actual(m, truth.parameters);
  const MachineModel identified(m, r.parameters);
  Setup setup;
  setup.workpiece_origin_mm = Vec3d(0, 0, 80);
  double worst_um = 0.0, worst_urad = 0.0, largest_error_um = 0.0;
  unsigned state = 12345u;
  auto uniform = [&state](double lo, double hi) {
    state = state * 1664525u + 1013904223u;
    return lo + (hi - lo) * double(state >> 8) / double(1u << 24);
  };
  for (int k = 0; k < 2000; ++k) {
    AxisPosition q = home_of(m);
    q.linear_mm = Vec3d(uniform(-250, 250), uniform(-250, 250), uniform(-150, 350));
    q.rotary_rad = Eigen::Vector2d(deg_to_rad(uniform(-10, 100)), deg_to_rad(uniform(-360, 360)));
    const auto pt = actual.tool_pose(q, setup);
    const auto pi = identified.tool_pose(q, setup);
    const auto pn = forward(m, q, setup);
    worst_um = std::max(worst_um, 1e3 * (pt.tip_mm - pi.tip_mm).norm());
    worst_urad = std::max(worst_urad, 1e6 * (pt.axis - pi.axis).norm());
    largest_error_um = std::max(largest_error_um, 1e3 * (pt.tip_mm - pn.tip_mm).norm());
  }
  INFO("largest tool-tip error of the truth " << largest_error_um << " um; prediction error " << worst_um
                                              << " um, axis " << worst_urad << " urad");
  printf(
      "public-clean: tool-tip error of the truth up to %.1f um; identified model off by at most %.3f um, "
      "%.3f urad\n",
      largest_error_um, worst_um, worst_urad);
  CHECK(worst_um < 1.0);
}
