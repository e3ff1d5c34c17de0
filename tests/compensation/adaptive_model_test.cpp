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

TEST_CASE("adaptive subdivision with an error model (dome path)", "[adaptive][model]") {
  const Machine m = load_machine(std::string(NCPOST_SOURCE_DIR) + "/tests/data/scenarios/public-clean/machine.toml");
  const Setup s = test::dome_setup();
  const test::LocationErrors errors;
  const test::ModelSolver<test::LocationErrors> solver{m, s, errors};
  const auto path = test::read_gotos(test::dome_path());
  AxisPosition previous;
  AdaptiveOptions o;
  o.tolerance_mm = 0.005;
  int blocks = 0, output = 0;
  double before = 0, after = 0, endpoint = 0;
  for (std::size_t i = 0; i < path.size(); ++i) {
    const IkOutcome ik = solver(path[i].point, previous);
    REQUIRE(ik.ok());
    endpoint = std::max(endpoint, (tool_pose<double>(m, *ik.position, s, errors).tip_mm - path[i].point.tip_mm).norm());
    if (i > 0 && !path[i].rapid) {
      const ClBlock b{path[i - 1].point, path[i].point, previous, *ik.position};
      const SplitBlock split = subdivide_adaptive(m, s, b, errors, solver, o);
      REQUIRE(split.ok());
      SplitBlock check = split;
      verify_split(m, s, b, check, errors);
      ++blocks;
      output += split.output_blocks();
      before = std::max(before, split.input_error_mm);
      after = std::max(after, check.max_error_mm);
    }
    previous = *ik.position;
  }
  fmt::print("adaptive on the machine with errors, dome, 0.005 mm: {} -> {} blocks, largest error {:.4f} -> {:.5f} mm, "
             "block ends {:.2e} mm\n", blocks, output, before, after, endpoint);
  CHECK(endpoint < 1e-8);
  CHECK(after <= o.tolerance_mm);
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
  const auto path = test::read_gotos(test::dome_path());
  AxisPosition previous;
  AdaptiveOptions o;
  o.tolerance_mm = 0.005;
  int blocks = 0, output = 0;
  double before = 0, after = 0;
  for (std::size_t i = 0; i < path.size(); ++i) {
    const IkOutcome ik = solver(path[i].point, previous);
    REQUIRE(ik.ok());
    if (i > 0 && !path[i].rapid) {
      const ClBlock b{path[i - 1].point, path[i].point, previous, *ik.position};
      const SplitBlock split = subdivide_adaptive(m, s, b, errors, solver, o);
      REQUIRE(split.ok());
      SplitBlock check = split;
      verify_split(m, s, b, check, errors);
      ++blocks;
      output += split.output_blocks();
      before = std::max(before, split.input_error_mm);
      after = std::max(after, check.max_error_mm);
    }
    previous = *ik.position;
  }
  fmt::print("adaptive with truth.json and solve_actual, dome, 0.005 mm: {} -> {} blocks, largest error {:.4f} -> "
             "{:.5f} mm\n", blocks, output, before, after);
  CHECK(after <= o.tolerance_mm);
}
