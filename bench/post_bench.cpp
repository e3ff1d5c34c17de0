// SPDX-License-Identifier: Apache-2.0
// Benchmark of posting with nonlinear-error compensation (issue 4 "Speed"), on the public AC
// trunnion (tests/data/scenarios/public-clean), N CL points of one of two paths:
//   spiral  a dense spiral over a dome, tool axis along the normal (bows far below 5 µm: the
//           cheap bound screens nearly every block);
//   dome    the public dome path repeated (1201 points per copy; 80% of its blocks bow over 5 µm)
//   dense   the spiral with 400 turns, tool axis 5 -> 70 deg (issue 26's second path: larger steps,
//           the compensated IK iterates more)
// posted to files: one block per motion, --tolerance 0.005 adaptive, harmonic, and adaptive on the
// actual machine of truth.json (compensated IK, `--model`). Wall time and peak memory (ru_maxrss).
// Usage: post_bench [N=1000000] [work dir=.] [spiral|dense|dome] [verify] [model] [write-only]
// (write-only: just the CL file DIR/bench_path.cls, for bench/run_post_bench.sh)
// The gcode-parser comparison parses out_adaptive.nc (README).
#include <fmt/format.h>
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "ncpost/compensation/model_json.hpp"
#include "ncpost/compensation/nonlinear_batch.hpp"
#include "ncpost/compensation/nonlinear_compensation.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/read/apt/apt_reader.hpp"
#include "ncpost/postproc/post.hpp"
#include "ncpost/postproc/solve/actual_solver.hpp"
#include "ncpost/postproc/solve/tolerance_subdivider.hpp"

using namespace ncpost;

namespace {

/// The spiral: `turns` turns over the dome, the tool axis from `polar0_rad` to `polar1_rad` off +Z.
void write_path(const std::string& path, long n, double turns = 40.0, double polar0_rad = 0.08,
                double polar1_rad = 1.03) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  std::fputs("PARTNO/BENCH\nUNITS/MM\nMULTAX/ON\nLOADTL/1\nRAPID\n", f);
  const double radius = 60.0;
  for (long i = 0; i < n; ++i) {
    const double s = static_cast<double>(i) / static_cast<double>(n - 1);
    const double polar = polar0_rad + (polar1_rad - polar0_rad) * s;  // spiral: near the pole down to ~60 deg
    const double azimuth = 2.0 * kPi * turns * s;
    const Vec3d normal(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth), std::cos(polar));
    const Vec3d tip = radius * normal - Vec3d(0, 0, 20);
    std::fprintf(f, "GOTO/%.4f,%.4f,%.4f,%.6f,%.6f,%.6f\n", tip.x(), tip.y(), tip.z(), normal.x(), normal.y(),
                 normal.z());
    if (i == 0) std::fputs("FEDRAT/MMPM,2000.0\n", f);
  }
  std::fputs("END\n", f);
  std::fclose(f);
}

void write_dome_copies(const std::string& path, const std::string& dome, long n) {
  std::vector<std::string> gotos;
  std::ifstream in(dome);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("GOTO/", 0) == 0) gotos.push_back(line);
  std::FILE* f = std::fopen(path.c_str(), "w");
  std::fputs("PARTNO/BENCH\nUNITS/MM\nMULTAX/ON\nLOADTL/1\n", f);
  for (long i = 0; i < n; ++i) {
    const std::size_t k = static_cast<std::size_t>(i) % gotos.size();
    if (k == 0) std::fputs("RAPID\n", f);
    std::fprintf(f, "%s\n", gotos[k].c_str());
    if (i == 0) std::fputs("FEDRAT/MMPM,1500.0\n", f);
  }
  std::fputs("END\n", f);
  std::fclose(f);
}

long peak_rss_kb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;
}

struct Result {
  double seconds;
  std::size_t blocks;
  double max_contour_mm;
};

Result run(const Machine& m, const Setup& setup, const std::string& cl, const std::string& out_path,
           std::optional<nonlinear::Method> method, bool verify, const NominalSolver& nominal,
           const ActualSolver* actual) {
  const MotionSolver& solver = actual ? static_cast<const MotionSolver&>(*actual) : nominal;
  std::ifstream in(cl);
  cl::AptReader reader(in, cl);
  PostOptions options;
  options.verify = verify;
  nonlinear::CompensationOptions comp;
  comp.tolerance_mm = 0.005;
  const Dialect dialect = dialect_named("fanuc");
  if (method) {
    comp.method = *method;
    options.subdivide =
        actual ? make_tolerance_subdivider(*actual, comp, dialect) : make_tolerance_subdivider(nominal, comp, dialect);
  }
  const auto t0 = std::chrono::steady_clock::now();
  AtomicFile out(out_path);
  NcWriter writer(out, dialect, "XYZAC");
  const PostSummary s = post_program(reader, cl, solver, writer, options);
  out.commit();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return {seconds, s.blocks_out, s.verify.max_contour_mm};
}

/// The compensation alone (no NC writing), in batches of 4096 blocks on `threads` threads: what a
/// pipeline that solves motions in order and compensates batches in parallel would spend on it.
double batch_seconds(const Machine& m, const Setup& setup, const std::string& cl, int threads,
                     std::size_t& out_blocks) {
  std::ifstream in(cl);
  cl::AptReader reader(in, cl);
  const nonlinear::NominalSolver solver{m, setup};
  nonlinear::CompensationOptions comp;
  comp.tolerance_mm = 0.005;
  comp.rounding_allowance_mm = nonlinear::rounding_allowance_mm(4, 4, 120.0);
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<nonlinear::ClBlock> batch;
  ClPoint previous_cl;
  AxisPosition previous_q = home_of(m);
  bool have = false;
  out_blocks = 0;
  auto flush = [&] {
    for (const auto& split : nonlinear::compensate_blocks(m, setup, batch, NominalErrors{}, solver, comp, threads))
      out_blocks += split.nodes.size();
    batch.clear();
  };
  while (auto r = reader.next()) {
    const auto* mo = std::get_if<cl::Motion>(&*r);
    if (!mo) continue;
    const IkOutcome ik = solve(m, mo->point, setup, previous_q);
    if (!ik.ok()) throw std::runtime_error(ik.failure.message);
    if (have && !mo->rapid) batch.push_back({previous_cl, mo->point, previous_q, *ik.position});
    if (batch.size() == 4096) flush();
    previous_cl = mo->point;
    previous_q = *ik.position;
    have = true;
  }
  flush();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  const long n = argc > 1 ? std::atol(argv[1]) : 1000000;
  const std::string dir = argc > 2 ? argv[2] : ".";
  const std::string kind = argc > 3 ? argv[3] : "spiral";
  bool verify = false, with_model = false, write_only = false;
  for (int i = 4; i < argc; ++i) {
    verify = verify || std::string(argv[i]) == "verify";
    with_model = with_model || std::string(argv[i]) == "model";
    write_only = write_only || std::string(argv[i]) == "write-only";
  }
  const std::string scenario = std::string(NCPOST_BENCH_SOURCE_DIR) + "/tests/data/scenarios/public-clean/";
  const Machine m = load_machine(scenario + "machine.toml");
  Setup setup;
  setup.workpiece_origin_mm = Vec3d(0, 0, 80);
  const std::string cl = dir + "/bench_path.cls";
  if (kind == "dome")
    write_dome_copies(cl, scenario + "path.cls", n);
  else if (kind == "dense")
    write_path(cl, n, 400.0, deg_to_rad(5.0), deg_to_rad(70.0));
  else
    write_path(cl, n);
  if (write_only) {
    fmt::print("post_bench: wrote {} CL points ({}) to {}\n", n, kind, cl);
    return 0;
  }
  fmt::print("post_bench: {} CL points ({}), public-clean AC trunnion, tolerance 0.005 mm{}\n", n, kind,
             verify ? ", with --verify" : "");
  const NominalSolver nominal(m, setup);
  auto report = [](const char* what, const Result& r) {
    fmt::print("  {:<24}: {:7.2f} s, {:8} blocks, verified contour {:.4f} mm, peak RSS {} MB\n", what, r.seconds,
               r.blocks, r.max_contour_mm, peak_rss_kb() / 1024);
  };
  report("one block per motion", run(m, setup, cl, dir + "/out_plain.nc", std::nullopt, verify, nominal, nullptr));
  report("adaptive",
         run(m, setup, cl, dir + "/out_adaptive.nc", nonlinear::Method::adaptive, verify, nominal, nullptr));
  report("harmonic",
         run(m, setup, cl, dir + "/out_harmonic.nc", nonlinear::Method::harmonic, verify, nominal, nullptr));
  for (int threads : {1, 2}) {
    std::size_t blocks = 0;
    const double seconds = batch_seconds(m, setup, cl, threads, blocks);
    fmt::print("  read + IK + adaptive compensation only, batches of 4096, {} thread(s): {:7.2f} s, {} blocks\n",
               threads, seconds, blocks);
  }
  if (!with_model) return 0;
  const comp::ModelFile file = comp::read_model_json(scenario + "truth.json", &m);
  const comp::MachineModel model(m, file.parameters);
  const ActualSolver actual(model, setup);
  report("adaptive, --model truth",
         run(m, setup, cl, dir + "/out_model.nc", nonlinear::Method::adaptive, verify, nominal, &actual));
  return 0;
}
