// SPDX-License-Identifier: Apache-2.0
// The paper's harmonic compensation realised as NC blocks (harmonic_compensation.hpp): on the seed
// 001 segment (BV100) and on the public dome path, blocks added and the largest remaining error,
// verified by re-execution.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "ncpost/compensation/harmonic_compensation.hpp"
#include "nonlinear_test_support.hpp"

using namespace ncpost;
using namespace ncpost::nonlinear;

TEST_CASE("harmonic compensation of the seed 001 segment", "[harmonic][seed001]") {
  const Machine m = test::machine_file("bv100.toml");
  const Setup s;
  const ClBlock b = test::seed001_block(m, s);
  for (double tolerance : {0.1, 0.005}) {
    HarmonicOptions o;
    o.tolerance_mm = tolerance;
    const SplitBlock split = harmonic_compensate(m, s, b, NominalErrors{}, o);
    REQUIRE(split.ok());
    fmt::print(
        "harmonic, seed 001, tolerance {} mm: {} output blocks ({} added), largest remaining error {:.4f} mm, "
        "orientation {:.4f} deg\n",
        tolerance, split.output_blocks(), split.inserted_blocks(), split.max_error_mm,
        rad_to_deg(split.max_orientation_rad));
    CHECK(split.max_error_mm < 0.15);
    CHECK(split.nodes.back().q.rotary_rad == b.to.rotary_rad);
  }
  // the paper's own setting: shifted points at its 22 interpolation intervals
  HarmonicOptions dense;
  dense.fixed_blocks = 22;
  dense.fit = HarmonicFit::peak;
  const SplitBlock split = harmonic_compensate(m, s, b, NominalErrors{}, dense);
  fmt::print("harmonic, seed 001, 22 shifted points (peak fit): largest remaining error {:.4f} mm (paper 0.0961)\n",
             split.max_error_mm);
  CHECK(split.max_error_mm == Approx(0.0961).margin(0.01));
}

TEST_CASE("harmonic compensation of the dome path", "[harmonic][dome]") {
  const Machine m = load_machine(std::string(NCPOST_SOURCE_DIR) + "/tests/data/scenarios/public-clean/machine.toml");
  const Setup s = test::dome_setup();
  const auto blocks = test::blocks_of(m, s, test::read_gotos(test::dome_path()));
  HarmonicOptions o;
  o.tolerance_mm = 0.005;
  int output = 0;
  double before = 0, after = 0;
  for (const ClBlock& b : blocks) {
    const SplitBlock split = harmonic_compensate(m, s, b, NominalErrors{}, o);
    REQUIRE(split.ok());
    output += split.output_blocks();
    before = std::max(before, nonlinear_error(m, s, b).max_error_mm);
    after = std::max(after, split.max_error_mm);
  }
  fmt::print("harmonic, dome path, tolerance 0.005 mm: {} blocks -> {} ({} added); largest error {:.4f} -> {:.4f} mm\n",
             blocks.size(), output, output - int(blocks.size()), before, after);
  CHECK(after < before);
}
