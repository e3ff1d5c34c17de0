// SPDX-License-Identifier: Apache-2.0
// Posting from code with the installed ncpost library (find_package(ncpost), ncpost::ncpost): the
// library entry point ncpost::post does what `ncpost post --workpiece-origin 0,0,80 --tolerance T
// --verify` does, from a stream to a stream. Here the bundled hemisphere sample on the AC trunnion:
// the program is written to OUTPUT and the before/after figures are printed (before: one block per
// CL motion; after: the written program, its blocks bounded to the tolerance, re-executed on the
// machine).
//
//   post_from_code MACHINE.toml INPUT.cls [OUTPUT.nc] [TOLERANCE_MM]
//   e.g. post_from_code machines/ac-trunnion.toml samples/hemisphere_5axis.cls hemisphere.nc 0.002
//
// Exit codes as the CLI's: 0 done, 1 usage, 2 bad input (file:line:col) or file, 3 infeasible.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <ncpost/ncpost.hpp>

int main(int argc, char** argv) {
  if (argc < 3 || argc > 5) {
    std::fprintf(stderr, "usage: %s MACHINE.toml INPUT.cls [OUTPUT.nc] [TOLERANCE_MM]\n", argv[0]);
    return 1;
  }
  const std::string output = argc > 3 ? argv[3] : "post_from_code.nc";
  const double tolerance_mm = argc > 4 ? std::atof(argv[4]) : 0.002;
  try {
    ncpost::PostRequest request;
    const ncpost::Machine machine = ncpost::load_machine(argv[1]);
    request.machine = ncpost::serial_post_machine(machine);  // nominal: no --model
    request.machine_source = argv[1];
    request.setup.workpiece_origin_mm = ncpost::Vec3d(0, 0, 80);  // as `--workpiece-origin 0,0,80`
    request.input_name = argv[2];
    request.tolerance_mm = tolerance_mm;
    request.tolerance_is_default = false;
    request.dialect = ncpost::dialect_named("fanuc");
    request.verify = true;  // the account: before and after
    std::printf("ncpost %s, machine %s\n", ncpost::version().c_str(), machine.name.c_str());

    std::ifstream in(argv[2], std::ios::binary);
    if (!in) throw ncpost::InputError({argv[2], 0, 0}, "cannot open the input file");
    std::ostringstream program;  // the whole program in memory here; any std::ostream will do
    const ncpost::PostResult result = ncpost::post(in, program, request);
    const ncpost::PostAccount& a = result.account;
    std::printf(
        "before (one block per CL motion): %zu blocks, largest contour error %.4f mm (CL line %d), "
        "mean %.4f mm\n",
        a.before_blocks, a.before_max_mm, a.before_worst_line, a.before_mean_mm);
    std::printf(
        "after  (--tolerance %g mm):        %zu CL motions -> %zu blocks, largest contour error %.4f mm "
        "(CL line %d), block ends within %.4f mm\n",
        tolerance_mm, a.motions_in, a.blocks_out, a.after.max_contour_mm, a.after.worst_line, a.after.max_endpoint_mm);
    for (const std::string& n : result.summary.notices) std::printf("notice: %s\n", n.c_str());
    ncpost::write_file_atomically(output, program.str());
    std::printf("written to %s\n", output.c_str());
    return 0;
  } catch (const ncpost::InputError& e) {
    std::fprintf(stderr, "post_from_code: error: %s\n", e.what());
    return 2;
  } catch (const ncpost::FileError& e) {
    std::fprintf(stderr, "post_from_code: error: %s\n", e.what());
    return 2;
  } catch (const ncpost::Infeasible& e) {
    std::fprintf(stderr, "post_from_code: infeasible: %s\n", e.what());
    return 3;
  }
}
