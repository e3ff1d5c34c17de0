// SPDX-License-Identifier: Apache-2.0
// The error model's own bow inside a block (adaptive_subdivision.hpp `model_bow_mm`, issue 17):
// on a three-axis machine whose X axis has a quadratic straightness error EY(x) = c·x², a straight
// X move compensated at its ends still bows by c·(L/2)² between them — across the segment only;
// a positioning error along the move bows nothing across it. The subdivision cuts such a block to
// the model bow's own bound even where the tolerance alone lets it through.
#include <catch2/catch.hpp>

#include "ncpost/compensation/actual_ik.hpp"
#include "ncpost/compensation/adaptive_subdivision.hpp"
#include "ncpost/compensation/machine_model.hpp"
#include "ncpost/kinematics/inverse.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "test_paths.hpp"
#include "vmcl600_setup.hpp"

using namespace ncpost;
using namespace ncpost::nonlinear;

namespace {

ClPoint at(double x, double y, double z) {
  ClPoint p;
  p.tip_mm = Vec3d(x, y, z);
  return p;
}

comp::MachineModel model_with(const Machine& m, const std::string& name, double value) {
  comp::ErrorParameters p;
  p.set(name, value);
  return comp::MachineModel(m, p);
}

}  // namespace

TEST_CASE("the error model's own bow: across the segment, c·(L/2)² for a quadratic straightness", "[adaptive][model]") {
  const Machine m = load_machine(test::source("machines/vmcl600.toml"));
  const Setup s = test::vmcl600_setup();
  const double c = 4e-8;  // 1/mm: EY(x) = c·x²
  const ClBlock block{at(-150, 20, 10), at(150, 20, 10), *solve(m, at(-150, 20, 10), s, {}).position,
                      *solve(m, at(150, 20, 10), s, {}).position};
  const comp::MachineModel straightness = model_with(m, "EYX:p2", c);
  // the chord of d between x = ±150 is c·150², d at the middle 0 (sampled at t = 1/2 exactly)
  CHECK(model_bow_mm(m, s, block, straightness.errors()) == Approx(c * 150 * 150).epsilon(1e-6));
  // the same curve in the positioning error bows along the move: the tip is early or late only
  const comp::MachineModel positioning = model_with(m, "EXX:p2", c);
  CHECK(model_bow_mm(m, s, block, positioning.errors()) < 1e-12);
  // the nominal machine has none
  CHECK(model_bow_mm(m, s, block, NominalErrors{}) == 0.0);
}

TEST_CASE("adaptive subdivision cuts a block to the model bow's bound below the tolerance", "[adaptive][model]") {
  const Machine m = load_machine(test::source("machines/vmcl600.toml"));
  const Setup s = test::vmcl600_setup();
  const double c = 4e-8;
  const comp::MachineModel model = model_with(m, "EYX:p2", c);
  auto solver = [&](const ClPoint& cl, const AxisPosition& previous) {
    IkOutcome o = solve(m, cl, s, previous);
    if (!o.ok()) return o;
    const comp::ActualIkOutcome a = comp::solve_actual(model, cl, s, *o.position);
    REQUIRE(a.ok());
    o.position = a.position;
    return o;
  };
  const ClPoint a = at(-150, 20, 10), b = at(150, 20, 10);
  const ClBlock block{a, b, *solver(a, {}).position, *solver(b, {}).position};
  const auto errors = model.errors();
  AdaptiveOptions o;
  o.tolerance_mm = 0.005;  // the bow (0.9 µm) is within it
  const SplitBlock plain = subdivide_adaptive(m, s, block, errors, solver, o);
  REQUIRE(plain.ok());
  CHECK(plain.output_blocks() == 1);
  CHECK(plain.max_error_mm >= c * 150 * 150);  // screened by the upper bound: at least the bow
  // bounded at 0.2 µm: 0.9 / 0.2 = 4.5, so 3 equal pieces of 100 mm, each bowing c·50² = 0.1 µm
  o.model_bow_mm = 0.0002;
  const SplitBlock cut = subdivide_adaptive(m, s, block, errors, solver, o);
  REQUIRE(cut.ok());
  REQUIRE(cut.output_blocks() == 3);
  CHECK(cut.nodes[0].t == Approx(1.0 / 3));
  CHECK(cut.nodes[1].t == Approx(2.0 / 3));
  ClPoint start = a;
  AxisPosition from = block.from;
  for (const BlockNode& node : cut.nodes) {
    const ClBlock piece{start, node.cl, from, node.q};
    CHECK(model_bow_mm(m, s, piece, errors) == Approx(c * 50 * 50).epsilon(1e-4));
    // the executed tip, with the ends compensated, within the bound of the segment
    const NonlinearError e = nonlinear_error(m, s, piece, errors);
    CHECK(e.max_error_mm <= 0.0002);
    start = node.cl;
    from = node.q;
  }
  // a bound the model already meets changes nothing
  o.model_bow_mm = 0.001;
  CHECK(subdivide_adaptive(m, s, block, errors, solver, o).output_blocks() == 1);
}
