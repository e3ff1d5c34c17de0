// Benchmark of posting with nonlinear-error compensation (issue 4 "Speed"): a synthetic five-axis
// path of N CL points (a spiral over a dome with the tool axis along the normal, as the public
// dome path but dense), posted to a file on the public AC trunnion
//   1. one block per motion (no tolerance),
//   2. --tolerance 0.005 adaptive, 3. --tolerance 0.005 harmonic,
// with wall time and peak memory (ru_maxrss). Usage: post_bench [N=1000000] [work dir=.]
// The figures go in the README; the gcode-parser comparison runs its parser on out_adaptive.nc.
#include <fmt/format.h>
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "ncpost/compensation/nonlinear_compensation.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/apt_reader.hpp"
#include "ncpost/postproc/post.hpp"

using namespace ncpost;

namespace {

void write_path(const std::string& path, long n) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  std::fputs("PARTNO/BENCH\nUNITS/MM\nMULTAX/ON\nLOADTL/1\nRAPID\n", f);
  const double radius = 60.0, turns = 40.0;
  for (long i = 0; i < n; ++i) {
    const double s = static_cast<double>(i) / static_cast<double>(n - 1);
    const double polar = 0.08 + 0.95 * s;          // from near the pole down to ~60 deg
    const double azimuth = 2.0 * kPi * turns * s;
    const Vec3d normal(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth), std::cos(polar));
    const Vec3d tip = radius * normal - Vec3d(0, 0, 20);
    std::fprintf(f, "GOTO/%.4f,%.4f,%.4f,%.6f,%.6f,%.6f\n", tip.x(), tip.y(), tip.z(), normal.x(), normal.y(), normal.z());
    if (i == 0) std::fputs("FEDRAT/MMPM,2000.0\n", f);
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
           std::optional<nonlinear::Method> method, bool verify) {
  std::ifstream in(cl);
  cl::AptReader reader(in, cl);
  NominalSolver solver(m, setup);
  PostOptions options;
  options.verify = verify;
  nonlinear::CompensationOptions comp;
  comp.tolerance_mm = 0.005;
  comp.rounding_allowance_mm = nonlinear::rounding_allowance_mm(4, 4, 120.0);
  if (method) {
    comp.method = *method;
    options.subdivide = [&](const SolvedPoint& a, const SolvedPoint& b) {
      auto ik = [&](const ClPoint& p, const AxisPosition& previous) { return solver.solve(p, previous); };
      const auto split = nonlinear::compensate_block(m, setup, {a.cl, b.cl, a.q, b.q}, NominalErrors{}, ik, comp);
      if (!split.ok()) throw std::runtime_error(split.failure);
      std::vector<SolvedPoint> points;
      points.reserve(split.nodes.size());
      for (const auto& node : split.nodes) points.push_back({node.cl, node.q});
      return points;
    };
  }
  const auto t0 = std::chrono::steady_clock::now();
  AtomicFile out(out_path);
  NcWriter writer(out, dialect_named("fanuc"), "XYZAC");
  const PostSummary s = post_program(reader, cl, solver, writer, options);
  out.commit();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return {seconds, s.blocks_out, s.verify.max_contour_mm};
}

}  // namespace

int main(int argc, char** argv) {
  const long n = argc > 1 ? std::atol(argv[1]) : 1000000;
  const std::string dir = argc > 2 ? argv[2] : ".";
  const bool verify = argc > 3 && std::string(argv[3]) == "verify";
  const Machine m = load_machine(std::string(NCPOST_BENCH_SOURCE_DIR) + "/machines/ac-trunnion.toml");
  Setup setup;
  setup.workpiece_origin_mm = Vec3d(0, 0, 80);
  const std::string cl = dir + "/bench_path.cls";
  write_path(cl, n);
  fmt::print("post_bench: {} CL points (dense dome spiral), AC trunnion, tolerance 0.005 mm{}\n", n,
             verify ? ", with --verify" : "");
  const Result plain = run(m, setup, cl, dir + "/out_plain.nc", std::nullopt, verify);
  fmt::print("  one block per motion : {:7.2f} s, {} blocks, contour {:.4f} mm, peak RSS {} MB\n", plain.seconds,
             plain.blocks, plain.max_contour_mm, peak_rss_kb() / 1024);
  const Result adaptive = run(m, setup, cl, dir + "/out_adaptive.nc", nonlinear::Method::adaptive, verify);
  fmt::print("  adaptive 0.005 mm    : {:7.2f} s, {} blocks, contour {:.4f} mm, peak RSS {} MB\n", adaptive.seconds,
             adaptive.blocks, adaptive.max_contour_mm, peak_rss_kb() / 1024);
  const Result harmonic = run(m, setup, cl, dir + "/out_harmonic.nc", nonlinear::Method::harmonic, verify);
  fmt::print("  harmonic 0.005 mm    : {:7.2f} s, {} blocks, contour {:.4f} mm, peak RSS {} MB\n", harmonic.seconds,
             harmonic.blocks, harmonic.max_contour_mm, peak_rss_kb() / 1024);
  return 0;
}
