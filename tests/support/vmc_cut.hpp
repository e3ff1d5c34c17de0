// SPDX-License-Identifier: Apache-2.0
#pragma once
// A program for the three-axis VMCL600 posted with a model (or none) and executed, independently,
// on the machine of a truth (dead bands followed block by block): the cut of the laser loop's tests
// and of bench/laser_unseen_bench.cpp (issues 17 and 25). The set-up is vmcl600_setup.hpp's.
#include <fmt/format.h>

#include <cmath>
#include <sstream>
#include <string>

#include "ncpost/compensation/machine_model.hpp"
#include "ncpost/postproc/post.hpp"
#include "ncpost/postproc/read/apt/apt_reader.hpp"
#include "ncpost/postproc/solve/actual_solver.hpp"
#include "ncpost/postproc/solve/executed_on.hpp"
#include "ncpost/postproc/solve/tolerance_subdivider.hpp"
#include "ncpost/postproc/write/atomic_file.hpp"
#include "vmcl600_setup.hpp"

namespace ncpost::test {

/// A hemisphere of radius 120 mm around W's origin: rings every `step` deg of latitude, points
/// every `step` deg of longitude (APT CL, mm).
inline std::string vmc_dome_cl(int step) {
  std::string cl = "PARTNO/DOME\nUNITS/MM\nFEDRAT/2000\n";
  for (int lat = step; lat < 90; lat += step)
    for (int lon = 0; lon <= 360; lon += step) {
      const double t = lat * kPi / 180, p = lon * kPi / 180;
      cl += fmt::format("GOTO/{:.4f},{:.4f},{:.4f}\n", 120 * std::sin(t) * std::cos(p), 120 * std::sin(t) * std::sin(p),
                        120 * std::cos(t));
    }
  return cl + "END\n";
}

struct VmcCut {
  PostSummary summary;
  std::string failure;  ///< the post's exception, if any
};

/// Posts `cl` for `model` (nullptr: the nominal machine, no compensation) with `tolerance_mm`
/// (<= 0: none, one block per CL motion) to `out_path` and executes it on `truth`.
inline VmcCut vmc_cut_on(const Machine& m, const comp::MachineModel* model, const comp::MachineModel& truth,
                         const std::string& cl, double tolerance_mm, const std::string& out_path) {
  const Setup setup = vmcl600_setup();
  std::istringstream in(cl);
  cl::AptReader reader(in, "cut.cls");
  const comp::MachineModel nominal(m, comp::ErrorParameters{});
  const ActualSolver actual(model ? *model : nominal, setup);
  const ExecutedOn on_truth(actual, truth, setup);
  const Dialect dialect = dialect_named("fanuc");
  PostOptions options;
  options.threads = 1;
  options.verify = true;
  if (tolerance_mm > 0) {
    nonlinear::CompensationOptions comp;
    comp.tolerance_mm = tolerance_mm;
    options.take_up_reversal = true;
    options.subdivide = make_tolerance_subdivider(actual, comp, dialect);
  }
  VmcCut c;
  AtomicFile out(out_path);
  NcWriter writer(out, dialect, "XYZ");
  try {
    c.summary = post_program(reader, "cut.cls", on_truth, writer, options);
  } catch (const std::exception& e) {
    c.failure = e.what();
  }
  return c;
}

}  // namespace ncpost::test
