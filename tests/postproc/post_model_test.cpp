// SPDX-License-Identifier: Apache-2.0
// `post --model --tolerance`: the compensated program executed on the *true* machine. The model
// is identified from measurements (never the truth itself); the written, rounded program is
// re-executed on the truth (the post's own verification, with a solver whose commands come from the
// identified model and whose execution is the truth's), against the CL segments.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <cstdio>
#include <fstream>

#include "ncpost/compensation/identify.hpp"
#include "ncpost/compensation/measurement_csv.hpp"
#include "ncpost/compensation/model_json.hpp"
#include "ncpost/compensation/plans.hpp"
#include "ncpost/compensation/simulate.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/solve/actual_solver.hpp"
#include "ncpost/postproc/read/apt/apt_reader.hpp"
#include "ncpost/postproc/solve/executed_on.hpp"
#include "ncpost/postproc/solve/tolerance_subdivider.hpp"
#include "test_paths.hpp"

using namespace ncpost;

namespace {

struct Outcome {
  PostSummary summary;
  double uncompensated_tip_max_mm = 0.0;
};

/// Posts `cl_path` with `tolerance_mm` (commands from the model if given, else nominal) and
/// re-executes the written program on `truth`.
Outcome post_on_truth(const Machine& m, const Setup& setup, const std::string& cl_path, const comp::MachineModel* model,
                      const comp::MachineModel& truth, double tolerance_mm) {
  std::ifstream in(cl_path);
  REQUIRE(in);
  cl::AptReader reader(in, cl_path);
  NominalSolver nominal(m, setup);
  std::unique_ptr<ActualSolver> actual;
  if (model) actual = std::make_unique<ActualSolver>(*model, setup);
  const KinematicModel& commands = actual ? static_cast<const KinematicModel&>(*actual) : nominal;
  const ExecutedOn solver(commands, truth, setup);
  nonlinear::CompensationOptions comp;
  comp.tolerance_mm = tolerance_mm;
  const Dialect dialect = dialect_named("fanuc");
  PostOptions options;
  options.verify = true;
  options.subdivide =
      actual ? make_tolerance_subdivider(*actual, comp, dialect) : make_tolerance_subdivider(nominal, comp, dialect);
  AtomicFile out("post_model_test_out.nc");
  NcWriter writer(out, dialect, "XYZ" + std::string(1, m.axes[3].letter) + std::string(1, m.axes[4].letter));
  Outcome o;
  SolverData data;
  o.summary = post_program(reader, cl_path, solver, writer, options, data);
  out.commit();
  if (actual) o.uncompensated_tip_max_mm = data.uncompensated.max_mm;
  return o;
}

}  // namespace

TEST_CASE("public-clean: identified model, dome path at 0.002 mm, executed on the truth within 5 um", "[model][post]") {
  const std::string dir = test::data("scenarios/public-clean/");
  const Machine m = load_machine(dir + "machine.toml");
  std::vector<comp::MeasurementSet> sets;
  for (const char* f : {"ballbar_h250.csv", "ballbar_h300.csv", "sphere.csv"})
    sets.push_back(comp::read_measurement_csv(dir + f, m));
  const comp::IdentifyResult r = comp::identify(m, sets, comp::basic_parameters(m));
  REQUIRE(r.converged);
  const comp::MachineModel identified(m, r.parameters);
  const comp::MachineModel truth(m, comp::read_model_json(dir + "truth.json", &m).parameters);
  Setup setup;
  setup.workpiece_origin_mm = Vec3d(0, 0, 80);  // job.json

  const Outcome plain = post_on_truth(m, setup, dir + "path.cls", nullptr, truth, 0.002);
  const Outcome comp = post_on_truth(m, setup, dir + "path.cls", &identified, truth, 0.002);
  std::printf(
      "public-clean dome, tolerance 0.002 mm, executed on the truth: uncompensated %.4f mm (%zu blocks), "
      "compensated %.4f mm (%zu blocks, line %d); tip error at the CL points before compensation %.4f mm\n",
      plain.summary.verify.max_contour_mm, plain.summary.blocks_out, comp.summary.verify.max_contour_mm,
      comp.summary.blocks_out, comp.summary.verify.worst_line, comp.uncompensated_tip_max_mm);
  CHECK(plain.summary.verify.max_contour_mm > 0.05);  // the geometric errors: about 80 um
  CHECK(comp.summary.verify.max_contour_mm < 0.005);
  CHECK(comp.summary.verify.max_endpoint_mm < 0.002);
}

TEST_CASE("BC head (seed 002): plan, simulate, identify, compensated post executed on the truth", "[model][post]") {
  const Machine m = load_machine(test::source("machines/gantry-bc-head.toml"));
  comp::ErrorParameters truth_values;
  for (const auto& [n, v] : std::vector<std::pair<std::string, double>>{{"EX0C", 0.012},
                                                                        {"EY0C", -0.018},
                                                                        {"EA0C", 2.5e-5},
                                                                        {"EB0C", -3e-5},
                                                                        {"EX0B", 0.02},
                                                                        {"EZ0B", -0.015},
                                                                        {"EA0B", 4e-5},
                                                                        {"EC0B", -2e-5},
                                                                        {"EB0B", 3e-5},
                                                                        {"EC0C", -2e-5}})
    truth_values.set(n, v);
  std::vector<comp::MeasurementSet> sets;
  std::uint64_t seed = 21;
  for (const auto& p : comp::plan_bc_head(m, comp::BcHeadPlanOptions{}))
    sets.push_back(comp::simulate(m, p.set, truth_values, {0.3, seed++}));
  comp::IdentifyOptions o;  // the two positioning errors are given (seed 002), measured by other means
  o.fixed.set("EB0B", 3e-5);
  o.fixed.set("EC0C", -2e-5);
  const comp::IdentifyResult r =
      comp::identify(m, sets, {"EX0C", "EY0C", "EA0C", "EB0C", "EX0B", "EZ0B", "EA0B", "EC0B"}, o);
  REQUIRE(r.converged);
  comp::ErrorParameters model_values = r.parameters;
  model_values.set("EB0B", 3e-5);
  model_values.set("EC0C", -2e-5);
  const comp::MachineModel identified(m, model_values);
  const comp::MachineModel truth(m, truth_values);
  Setup setup;
  setup.workpiece_origin_mm = Vec3d(0, 0, -300);
  setup.tool_length_mm = 120.0;
  const std::string path = test::source("samples/hemisphere_5axis.cls");
  const Outcome plain = post_on_truth(m, setup, path, nullptr, truth, 0.002);
  const Outcome comp = post_on_truth(m, setup, path, &identified, truth, 0.002);
  std::printf(
      "BC head, hemisphere sample, tolerance 0.002 mm, executed on the truth: uncompensated %.4f mm, "
      "compensated %.4f mm (%zu blocks)\n",
      plain.summary.verify.max_contour_mm, comp.summary.verify.max_contour_mm, comp.summary.blocks_out);
  CHECK(plain.summary.verify.max_contour_mm > 0.02);
  CHECK(comp.summary.verify.max_contour_mm < 0.005);
}
