// SPDX-License-Identifier: Apache-2.0
// Reversal (a play, reversal.hpp) in compensated posting (issue 17): the compensated IK solves at
// the kink of the dead band (the needed move tiny, either way, or the axis standing inside its
// band), and `post --model --tolerance 0.002` on a model with reversal of either rotary axis
// (5 to 200 µrad) posts dense and sparse paths whose program, executed on a true machine with the
// same reversal (dead band followed block by block), stays within 2 µm of the CL path.
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "ncpost/compensation/actual_ik.hpp"
#include "ncpost/compensation/model_json.hpp"
#include "ncpost/kinematics/inverse.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/solve/actual_solver.hpp"
#include "ncpost/postproc/read/apt/apt_reader.hpp"
#include "ncpost/postproc/write/atomic_file.hpp"
#include "ncpost/postproc/solve/executed_on.hpp"
#include "ncpost/postproc/solve/tolerance_subdivider.hpp"
#include "test_paths.hpp"
#include "vmcl600_setup.hpp"

using namespace ncpost;

namespace {

const std::string kDir = test::data("scenarios/public-clean/");

Setup dome_setup() {
  Setup s;
  s.workpiece_origin_mm = Vec3d(0, 0, 80);
  return s;
}

comp::ErrorParameters truth_with(const Machine& m, const std::string& name, double value) {
  comp::ErrorParameters p = comp::read_model_json(kDir + "truth.json", &m).parameters;
  p.set(name, value);
  return p;
}

/// The dome's header and its GOTOs `first`..`last` (1-based, feed moves), every `step`-th.
std::string dome_part(int last, int step) {
  std::ifstream in(kDir + "path.cls");
  REQUIRE(in);
  std::string line, out;
  int gotos = 0;
  while (std::getline(in, line)) {
    if (line.rfind("GOTO/", 0) == 0) {
      ++gotos;
      if (gotos > last) continue;
      if (gotos > 2 && gotos != last && (gotos - 2) % step != 0) continue;
    }
    if (line.rfind("END", 0) == 0) continue;
    out += line + "\n";
  }
  return out + "END\n";
}

struct Cut {
  PostSummary summary;
  bool ok = false;
  std::string failure;
};

/// Posts `cl` compensated for `model` with `--tolerance`, executed on `truth`.
Cut post_on_truth(const Machine& m, const comp::MachineModel& model, const comp::MachineModel& truth,
                  const std::string& cl, double tolerance_mm, const Setup& setup = dome_setup()) {
  std::istringstream in(cl);
  cl::AptReader reader(in, "dome.cls");
  const ActualSolver actual(model, setup);
  const ExecutedOn on_truth(actual, truth, setup);
  const Dialect dialect = dialect_named("fanuc");
  nonlinear::CompensationOptions comp;
  comp.tolerance_mm = tolerance_mm;
  PostOptions options;
  options.threads = 1;
  options.verify = true;
  options.take_up_reversal = true;
  options.subdivide = make_tolerance_subdivider(actual, comp, dialect);
  Cut c;
  AtomicFile out("reversal_play_test.nc");
  std::string letters;
  for (const auto& axis : m.axes) letters += axis.letter;
  NcWriter writer(out, dialect, letters);
  try {
    c.summary = post_program(reader, "dome.cls", on_truth, writer, options);
    c.ok = true;
  } catch (const std::exception& e) {
    c.failure = e.what();
  }
  return c;
}

}  // namespace

TEST_CASE("compensated IK at the kink of the play: tiny moves either way, standing inside the band", "[reversal]") {
  const Machine m = load_machine(kDir + "machine.toml");
  const Setup setup = dome_setup();
  const double band = 5e-5;
  const comp::MachineModel model(m, truth_with(m, "reversal:A", band));
  const comp::MachineModel smooth(m, comp::read_model_json(kDir + "truth.json", &m).parameters);
  ClPoint cl;
  cl.tip_mm = Vec3d(5.2222, 0.2737, 41.7717);  // the dome's 2nd feed point (tilt 5 deg)
  cl.axis = Vec3d(0.087036, 0.004561, 0.996195).normalized();
  const IkOutcome nominal = solve(m, cl, setup, AxisPosition{});
  REQUIRE(nominal.ok());
  // where the axes must actually go: the model without reversal
  const comp::ActualIkOutcome free = comp::solve_actual(smooth, cl, setup, *nominal.position);
  REQUIRE(free.ok());
  for (double shift : {-1e-5, -3e-7, -2e-8, 0.0, 2e-8, 3e-7, 1e-5}) {
    for (bool came_falling : {false, true}) {
      INFO("A stands " << shift << " rad from where it must go, came " << (came_falling ? "falling" : "rising"));
      comp::ActualIkOptions o;
      o.tip_tolerance_mm = ActualSolver::kPostTipToleranceMm;
      o.axis_tolerance_rad = ActualSolver::kPostAxisToleranceRad;
      AxisPosition stands = *free.position;
      stands[3] += shift;
      AxisPosition command = stands;
      if (came_falling) command[3] -= band;  // falling: actual = command + b
      o.previous_actual = stands;
      o.previous_command = command;
      const comp::ActualIkOutcome r = comp::solve_actual(model, cl, setup, *nominal.position, o);
      INFO(r.message);
      REQUIRE(r.ok());
      const ToolPoseT<double> p = model.tool_pose(*r.position, setup, comp::reversal_state(model, *r.position, stands));
      CHECK((p.tip_mm - cl.tip_mm).norm() <= ActualSolver::kPostTipToleranceMm);
      CHECK(std::atan2(p.axis.cross(cl.axis).norm(), p.axis.dot(cl.axis)) <= ActualSolver::kPostAxisToleranceRad);
      const double need = (*free.position)[3] - stands[3];
      if (std::abs(need) <= 3e-8) {
        CHECK((*r.position)[3] == Approx(command[3]).margin(1e-12));  // stands still: the command stays
      } else if (need > 0) {
        CHECK((*r.position)[3] == Approx(r.actual[3]).margin(1e-12));  // rising: actual = command
      } else {
        CHECK((*r.position)[3] == Approx(r.actual[3] - band).margin(1e-12));  // falling: actual = command + b
      }
    }
  }
}

TEST_CASE("post --model --tolerance 0.002 with reversal of A or C cuts within 2 µm on the true machine", "[reversal]") {
  const Machine m = load_machine(kDir + "machine.toml");
  struct Path {
    const char* name;
    std::string cl;
  };
  // dense: one block per CL point (3 deg of C each); sparse: every 8th point (24 deg of C)
  const Path paths[] = {{"dense", dome_part(90, 1)}, {"sparse", dome_part(250, 8)}};
  const comp::MachineModel plain(m, comp::read_model_json(kDir + "truth.json", &m).parameters);
  for (const Path& path : paths) {
    const Cut without = post_on_truth(m, plain, plain, path.cl, 0.002);
    REQUIRE(without.ok);
    for (const char* axis : {"reversal:A", "reversal:C"}) {
      for (double band : {5e-6, 5e-5, 2e-4}) {
        INFO(path.name << " path, " << axis << " = " << band << " rad");
        const comp::MachineModel model(m, truth_with(m, axis, band));
        const comp::MachineModel truth(m, truth_with(m, axis, band));  // executed independently
        const Cut c = post_on_truth(m, model, truth, path.cl, 0.002);
        INFO(c.failure);
        REQUIRE(c.ok);
        CHECK(c.summary.verify.max_contour_mm <= 0.002);
        CHECK(c.summary.verify.max_endpoint_mm <= 0.0005);
        // the tilt turns back inside every block of the constant-tilt rings: the play of A is
        // taken up there (blocks with the tool still), C turns less often
        if (std::string(axis) == "reversal:A") CHECK(c.summary.blocks_out > without.summary.blocks_out);
      }
    }
  }
}

TEST_CASE("three-axis VMC with reversal of X, Y, Z: a dome posted with --tolerance 0.002 cuts within 2 µm",
          "[reversal]") {
  // the laser-identified model of samples/measurements/vmcl600 and its truth (21 errors, plays of
  // 3 to 5 µm); a hemisphere of radius 120 mm in rings every 10 deg, points every 10 deg
  const std::string dir = test::source("samples/measurements/vmcl600/");
  const Machine m = load_machine(test::source("machines/vmcl600.toml"));
  const Setup setup = test::vmcl600_setup();
  const comp::MachineModel model(m, comp::read_model_json(dir + "model.json", &m).parameters);
  const comp::MachineModel truth(m, comp::read_model_json(dir + "truth.json", &m).parameters);
  REQUIRE(model.has_reversal());
  std::string cl = "PARTNO/DOME\nUNITS/MM\nFEDRAT/2000\n";
  for (int lat = 10; lat < 90; lat += 10)
    for (int lon = 0; lon <= 360; lon += 10) {
      const double t = lat * kPi / 180, p = lon * kPi / 180;
      cl += fmt::format("GOTO/{:.4f},{:.4f},{:.4f}\n", 120 * std::sin(t) * std::cos(p), 120 * std::sin(t) * std::sin(p),
                        120 * std::cos(t));
    }
  cl += "END\n";
  const Cut c = post_on_truth(m, model, truth, cl, 0.002, setup);
  INFO(c.failure);
  REQUIRE(c.ok);
  CHECK(c.summary.verify.max_contour_mm <= 0.002);
}
