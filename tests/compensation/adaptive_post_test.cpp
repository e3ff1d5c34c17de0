// SPDX-License-Identifier: Apache-2.0
// The compensation API wired into the lead's post pipeline through `PostOptions::subdivide`
// (the way `ncpost post --tolerance` is to call it), on the public dome path: the post's own
// verification (re-execution of the written, rounded program) sees every block within 5 um.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <fstream>

#include "ncpost/compensation/nonlinear_compensation.hpp"
#include "ncpost/postproc/read/apt/apt_reader.hpp"
#include "ncpost/postproc/post.hpp"
#include "nonlinear_test_support.hpp"

using namespace ncpost;

namespace {

PostSummary post_dome(nonlinear::Method method, double tolerance_mm, const std::string& out_path) {
  const Machine m = load_machine(std::string(NCPOST_SOURCE_DIR) + "/tests/data/scenarios/public-clean/machine.toml");
  const Setup setup = test::dome_setup();
  std::ifstream in(test::dome_path());
  cl::AptReader reader(in, "path.cls");
  NominalSolver solver(m, setup);
  nonlinear::CompensationOptions comp;
  comp.method = method;
  comp.tolerance_mm = tolerance_mm;
  // 4-decimal words, tips within 200 mm of the A and C lines on the dome
  comp.rounding_allowance_mm = nonlinear::rounding_allowance_mm(4, 4, 200.0);
  PostOptions options;
  options.verify = true;
  options.subdivide = [&](const SolvedPoint& a, const SolvedPoint& b) {
    auto ik = [&](const ClPoint& cl, const AxisPosition& previous) { return solver.solve(cl, previous); };
    const nonlinear::SplitBlock split =
        nonlinear::compensate_block(m, setup, {a.cl, b.cl, a.q, b.q}, NominalErrors{}, ik, comp);
    if (!split.ok()) throw std::runtime_error(split.failure);
    std::vector<SolvedPoint> points;
    for (const auto& node : split.nodes) points.push_back({node.cl, node.q});
    return points;
  };
  AtomicFile out(out_path);
  NcWriter writer(out, dialect_named("fanuc"), "XYZAC");
  const PostSummary s = post_program(reader, "path.cls", solver, writer, options);
  out.commit();
  return s;
}

}  // namespace

TEST_CASE("post --tolerance 0.005 (adaptive) on the dome path: verified within 5 um", "[adaptive][post]") {
  const PostSummary s = post_dome(nonlinear::Method::adaptive, 0.005, "adaptive_post_test_out.nc");
  fmt::print(
      "post, dome, adaptive 0.005 mm: {} motions -> {} blocks; verify: contour {:.5f} mm (line {}), "
      "orientation {:.4f} deg, block ends {:.6f} mm\n",
      s.motions_in, s.blocks_out, s.verify.max_contour_mm, s.verify.worst_line,
      rad_to_deg(s.verify.max_orientation_rad), s.verify.max_endpoint_mm);
  CHECK(s.verify.max_contour_mm <= 0.005);
  CHECK(s.blocks_out > s.motions_in);
}

TEST_CASE("post --tolerance 0.005 --nonlinear harmonic on the dome path", "[harmonic][post]") {
  const PostSummary s = post_dome(nonlinear::Method::harmonic, 0.005, "harmonic_post_test_out.nc");
  fmt::print("post, dome, harmonic 0.005 mm: {} motions -> {} blocks; verify: contour {:.5f} mm (line {})\n",
             s.motions_in, s.blocks_out, s.verify.max_contour_mm, s.verify.worst_line);
  CHECK(s.verify.max_contour_mm < 0.1);
}
