// SPDX-License-Identifier: Apache-2.0
// Adaptive subdivision on an actual machine (geometric errors through the error hook, IK of the
// actual machine): the dome path's output blocks, re-executed on that machine, stay within 5 um of
// the CL segments, and the inserted points are on the CL segment.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "ncpost/compensation/actual_ik.hpp"
#include "ncpost/compensation/adaptive_ideal.hpp"
#include "ncpost/compensation/machine_model.hpp"
#include "ncpost/compensation/model_json.hpp"
#include "nonlinear_test_support.hpp"

using namespace ncpost;
using namespace ncpost::nonlinear;

namespace {

/// What adaptive subdivision of the dome path at 5 µm gives on a machine with errors.
struct DomeRun {
  int blocks = 0, output = 0;
  double before = 0, after = 0;  ///< largest error of the input blocks, of the output (re-executed), mm
  double endpoint = 0;           ///< largest distance of a block end from its CL point, mm
  double tolerance = 0;
};

/// Solves each GOTO of the dome path with `solver`, subdivides every feed block to 5 µm and
/// re-executes the output on the machine `errors` describe.
template <class Errors, class Solver>
DomeRun subdivide_dome(const Machine& m, const Setup& s, const Errors& errors, const Solver& solver) {
  const auto path = test::read_gotos(test::dome_path());
  AxisPosition previous = home_of(m);
  AdaptiveOptions o;
  o.tolerance_mm = 0.005;
  DomeRun r;
  r.tolerance = o.tolerance_mm;
  for (std::size_t i = 0; i < path.size(); ++i) {
    const IkOutcome ik = solver(path[i].point, previous);
    REQUIRE(ik.ok());
    r.endpoint =
        std::max(r.endpoint, (tool_pose<double>(m, *ik.position, s, errors).tip_mm - path[i].point.tip_mm).norm());
    if (i > 0 && !path[i].rapid) {
      const ClBlock b{path[i - 1].point, path[i].point, previous, *ik.position};
      const SplitBlock split = subdivide_adaptive(m, s, b, errors, solver, o);
      REQUIRE(split.ok());
      SplitBlock check = split;
      verify_split(m, s, b, check, errors);
      ++r.blocks;
      r.output += split.output_blocks();
      r.before = std::max(r.before, split.input_error_mm);
      r.after = std::max(r.after, check.max_error_mm);
    }
    previous = *ik.position;
  }
  return r;
}

}  // namespace

TEST_CASE("adaptive subdivision with an error model (dome path)", "[adaptive][model]") {
  const Machine m = load_machine(std::string(NCPOST_SOURCE_DIR) + "/tests/data/scenarios/public-clean/machine.toml");
  const Setup s = test::dome_setup();
  const test::LocationErrors errors;
  const test::ModelSolver<test::LocationErrors> solver{m, s, errors};
  const DomeRun r = subdivide_dome(m, s, errors, solver);
  fmt::print(
      "adaptive on the machine with errors, dome, 0.005 mm: {} -> {} blocks, largest error {:.4f} -> {:.5f} mm, "
      "block ends {:.2e} mm\n",
      r.blocks, r.output, r.before, r.after, r.endpoint);
  CHECK(r.endpoint < 1e-8);
  CHECK(r.after <= r.tolerance);
}

TEST_CASE("adaptive subdivision with the project's error model and compensated IK (truth.json)", "[adaptive][model]") {
  const std::string scenario = std::string(NCPOST_SOURCE_DIR) + "/tests/data/scenarios/public-clean/";
  const Machine m = load_machine(scenario + "machine.toml");
  const Setup s = test::dome_setup();
  const comp::ModelFile file = comp::read_model_json(scenario + "truth.json", &m);
  const comp::MachineModel model(m, file.parameters);
  const auto errors = model.errors();
  auto solver = [&](const ClPoint& cl, const AxisPosition& previous) {
    IkOutcome o = solve(m, cl, s, previous);
    if (!o.ok()) return o;
    const comp::ActualIkOutcome a = comp::solve_actual(model, cl, s, *o.position);
    if (!a.ok()) {
      o.position.reset();
      o.failure.message = a.message;
    } else {
      o.position = a.position;
    }
    return o;
  };
  const DomeRun r = subdivide_dome(m, s, errors, solver);
  fmt::print(
      "adaptive with truth.json and solve_actual, dome, 0.005 mm: {} -> {} blocks, largest error {:.4f} -> "
      "{:.5f} mm (block ends {:.2e} mm)\n",
      r.blocks, r.output, r.before, r.after, r.endpoint);
  CHECK(r.endpoint < 1e-5);  // solve_actual converges to well below the 0.1 µm word resolution
  CHECK(r.after <= r.tolerance);
}
