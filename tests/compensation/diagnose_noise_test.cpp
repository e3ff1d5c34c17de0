// SPDX-License-Identifier: Apache-2.0
// No false positives (issue 6): data sets whose only errors are those of the basic model (the
// location errors of public-clean's truth.json), simulated as `ncpost simulate` does with
// several noise seeds and levels: residual analysis adds nothing.
#include <catch2/catch.hpp>

#include "diagnose_support.hpp"

using namespace ncpost;
using namespace ncpost::comp;

TEST_CASE("diagnose: noise-only data sets add nothing", "[diagnose][noise]") {
  const Machine m = test::public_machine();
  const ErrorParameters truth = test::truth_with(m, {});
  const std::pair<double, std::uint64_t> runs[] = {{0.5, 11}, {0.5, 2026}, {0.5, 31337}, {2.0, 4242}};
  for (const auto& [noise_um, seed] : runs) {
    const std::string title = "noise " + std::to_string(noise_um) + " um, seed " + std::to_string(seed);
    const DiagnoseResult d = test::run_diagnose(title.c_str(), m, test::simulated_sets(m, truth, noise_um, seed));
    INFO(title);
    CHECK(d.effects_added().empty());
    CHECK(d.final_fit.rms_after_um < 1.1 * noise_um);
    // the noise level the data show (successive differences) is the simulated one
    CHECK(d.noise_um == Approx(noise_um).epsilon(0.15));
  }
}
