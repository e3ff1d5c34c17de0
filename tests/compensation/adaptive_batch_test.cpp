// SPDX-License-Identifier: Apache-2.0
// compensate_blocks on two threads gives the same output blocks as one block at a time.
#include <catch2/catch.hpp>

#include "ncpost/compensation/nonlinear_batch.hpp"
#include "nonlinear_test_support.hpp"

using namespace ncpost;
using namespace ncpost::nonlinear;
using ncpost::nonlinear::NominalSolver;  // (ncpost::NominalSolver is the post's)

TEST_CASE("compensate_blocks: two threads, same result", "[adaptive][batch]") {
  const Machine m = load_machine(std::string(NCPOST_SOURCE_DIR) + "/tests/data/scenarios/public-clean/machine.toml");
  const Setup s = test::dome_setup();
  const auto blocks = test::blocks_of(m, s, test::read_gotos(test::dome_path()));
  const NominalSolver solver{m, s};
  for (Method method : {Method::adaptive, Method::harmonic}) {
    CompensationOptions o;
    o.method = method;
    o.tolerance_mm = 0.005;
    const auto parallel = compensate_blocks(m, s, blocks, NominalErrors{}, solver, o, 2);
    REQUIRE(parallel.size() == blocks.size());
    for (std::size_t i = 0; i < blocks.size(); i += 7) {
      NominalSolver local = solver;
      const SplitBlock one = compensate_block(m, s, blocks[i], NominalErrors{}, local, o);
      REQUIRE(one.nodes.size() == parallel[i].nodes.size());
      for (std::size_t k = 0; k < one.nodes.size(); ++k)
        CHECK(one.nodes[k].q.linear_mm == parallel[i].nodes[k].q.linear_mm);
      CHECK(one.max_error_mm == parallel[i].max_error_mm);
    }
  }
}
