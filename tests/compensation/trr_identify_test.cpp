// SPDX-License-Identifier: Apache-2.0
// Identification of the TRR-XY error parameters from simulated sphere probing (issue 8, beyond the
// seed), with the identifiability report, and the compensated post of a test path executed on the
// true machine: error before and after.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <fstream>
#include <random>
#include <regex>
#include <sstream>

#include "ncpost/compensation/trr_identify.hpp"
#include "ncpost/compensation/trr_model.hpp"
#include "ncpost/machines/trr_xy_file.hpp"
#include "test_paths.hpp"
#include "trr_program.hpp"

using namespace ncpost;
using namespace ncpost::trr;

namespace {

const Vec3d kOrigin(0.0, 0.0, -300.0);

Errors random_truth(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Errors e;
  for (int k = 0; k < kParameterCount; ++k) e[k] = u(rng) * (Errors::is_angle(k) ? 1e-4 : 0.03);
  return e;
}

/// A finishing path on the spec's test hemisphere (R 120 mm, tool normal, polar 5-30 deg): rings
/// of 72 points, as APT CL source.
std::string hemisphere_cl(std::vector<ClPoint>& points) {
  std::string s = "PARTNO/TRR TEST HEMISPHERE\nUNITS/MM\nMULTAX/ON\nFEDRAT/MMPM,1500\n";
  for (int ring = 1; ring <= 6; ++ring) {
    const double phi = deg_to_rad(5.0 * ring);
    for (int j = 0; j < 72; ++j) {
      const double a = deg_to_rad(5.0 * j);
      const Vec3d n(std::sin(phi) * std::cos(a), std::sin(phi) * std::sin(a), std::cos(phi));
      const Vec3d p = 120.0 * n;
      points.push_back({p, n});
      char buf[160];
      std::snprintf(buf, sizeof buf, "GOTO/%.4f,%.4f,%.4f,%.6f,%.6f,%.6f\n", p.x(), p.y(), p.z(), n.x(), n.y(), n.z());
      s += buf;
    }
  }
  return s + "FINI\n";
}

struct Execution {
  double max_end_mm = 0.0;     ///< at the block ends (the CL points)
  double max_normal_um = 0.0;  ///< largest |deviation along the surface normal| at the block ends
};

/// Runs the program on machine `k`; block i ends at CL point i (one block per CL motion).
Execution execute(const Kinematics& k, const std::vector<Command>& program, const std::vector<ClPoint>& cl) {
  Execution ex;
  REQUIRE(program.size() == cl.size());
  std::optional<Rigidd> warm;
  for (std::size_t i = 0; i < program.size(); ++i) {
    const Command& c = program[i];
    const auto tp = k.tool(c.slider_mm, warm);
    if (!tp) FAIL("forward kinematics failed");
    warm = tp->machine_T_plate;
    const Vec3d tip = Kinematics::tip_in_workpiece(*tp, c, kOrigin);
    ex.max_end_mm = std::max(ex.max_end_mm, (tip - cl[i].tip_mm).norm());
    ex.max_normal_um = std::max(ex.max_normal_um, 1000.0 * std::abs((tip - cl[i].tip_mm).dot(cl[i].axis)));
  }
  return ex;
}

}  // namespace

TEST_CASE("identify the 30 TRR-XY parameters from sphere probing, then compensate a hemisphere path") {
  const std::string machine_file = test::source("machines/trr-xy.toml");
  const trr::Machine m = load_trr_xy_machine(machine_file);
  const Errors truth = random_truth(2024);
  const Kinematics actual(m, truth), nominal(m);

  const std::vector<Vec3d> poses = probing_poses(m);
  REQUIRE(poses.size() == 3 * (1 + 3 * 12));
  const std::vector<ProbeMeasurement> data = simulate_probing(actual, poses, {0.0, 100.0}, 0.2, 7);
  const IdentifyResult id = identify(m, data);

  std::ostringstream report;
  report << "probing: " << poses.size() << " poses x 2 styli, noise 0.2 um; rank " << id.identifiability.rank << " of "
         << id.identifiability.parameters << "; residual rms " << id.rms_before_um << " -> " << id.rms_after_um
         << " um, max " << id.max_before_um << " -> " << id.max_after_um << " um; " << id.iterations << " iterations\n";
  report << "singular values (scaled):";
  for (double s : id.singular_values) report << " " << s / id.singular_values.front();
  report << "\nidentified (truth, value, standard deviation; mm or rad):\n";
  for (int k = 0; k < kParameterCount; ++k)
    report << " " << Errors::name(k) << " " << truth[k] << " " << id.errors[k] << " "
           << id.uncertainty[static_cast<std::size_t>(k)] << "\n";
  report << "null space:\n";
  for (const auto& dir : id.identifiability.null_space) {
    for (const auto& [name, w] : dir) report << " " << name << " " << w;
    report << "\n";
  }
  WARN(report.str());

  // the set-up at home hides some directions (e.g. dzs, see the sensitivity test): reported, not fitted
  CHECK(id.identifiability.rank < kParameterCount);
  CHECK(id.identifiability.null_space.size() == static_cast<std::size_t>(kParameterCount - id.identifiability.rank));
  bool dzs_in_null_space = false;
  for (const auto& dir : id.identifiability.null_space)
    for (const auto& [name, w] : dir)
      if (name.rfind("dzs_", 0) == 0 && std::abs(w) > 0.5) dzs_in_null_space = true;
  CHECK(dzs_in_null_space);
  CHECK(id.rms_before_um > 10.0);
  CHECK(id.rms_after_um < 0.3);  // at the noise level
  // where a parameter is determined, the truth lies within 4 standard deviations; dzs is not
  int determined = 0;
  for (int k = 0; k < kParameterCount; ++k) {
    const double sd = id.uncertainty[static_cast<std::size_t>(k)];
    if (Errors::name(k).rfind("dzs_", 0) == 0) CHECK(sd < 0.0);
    if (sd < 0.0) continue;
    ++determined;
    INFO(Errors::name(k));
    CHECK(std::abs(id.errors[k] - truth[k]) < 4.0 * sd);
  }
  CHECK(determined >= 6);

  // the identified model predicts the true machine at poses it was not fitted on
  const Kinematics model(m, id.errors);
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst_um = 0.0, worst_nominal_um = 0.0;
  for (int i = 0; i < 200; ++i) {
    const double tilt = deg_to_rad(30.0) * std::sqrt(u(rng)), az = 2 * kPi * u(rng);
    const ClPoint cl{Vec3d(0, 0, -180.0 - 200.0 * u(rng)),
                     Vec3d(std::sin(tilt) * std::cos(az), std::sin(tilt) * std::sin(az), std::cos(tilt))};
    const InverseOutcome ik = inverse(nominal, cl, Vec3d::Zero());
    REQUIRE(ik.ok());
    for (double L : {0.0, 100.0}) {
      const auto p_true = predicted_deviation(actual, nominal, ik.command->slider_mm, L);
      const auto p_model = predicted_deviation(model, nominal, ik.command->slider_mm, L);
      REQUIRE(p_true);
      REQUIRE(p_model);
      worst_um = std::max(worst_um, 1000.0 * (*p_true - *p_model).norm());
      worst_nominal_um = std::max(worst_nominal_um, 1000.0 * p_true->norm());
    }
  }
  WARN("validation poses: true machine vs nominal up to " << worst_nominal_um << " um, vs identified model up to "
                                                          << worst_um << " um");
  CHECK(worst_um < 1.5);
  CHECK(worst_nominal_um > 30.0);

  // the model file round trip and the compensated post of the hemisphere, executed on the truth
  comp::ModelFile file = model_from_errors(id.errors, m.name);
  file.identifiability = id.identifiability;
  for (int k = 0; k < kParameterCount; ++k)
    if (id.uncertainty[static_cast<std::size_t>(k)] >= 0.0)
      file.uncertainty.set(Errors::name(k), id.uncertainty[static_cast<std::size_t>(k)]);
  std::ofstream("trr_identified.json") << comp::format_model_json(file);
  std::vector<ClPoint> cl;
  std::ofstream("trr_hemisphere.cls") << hemisphere_cl(cl);
  const std::string base = std::string(NCPOST_BINARY) + " post --machine " + machine_file +
                           " --workpiece-origin 0,0,-300 --tolerance none ";  // one block per CL point
  REQUIRE(std::system((base + "-o trr_before.nc trr_hemisphere.cls 2>/dev/null").c_str()) == 0);
  REQUIRE(std::system((base + "--model trr_identified.json -o trr_after.nc trr_hemisphere.cls 2>/dev/null").c_str()) ==
          0);
  const Execution before = execute(actual, test::read_trr_program("trr_before.nc"), cl);
  const Execution after = execute(actual, test::read_trr_program("trr_after.nc"), cl);
  WARN("hemisphere on the true machine: before " << before.max_end_mm * 1000 << " um (normal " << before.max_normal_um
                                                 << " um), after compensation " << after.max_end_mm * 1000
                                                 << " um (normal " << after.max_normal_um << " um)");
  CHECK(before.max_end_mm > 0.02);
  CHECK(after.max_end_mm < 0.0015);
  CHECK(after.max_end_mm < before.max_end_mm / 20.0);
}
