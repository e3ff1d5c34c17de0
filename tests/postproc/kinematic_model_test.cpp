// SPDX-License-Identifier: Apache-2.0
// The kinematic model interface (kinematics/kinematic_model.hpp, issue 16 item 1): the inverse
// with all its branches and the error hook, on the serial chain, the serial chain with an error
// model (ActualSolver) and the TRR-XY machine; and the layering: kinematics/ includes nothing of
// postproc/ or compensation/ (the error model implements the interface from above).
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "ncpost/compensation/model_json.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/machines/trr_xy_file.hpp"
#include "ncpost/postproc/solve/actual_solver.hpp"
#include "ncpost/postproc/solve/trr_solver.hpp"
#include "test_paths.hpp"

using namespace ncpost;

namespace {

/// NX's CLSF point of the README's worked example (tool axis tipped 22.2° toward −X), in mm.
ClPoint umc750_point() {
  return ClPoint{Vec3d(-4.2721, -3.0148, 3.0) * 25.4, Vec3d(-0.3778015, -0.0069217, 0.9258607).normalized()};
}

}  // namespace

TEST_CASE("kinematic model: the serial chain gives both branches, each on the CL point", "[kinematic_model]") {
  const Machine m = load_machine(test::source("machines/haas-umc750.toml"));
  const Setup setup{Vec3d(0, 0, 0), 0.0};
  const SerialChainModel model(m, setup);
  const KinematicModel& k = model;
  SolverData data;
  const ClPoint cl = umc750_point();
  const std::vector<AxisPosition> all = k.branches(cl, AxisPosition{}, data);
  REQUIRE(all.size() == 2);
  // README: (B −22.2015°, C 1.0496°) moves least from home, then (B +22.2015°, C −178.9504°)
  CHECK(rad_to_deg(all[0][3]) == Approx(-22.2015).margin(1e-4));
  CHECK(rad_to_deg(all[0][4]) == Approx(1.0496).margin(1e-4));
  CHECK(rad_to_deg(all[1][3]) == Approx(22.2015).margin(1e-4));
  CHECK(rad_to_deg(all[1][4]) == Approx(-178.9504).margin(1e-4));
  for (const AxisPosition& q : all) {
    const ToolPoseT<double> pose = k.execute(q, data);
    CHECK((pose.tip_mm - cl.tip_mm).norm() < 1e-9);
    CHECK((pose.axis - cl.axis).norm() < 1e-9);
    // the nominal chain has no error
    CHECK(k.deviation(q, data).tip_mm.norm() == 0.0);
  }
  // solve() chooses the first branch
  const IkOutcome chosen = k.solve(cl, AxisPosition{}, data);
  REQUIRE(chosen.ok());
  CHECK((chosen.position->rotary_rad - all[0].rotary_rad).norm() < 1e-12);
}

TEST_CASE("kinematic model: the chain with an error model compensates every branch; its error hook",
          "[kinematic_model]") {
  const Machine m = load_machine(test::data("scenarios/public-clean/machine.toml"));
  const comp::MachineModel truth(m,
                                 comp::read_model_json(test::data("scenarios/public-clean/truth.json"), &m).parameters);
  const Setup setup{Vec3d(0, 0, 80), 0.0};
  const ActualSolver actual(truth, setup);
  const SerialChainModel nominal(m, setup);
  const KinematicModel& k = actual;
  const ClPoint cl{Vec3d(20, -10, 5), Vec3d(0.2, 0.3, 0.9).normalized()};
  SolverData data;
  const std::vector<AxisPosition> nominal_branches = nominal.branches(cl, AxisPosition{}, data);
  const std::vector<AxisPosition> actual_branches = k.branches(cl, AxisPosition{}, data);
  REQUIRE(!nominal_branches.empty());
  REQUIRE(actual_branches.size() == nominal_branches.size());
  for (std::size_t i = 0; i < actual_branches.size(); ++i) {
    const AxisPosition& q = actual_branches[i];
    CHECK(actual.reaches(cl, q, std::nullopt));                        // on the CL point on the actual machine
    CHECK_FALSE(nominal.execute(q).tip_mm.isApprox(cl.tip_mm, 1e-9));  // not on the nominal one
    // near its nominal branch: the compensation is tens of µm, not another solution
    CHECK((q.linear_mm - nominal_branches[i].linear_mm).norm() < 1.0);
    CHECK((q.rotary_rad - nominal_branches[i].rotary_rad).norm() < 0.01);
    // the error hook: the actual pose less the nominal one
    const ToolPoseT<double> e = k.deviation(q, data);
    CHECK((e.tip_mm - (k.execute(q, data).tip_mm - nominal.execute(q).tip_mm)).norm() < 1e-12);
    CHECK(e.tip_mm.norm() > 1e-3);  // the truth's errors: tens of µm
  }
}

TEST_CASE("kinematic model: the TRR-XY machine's one branch and its error hook", "[kinematic_model][trr]") {
  const trr::Machine machine = load_trr_xy_machine(test::source("machines/trr-xy.toml"));
  const trr::Kinematics nominal(machine);
  const TrrSolver model(nominal, nominal, Vec3d(0.0, 0.0, -300.0));
  const KinematicModel& k = model;
  SolverData data;
  const ClPoint cl{Vec3d(5, -3, 2), Vec3d(0.05, -0.08, 1.0).normalized()};
  const std::vector<AxisPosition> all = k.branches(cl, AxisPosition{}, data);
  REQUIRE(all.size() == 1);
  const ToolPoseT<double> pose = k.execute(all[0], data);
  CHECK((pose.tip_mm - cl.tip_mm).norm() < 1e-6);
  CHECK(k.deviation(all[0], data).tip_mm.norm() == 0.0);  // executed on the machine it was solved for
  CHECK(k.words().count == 5);
  // five lengths: none of a serial chain's capabilities (command_words.hpp)
  const CommandWords w = k.words();
  CHECK_FALSE(w.angles_are_programmed);
  CHECK_FALSE(w.cutter_comp_supported);
  CHECK_FALSE(w.tilted_plane_capable);
  CHECK_FALSE(w.branches_chosen);
  CHECK_FALSE(w.limits_name_the_axis);
}

TEST_CASE("kinematic model: kinematics/ includes nothing of postproc/ or compensation/",
          "[kinematic_model][layering]") {
  int files = 0;
  for (const char* dir : {"kinematics/include", "kinematics/src"}) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(test::source(dir))) {
      if (!entry.is_regular_file()) continue;
      std::ifstream in(entry.path());
      std::ostringstream text;
      text << in.rdbuf();
      INFO(entry.path().string());
      CHECK(text.str().find("ncpost/postproc/") == std::string::npos);
      CHECK(text.str().find("ncpost/compensation/") == std::string::npos);
      CHECK(text.str().find("ncpost/machines/") == std::string::npos);
      ++files;
    }
  }
  CHECK(files > 10);
}
