// Adaptive subdivision on an actual machine (geometric errors through the error hook, IK of the
// actual machine): the dome path's output blocks, re-executed on that machine, stay within 5 um of
// the CL segments, and the inserted points are on the CL segment.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "ncpost/compensation/adaptive_ideal.hpp"
#include "nonlinear_test_support.hpp"

using namespace ncpost;
using namespace ncpost::nonlinear;

TEST_CASE("adaptive subdivision with an error model (dome path)", "[adaptive][model]") {
  const Machine m = load_machine(std::string(NCPOST_SHARED_DIR) + "/data/scenarios/public-clean/machine.toml");
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
