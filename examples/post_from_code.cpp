// SPDX-License-Identifier: Apache-2.0
// Posting from code with the installed ncpost library (find_package(ncpost), ncpost::ncpost):
// the bundled hemisphere sample on the AC trunnion, once with one block per CL motion and once with
// the nonlinear error bounded to a tolerance, both re-executed on the machine (verification), and
// the before/after figures printed — what `ncpost post --tolerance T --verify` does.
//
//   post_from_code MACHINE.toml INPUT.cls [OUTPUT.nc] [TOLERANCE_MM]
//   e.g. post_from_code machines/ac-trunnion.toml samples/hemisphere_5axis.cls hemisphere.nc 0.002
//
// Exit codes as the CLI's: 0 done, 1 usage, 2 bad input (file:line:col), 3 infeasible.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

#include <ncpost/ncpost.hpp>

namespace {

struct Job {
  ncpost::Machine machine;
  ncpost::Setup setup;
  ncpost::Dialect dialect;
  std::string input;
};

std::string axis_letters(const ncpost::Machine& m) {
  std::string s;
  for (const ncpost::Axis& a : m.axes) s += a.letter;
  return s;
}

/// Posts `job.input` to `output` (written only when `commit`), re-executing every block on the
/// nominal machine; `tolerance_mm` > 0 bounds the nonlinear error of every block.
ncpost::PostSummary post(const Job& job, const std::string& output, double tolerance_mm, bool commit) {
  std::ifstream in(job.input, std::ios::binary);
  if (!in) throw ncpost::InputError({job.input, 0, 0}, "cannot open the input file");
  ncpost::cl::AptReader reader(in, job.input);
  const ncpost::NominalSolver solver(job.machine, job.setup);

  ncpost::PostOptions options;
  options.verify = true;
  options.program_name = "EXAMPLE";
  options.header_comments = {"ncpost " + ncpost::version() + " from " + job.input};
  if (tolerance_mm > 0) {
    ncpost::nonlinear::CompensationOptions comp;
    comp.tolerance_mm = tolerance_mm;
    options.take_up_reversal = true;
    options.subdivide =
        ncpost::make_tolerance_subdivider(job.machine, job.setup, solver, nullptr, comp, job.dialect, job.input);
  }
  ncpost::AtomicFile out(output);  // not committed: removed when it goes out of scope
  ncpost::NcWriter writer(out, job.dialect, axis_letters(job.machine));
  const ncpost::PostSummary summary = ncpost::post_program(reader, job.input, solver, writer, options);
  if (commit) out.commit();
  return summary;
}

void print(const char* what, const ncpost::PostSummary& s) {
  std::printf("%s %zu CL motions -> %zu blocks: largest contour error %.4f mm (CL line %d), "
              "block ends within %.4f mm\n",
              what, s.motions_in, s.blocks_out, s.verify.max_contour_mm, s.verify.worst_line,
              s.verify.max_endpoint_mm);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3 || argc > 5) {
    std::fprintf(stderr, "usage: %s MACHINE.toml INPUT.cls [OUTPUT.nc] [TOLERANCE_MM]\n", argv[0]);
    return 1;
  }
  const std::string output = argc > 3 ? argv[3] : "post_from_code.nc";
  const double tolerance_mm = argc > 4 ? std::atof(argv[4]) : 0.002;
  try {
    Job job;
    job.machine = ncpost::load_machine(argv[1]);
    job.setup.workpiece_origin_mm = ncpost::Vec3d(0, 0, 80);  // as `--workpiece-origin 0,0,80`
    job.dialect = ncpost::dialect_named("fanuc");
    job.input = argv[2];
    std::printf("ncpost %s, machine %s\n", ncpost::version().c_str(), job.machine.name.c_str());
    const ncpost::PostSummary before = post(job, output + ".before", 0.0, false);
    const ncpost::PostSummary after = post(job, output, tolerance_mm, true);
    print("before (one block per CL motion):", before);
    print("after  (--tolerance):            ", after);
    std::printf("written to %s\n", output.c_str());
    return 0;
  } catch (const ncpost::InputError& e) {
    std::fprintf(stderr, "post_from_code: error: %s\n", e.what());
    return 2;
  } catch (const ncpost::Infeasible& e) {
    std::fprintf(stderr, "post_from_code: error: %s\n", e.what());
    return 3;
  }
}
