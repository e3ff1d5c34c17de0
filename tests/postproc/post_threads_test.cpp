// SPDX-License-Identifier: Apache-2.0
// The post's read-ahead threads (PostOptions::threads = 2) write the same program as one thread:
// under `--model --tolerance` (the compensated IK solved ahead), on real files whose arcs, cycles
// and G-code angles make the post leave the motions solved ahead unused, and with a reversal model
// (records read ahead, motions solved on the post's thread). Errors surface the same way: a bad
// statement after thousands of good ones is reported with its line, and a post that fails
// half-way stops the reading threads.
#include <catch2/catch.hpp>

#include <fstream>
#include <memory>
#include <sstream>

#include "ncpost/compensation/model_json.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/solve/actual_solver.hpp"
#include "ncpost/postproc/read/apt/apt_reader.hpp"
#include "ncpost/postproc/write/atomic_file.hpp"
#include "ncpost/postproc/read/gcode/gcode_cl_reader.hpp"
#include "ncpost/postproc/solve/tolerance_subdivider.hpp"
#include "test_paths.hpp"

using namespace ncpost;

namespace {

struct Posted {
  std::string program;
  PostSummary summary;
  ErrorStats uncompensated;
};

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  REQUIRE(in);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Posts the APT text `cl` (named `name`) with `threads`; a model turns on the compensated IK, a
/// tolerance the adaptive subdivision.
Posted post_text(const Machine& m, const Setup& setup, const std::string& cl, const std::string& name, int threads,
                 const comp::MachineModel* model, std::optional<double> tolerance_mm) {
  std::istringstream in(cl);
  cl::AptReader reader(in, name);
  const NominalSolver nominal(m, setup);
  std::unique_ptr<ActualSolver> actual;
  if (model) actual = std::make_unique<ActualSolver>(*model, setup);
  const KinematicModel& solver = actual ? static_cast<const KinematicModel&>(*actual) : nominal;
  const Dialect dialect = dialect_named("fanuc");
  nonlinear::CompensationOptions comp;
  PostOptions options;
  options.threads = threads;
  if (tolerance_mm) {
    comp.tolerance_mm = *tolerance_mm;
    options.subdivide =
        actual ? make_tolerance_subdivider(*actual, comp, dialect) : make_tolerance_subdivider(nominal, comp, dialect);
  }
  const std::string path = "post_threads_test_" + std::to_string(threads) + ".nc";
  Posted p;
  SolverData data;  // the post's working data: its figures are those of the CL points used
  {
    AtomicFile out(path);
    NcWriter writer(out, dialect, "XYZ" + std::string(1, m.axes[3].letter) + std::string(1, m.axes[4].letter));
    p.summary = post_program(reader, name, solver, writer, options, data);
    out.commit();
  }
  p.program = slurp(path);
  if (actual) p.uncompensated = data.uncompensated;
  return p;
}

}  // namespace

TEST_CASE("read-ahead: --model --tolerance on the dome writes the same program as one thread", "[post][threads]") {
  const std::string dir = test::data("scenarios/public-clean/");
  const Machine m = load_machine(dir + "machine.toml");
  Setup setup;
  setup.workpiece_origin_mm = Vec3d(0, 0, 80);
  const comp::MachineModel truth(m, comp::read_model_json(dir + "truth.json", &m).parameters);
  const std::string cl = slurp(dir + "path.cls");
  const Posted one = post_text(m, setup, cl, "path.cls", 1, &truth, 0.005);
  const Posted two = post_text(m, setup, cl, "path.cls", 2, &truth, 0.005);
  CHECK(one.summary.blocks_out > 2000);  // subdivided: the dome bows up to 1 mm
  CHECK(two.summary.blocks_out == one.summary.blocks_out);
  CHECK(two.program == one.program);
  // the solver's figures count each CL point once, whichever thread solved it
  CHECK(two.uncompensated.count == one.uncompensated.count);
  CHECK(two.uncompensated.max_mm == one.uncompensated.max_mm);
  CHECK(two.uncompensated.rms_mm() == Approx(one.uncompensated.rms_mm()).epsilon(1e-12));
  CHECK(one.uncompensated.max_mm > 0.05);  // the truth's errors: tens of um at the CL points
}

TEST_CASE("read-ahead: real files with arcs, cycles and programmed angles post the same", "[post][threads]") {
  struct Case {
    const char* file;
    const char* machine;
    bool gcode;
  };
  const Case cases[] = {{"nx_APT_Zig_Zag_Smoothed.txt", "haas-umc750", false},
                        {"creo_bohren_1.ncl", "ac-trunnion", false},
                        {"creo_schruppen_1.ncl", "ac-trunnion", false},
                        {"linuxcnc_impeller-7bl-xyzac.ngc", "linuxcnc-xyzac-trt", true}};
  for (const Case& c : cases) {
    INFO(c.file);
    const Machine m = load_machine(test::source(std::string("machines/") + c.machine + ".toml"));
    const Setup setup;
    std::string program[2];
    for (int threads : {1, 2}) {
      std::ifstream in(test::data(std::string("real/") + c.file), std::ios::binary);
      std::unique_ptr<cl::Reader> reader;
      if (c.gcode)
        reader = std::make_unique<gcode::GcodeClReader>(in, c.file, m, setup);
      else
        reader = std::make_unique<cl::AptReader>(in, c.file);
      const NominalSolver solver(m, setup);
      PostOptions options;
      options.threads = threads;
      const std::string path = "post_threads_test_real_" + std::to_string(threads) + ".nc";
      {
        AtomicFile out(path);
        NcWriter writer(out, dialect_named("fanuc"),
                        "XYZ" + std::string(1, m.axes[3].letter) + std::string(1, m.axes[4].letter));
        post_program(*reader, c.file, solver, writer, options);
        out.commit();
      }
      program[threads - 1] = slurp(path);
    }
    CHECK(program[0].size() > 300);  // a real program (creo_bohren_1: 8 holes in 689 bytes)
    CHECK(program[1] == program[0]);
  }
}

TEST_CASE("read-ahead: a model with reversal is solved on the post's thread, same program", "[post][threads]") {
  const std::string dir = test::data("scenarios/public-clean/");
  const Machine m = load_machine(dir + "machine.toml");
  Setup setup;
  setup.workpiece_origin_mm = Vec3d(0, 0, 80);
  comp::ErrorParameters p = comp::read_model_json(dir + "truth.json", &m).parameters;
  p.set("reversal:C", 5e-5);
  const comp::MachineModel model(m, p);
  REQUIRE_FALSE(ActualSolver(model, setup).concurrent());
  const std::string cl = slurp(dir + "path.cls");
  const Posted one = post_text(m, setup, cl, "path.cls", 1, &model, 0.005);
  const Posted two = post_text(m, setup, cl, "path.cls", 2, &model, 0.005);
  CHECK(two.program == one.program);
}

TEST_CASE("read-ahead: errors surface at their line; a failed post stops the reading thread", "[post][threads]") {
  const std::string dir = test::data("scenarios/public-clean/");
  const Machine m = load_machine(dir + "machine.toml");
  Setup setup;
  setup.workpiece_origin_mm = Vec3d(0, 0, 80);
  std::string cl = "PARTNO/T\nMULTAX/ON\nFEDRAT/MMPM,1000\n";
  for (int i = 0; i < 5000; ++i) cl += "GOTO/" + std::to_string(0.01 * i) + ",0,10,0,0,1\n";
  const int bad_line = 3 + 5000 + 1;
  SECTION("a malformed statement after 5000 good ones") {
    const std::string text = cl + "GOTO/1,2,abc,0,0,1\n" + "GOTO/1,2,3,0,0,1\nEND\n";
    try {
      post_text(m, setup, text, "bad.cls", 2, nullptr, std::nullopt);
      FAIL("no error");
    } catch (const InputError& e) {
      CHECK(e.where().line == bad_line);
    }
  }
  SECTION("a point out of reach (the post fails, thousands of motions read ahead)") {
    std::string text = cl + "GOTO/0,0,10,0.17,0,-0.985\n";  // tilted 170 deg: beyond A +-120
    for (int i = 0; i < 20000; ++i) text += "GOTO/" + std::to_string(0.01 * i) + ",1,10,0,0,1\n";
    CHECK_THROWS_AS(post_text(m, setup, text + "END\n", "far.cls", 2, nullptr, std::nullopt), Infeasible);
  }
}
