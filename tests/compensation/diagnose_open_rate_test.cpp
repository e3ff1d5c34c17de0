// SPDX-License-Identifier: Apache-2.0
// Issue 17: how often the open-ended diagnosis attributes something that is not there.
//  - noise-only sets (public-clean's location errors, nothing else; 20 seeds): any effect added or
//    any structure reported unexplained is a false attribution. Each step tests at a family-wise
//    rate of 1e-3 (Bonferroni over ~100-250 candidates) and the structure test at 1e-3 (Bonferroni
//    over its columns), so the expected rate is about 2e-3 per set: over 20 sets, 0 expected;
//    allowing 1 keeps the test from failing by chance (P(≥ 2 | rate 2e-3) < 1e-3), and a rate of
//    one set in five or worse fails (P(≤ 1 | 20, 0.2) = 7 %). The rate itself, over 50 sets of
//    each kind, is measured by bench/run_diagnose_full.sh (the hidden [sweep] case below); the
//    suite ran 50 sets here before (37 s), cut to 20 to keep the test command short (issue 26).
//  - wrong-model sets: an effect outside every family of the model, a three-per-revolution
//    angular error of C whose amplitude grows with A (3 seeds, one ballbar of 200 rows and the
//    sphere every 30°, to keep the time): any effect added is a false attribution (the closest-
//    looking term, e.g. ECC:h3 at the mean amplitude); what is left beyond the noise must be
//    reported as unexplained, with its signature.
//  - the sweep over many sets (hidden, `[sweep]`; NCPOST_SWEEP_SETS sets of each kind, 20 unless
//    given): the same counts, printed; the README gives its figures.
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cstdlib>

#include "diagnose_open_support.hpp"

using namespace ncpost;
using namespace ncpost::test;

TEST_CASE("False-attribution rate over noise-only sets", "[diagnose][open][rate]") {
  const Machine m = public_machine();
  const auto plans = open_plan(m, 30.0, 100, false);
  const comp::ErrorParameters truth = truth_with(m, {});
  int false_sets = 0, unexplained_sets = 0;
  const int seeds = 20;
  const auto t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < seeds; ++k) {
    const auto sets = simulate_plan(m, plans, truth, 0.5, 1000 + 37 * static_cast<std::uint64_t>(k));
    const comp::DiagnoseResult d = comp::diagnose(m, sets, comp::basic_parameters(m));
    if (!d.added.empty()) {
      ++false_sets;
      std::printf("  seed %d: added %s (p %.3g)\n", 1000 + 37 * k, d.added.front().candidate.effect.c_str(),
                  d.added.front().p_value);
    }
    if (!d.unexplained.empty()) {
      ++unexplained_sets;
      std::printf("  seed %d: unexplained %s %s vs %c (p %.3g)\n", 1000 + 37 * k, d.unexplained.front().file.c_str(),
                  d.unexplained.front().value.c_str(), d.unexplained.front().axis, d.unexplained.front().p_value);
    }
  }
  const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("noise-only: %d of %d sets with an effect added, %d with structure reported unexplained (%.1f s)\n",
              false_sets, seeds, unexplained_sets, sec);
  CHECK(false_sets + unexplained_sets <= 1);
}

namespace {

struct Counts {
  int sets = 0, added = 0, wrong = 0, unexplained = 0;
};

/// Runs the diagnosis on `sets` of one kind; counts the sets with an effect added and those with
/// structure reported unexplained.
/// `truth_family`: the prefix of the effects that are the truth's own component (e.g. "ECC:h3"
/// for an error of C growing with A: its mean amplitude; "" for noise-only data); an effect added
/// outside it is a false attribution (`wrong`).
template <class Make>
Counts count_attributions(const char* kind, int n, const Make& make, bool verbose,
                          const std::string& truth_family = "") {
  Counts c;
  for (int k = 0; k < n; ++k) {
    const auto sets = make(k);
    const comp::DiagnoseResult d = comp::diagnose(public_machine(), sets, comp::basic_parameters(public_machine()));
    ++c.sets;
    if (!d.added.empty()) ++c.added;
    if (std::any_of(d.added.begin(), d.added.end(), [&](const comp::AddedEffect& e) {
          return truth_family.empty() || e.candidate.effect.rfind(truth_family, 0) != 0;
        }))
      ++c.wrong;
    if (!d.unexplained.empty()) ++c.unexplained;
    if (verbose || !d.added.empty()) {
      std::printf("  %s %d: rms %.3f -> %.3f um, added [", kind, k, d.basic.rms_after_um, d.final_fit.rms_after_um);
      for (const auto& e : d.added) std::printf(" %s", e.candidate.effect.c_str());
      std::printf(" ], not attributed [");
      for (const auto& e : d.not_attributed) std::printf(" %s", e.c_str());
      std::printf(" ]");
      if (!d.unexplained.empty())
        std::printf(", unexplained: %s %s vs %c: %s", d.unexplained.front().file.c_str(),
                    d.unexplained.front().value.c_str(), d.unexplained.front().axis,
                    d.unexplained.front().shape.c_str());
      std::printf("\n");
    }
  }
  std::printf("%s: %d of %d sets with an effect added, %d with a false one, %d with structure reported unexplained\n",
              kind, c.added, c.sets, c.wrong, c.unexplained);
  return c;
}

}  // namespace

TEST_CASE("Wrong-model sets: an error of C whose amplitude grows with A is reported, not attributed",
          "[diagnose][open][rate]") {
  const Machine m = public_machine();
  const auto plans = open_plan(m, 30.0, 200, false);
  const comp::ErrorParameters truth = truth_with(m, {});
  // 30 µrad of ECC:h3 per rad of A: 47 µrad at A = 90°
  const Counts c = count_attributions(
      "ECC:h3 growing with A", 3,
      [&](int k) {
        return simulate_h3_growing_with_a(m, plans, truth, 30e-6, 0.5, 500 + 11 * static_cast<std::uint64_t>(k));
      },
      true, "ECC:h3");
  // measured (3 seeds): ECC:h3 at the mean amplitude in 3 of 3, structure reported in 1 of 3; an
  // effect of another component or axis (a false attribution) in none
  CHECK(c.wrong == 0);
  CHECK(c.unexplained >= 1);
}

// Item 2 of issue 17: the sphere keeps structure nothing explains (the error of C growing with A);
// the ballbar, at the noise once the squareness is in, is the squareness's own evidence: it is
// kept, what chased the structure is not attributed, and the structure is reported.
TEST_CASE("A true effect beside an unexplained one is kept, the unexplained one reported", "[diagnose][open][rate]") {
  const Machine m = public_machine();
  const auto plans = open_plan(m, 30.0, 200, false);
  comp::ErrorParameters extra;
  extra.set("EC0Y", 30e-6);  // squareness of Y to X: 30 µrad, a signature of its own on the ballbar
  const comp::ErrorParameters truth = truth_with(m, extra);
  const auto sets = simulate_h3_growing_with_a(m, plans, truth, 30e-6, 0.5, 500);
  const comp::DiagnoseResult d = run_diagnose("EC0Y beside ECC:h3 growing with A", m, sets);
  for (const auto& n : d.not_attributed) std::printf("  not attributed: %s\n", n.c_str());
  for (const auto& u : d.unexplained)
    std::printf("  unexplained: %s %s vs %c: %s\n", u.file.c_str(), u.value.c_str(), u.axis, u.shape.c_str());
  // kept: the squareness (its own evidence) and at most C's angular error of order 3 (the
  // truth's component and order at its mean amplitude over A), nothing else
  REQUIRE(has_effect(d, "EC0Y"));
  for (const auto& e : d.added) CHECK((e.candidate.effect == "EC0Y" || e.candidate.effect == "ECC:h3"));
  CHECK(std::abs(*d.final_fit.parameters.get("EC0Y") - 30e-6) < 4.0 * *d.final_fit.uncertainty.get("EC0Y"));
  CHECK_FALSE(d.unexplained.empty());
  CHECK(false_terms(d).empty());
}

TEST_CASE("False-attribution sweep over many noise-only and wrong-model sets", "[.][sweep]") {
  const Machine m = public_machine();
  const char* env = std::getenv("NCPOST_SWEEP_SETS");
  const int n = env ? std::max(1, std::atoi(env)) : 20;
  const auto plans = open_plan(m, 30.0, 200, false);
  const comp::ErrorParameters truth = truth_with(m, {});
  const auto t0 = std::chrono::steady_clock::now();
  const Counts noise = count_attributions(
      "noise-only", n,
      [&](int k) { return simulate_plan(m, plans, truth, 0.5, 7000 + 37 * static_cast<std::uint64_t>(k)); }, false);
  const Counts wrong = count_attributions(
      "ECC:h3 growing with A", n,
      [&](int k) {
        return simulate_h3_growing_with_a(m, plans, truth, 30e-6, 0.5, 9000 + 11 * static_cast<std::uint64_t>(k));
      },
      false, "ECC:h3");
  const Counts coupled = count_attributions(
      "C tilt growing with A (in the model: EA0C:A:p1)", n,
      [&](int k) {
        return simulate_coupled_tilt(m, plans, truth, 40e-6, 0.5, 11000 + 13 * static_cast<std::uint64_t>(k));
      },
      false, "EA0C:A:p1");
  std::printf(
      "sweep of %d sets each (%.0f s): noise-only %d added / %d unexplained; ECC:h3 growing with A %d added "
      "(%d false) / %d unexplained; coupled tilt %d added (%d false) / %d unexplained\n",
      n, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), noise.added, noise.unexplained,
      wrong.added, wrong.wrong, wrong.unexplained, coupled.added, coupled.wrong, coupled.unexplained);
  CHECK(noise.added + noise.unexplained <= std::max(2, n / 25));
  CHECK(wrong.wrong == 0);
  CHECK(coupled.wrong == 0);
}
