// SPDX-License-Identifier: Apache-2.0
// The seed-000 ballbar plan reproduces the public scenario's commands, and simulating it on the
// scenario's truth reproduces the recorded lengths within the noise.
#include <catch2/catch.hpp>

#include <cmath>

#include "ncpost/compensation/measurement_csv.hpp"
#include "ncpost/compensation/model_json.hpp"
#include "ncpost/compensation/plans.hpp"
#include "ncpost/compensation/simulate.hpp"
#include "ncpost/machines/machine_file.hpp"

using namespace ncpost;
using namespace ncpost::comp;

namespace {
const std::string kClean = std::string(NCPOST_SOURCE_DIR) + "/tests/data/scenarios/public-clean/";
}

TEST_CASE("ballbar-4axis plan reproduces the public scenario commands and lengths") {
  const Machine m = load_machine(kClean + "machine.toml");
  const ModelFile truth = read_model_json(kClean + "truth.json", &m);
  BallbarPlanOptions o;
  o.heights_mm = {250.0, 300.0};
  const auto plans = plan_ballbar_4axis(m, o);
  REQUIRE(plans.size() == 2);
  for (std::size_t h = 0; h < 2; ++h) {
    const MeasurementSet data = read_measurement_csv(kClean + (h == 0 ? "ballbar_h250.csv" : "ballbar_h300.csv"), m);
    const MeasurementSet& plan = plans[h].set;
    REQUIRE(plan.rows.size() == data.rows.size());
    CHECK((plan.table_ball_mm - data.table_ball_mm).norm() < 1e-9);
    double worst_cmd = 0.0, worst_t = 0.0;
    for (std::size_t k = 0; k < plan.rows.size(); ++k) {
      for (int a = 0; a < 5; ++a)
        worst_cmd = std::max(worst_cmd, std::abs(plan.rows[k].command[a] - data.rows[k].command[a]));
      worst_t = std::max(worst_t, std::abs(plan.rows[k].time_s - data.rows[k].time_s));
    }
    CHECK(worst_cmd < 1e-8);
    CHECK(worst_t < 1e-9);
    const MeasurementSet sim = simulate(m, plan, truth.parameters);
    double sum2 = 0.0, worst = 0.0;
    for (std::size_t k = 0; k < sim.rows.size(); ++k) {
      const double d = sim.rows[k].value[0] - data.rows[k].value[0];
      sum2 += d * d;
      worst = std::max(worst, std::abs(d));
    }
    const double rms_um = 1e3 * std::sqrt(sum2 / double(sim.rows.size()));
    INFO("height " << plans[h].name << ": rms " << rms_um << " um, max " << worst * 1e3 << " um");
    CHECK(rms_um < 0.8);
    CHECK(worst * 1e3 < 3.0);
  }
}

TEST_CASE("sphere plan reproduces the public scenario commands and deviations") {
  const Machine m = load_machine(kClean + "machine.toml");
  const ModelFile truth = read_model_json(kClean + "truth.json", &m);
  const MeasurementSet data = read_measurement_csv(kClean + "sphere.csv", m);
  SpherePlanOptions o;
  o.t0_s = 619.0;
  const auto plan = plan_sphere(m, o);
  REQUIRE(plan.size() == 1);
  REQUIRE(plan[0].set.rows.size() == data.rows.size());
  double worst_cmd = 0.0;
  for (std::size_t k = 0; k < data.rows.size(); ++k)
    for (int a = 0; a < 5; ++a)
      worst_cmd = std::max(worst_cmd, std::abs(plan[0].set.rows[k].command[a] - data.rows[k].command[a]));
  CHECK(worst_cmd < 1e-8);
  const MeasurementSet sim = simulate(m, plan[0].set, truth.parameters);
  double sum2 = 0.0;
  for (std::size_t k = 0; k < sim.rows.size(); ++k) sum2 += (sim.rows[k].value - data.rows[k].value).squaredNorm();
  const double rms_um = 1e3 * std::sqrt(sum2 / double(3 * sim.rows.size()));
  INFO("sphere rms " << rms_um << " um");
  CHECK(rms_um < 1.2);  // the probe noise of this file is about 0.85 um, without pattern
}

TEST_CASE("sphere residual by component (diagnostic)", "[.diag]") {
  const Machine m = load_machine(kClean + "machine.toml");
  const ModelFile truth = read_model_json(kClean + "truth.json", &m);
  const MeasurementSet data = read_measurement_csv(kClean + "sphere.csv", m);
  const MeasurementSet sim = simulate(m, data, truth.parameters);
  for (std::size_t k = 0; k < sim.rows.size(); k += 7) {
    const Eigen::Vector3d d = 1e3 * (data.rows[k].value - sim.rows[k].value);
    printf("%7.1f A%6.1f C%6.1f  %7.3f %7.3f %7.3f\n", data.rows[k].time_s, rad_to_deg(data.rows[k].command[3]),
           rad_to_deg(data.rows[k].command[4]), d.x(), d.y(), d.z());
  }
}
