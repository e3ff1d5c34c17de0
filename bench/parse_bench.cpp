// SPDX-License-Identifier: Apache-2.0
// G-code parse and re-post throughput on a generated five-axis program (figures in the README).
//
//   parse_bench [--blocks N] [--file PATH] [--keep] [--generate-only] [--stage lex|to-cl|re-post|re-post-ik|all]
//
// Generates a machine-axis program of N motion blocks (default 1,000,000) for an AC trunnion
// table (X Y Z A C, feeds, comments) to PATH (default: a temporary file, removed at the end
// unless --keep), then times, each over the whole file:
//   lex     line source + Spirit X3 block grammar (words, comments): the parser alone
//   to-CL   + modal interpretation + nominal forward kinematics: gcode::GcodeClReader
//   re-post + inverse kinematics with the programmed rotary angles (kinematics::linear_for, what
//           the post does with G-code input) + formatting one output block per motion with fmt
//           into a buffer written to /dev/null. A stand-in for the post pipeline (which lives in
//           postproc/src/post*.cpp) to bound what re-posting costs.
//   +IK     the same, but the rotary angles chosen again by the closed-form IK (kinematics::solve).
// Prints MB/s and blocks/s per stage, and the peak resident memory (it stays flat: streaming).
#include <fmt/format.h>
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <unistd.h>

#include "ncpost/kinematics/inverse.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/read/gcode/gcode_block.hpp"
#include "ncpost/postproc/read/gcode/gcode_cl_reader.hpp"
#include "ncpost/postproc/read/line_source.hpp"
#include "ncpost/postproc/write/fixed_format.hpp"
#include "ncpost/postproc/post.hpp"
#include "ac_trunnion_text.hpp"

using namespace ncpost;
using Clock = std::chrono::steady_clock;

namespace {

const std::string kMachine = ncpost::testing::ac_trunnion_toml("bench-ac-trunnion");

/// A five-axis machine-axis program: a swept surface, feeds changing now and then, comments.
void generate(const std::string& path, long blocks) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) throw std::runtime_error("cannot write " + path);
  fmt::memory_buffer out;
  fmt::format_to(std::back_inserter(out),
                 "%\nO1000 (NCPOST PARSE BENCH, {} BLOCKS)\nG90 G21 G94 G17\nT1 M6\nS12000 M3\n", blocks);
  fmt::format_to(std::back_inserter(out), "G0 X0 Y0 Z50 A0 C0\n");
  for (long i = 0; i < blocks; ++i) {
    const double t = static_cast<double>(i) * 1e-3;
    const double x = 40.0 * std::cos(t) + 0.01 * static_cast<double>(i % 997);
    const double y = 40.0 * std::sin(t) - 0.02 * static_cast<double>(i % 389);
    const double z = 10.0 + 5.0 * std::sin(0.37 * t);
    const double a = -45.0 + 30.0 * std::sin(0.11 * t);
    const double c = std::fmod(57.2957795 * t, 720.0) - 360.0;
    if (i % 1000 == 0) fmt::format_to(std::back_inserter(out), "(PASS {})\n", i / 1000);
    if (i % 100 == 0)
      fmt::format_to(std::back_inserter(out), "G1 X{:.4f} Y{:.4f} Z{:.4f} A{:.3f} C{:.3f} F{}\n", x, y, z, a, c,
                     1000 + (i / 100) % 7 * 250);
    else
      fmt::format_to(std::back_inserter(out), "X{:.4f} Y{:.4f} Z{:.4f} A{:.3f} C{:.3f}\n", x, y, z, a, c);
    if (out.size() > (1 << 20)) {
      std::fwrite(out.data(), 1, out.size(), f);
      out.clear();
    }
  }
  fmt::format_to(std::back_inserter(out), "M5\nM30\n%\n");
  std::fwrite(out.data(), 1, out.size(), f);
  std::fclose(f);
}

struct Figures {
  double seconds = 0;
  long blocks = 0;
};

void report(const char* stage, const Figures& r, double megabytes) {
  fmt::print("{:<8} {:8.3f} s  {:8.1f} MB/s  {:12.0f} blocks/s\n", stage, r.seconds, megabytes / r.seconds,
             static_cast<double>(r.blocks) / r.seconds);
}

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

Figures lex(const std::string& path) {
  const auto start = Clock::now();
  std::ifstream in(path, std::ios::binary);
  LineSource source(in, path, "a line of G-code");
  gcode::Block block;
  std::string_view line;
  long blocks = 0, words = 0;
  while (source.next(line)) {
    gcode::parse_block(line, block, path, source.line_number());
    words += static_cast<long>(block.words.size());
    ++blocks;
  }
  if (words == 0) std::puts("no words?");
  return {seconds_since(start), blocks};
}

Figures to_cl(const std::string& path, const Machine& m) {
  const auto start = Clock::now();
  std::ifstream in(path, std::ios::binary);
  gcode::GcodeClReader reader(in, path, m, Setup{});
  long motions = 0;
  double checksum = 0;
  while (auto r = reader.next()) {
    if (const auto* mo = std::get_if<cl::Motion>(&*r)) {
      ++motions;
      checksum += mo->point.tip_mm.x();
    }
  }
  if (checksum == 0.123) std::puts("");
  return {seconds_since(start), reader.lines_read()};
}

/// Re-post stand-in: X Y Z for every CL motion, then one formatted output block. With
/// `solve_ik` the rotary angles are chosen by the closed-form IK (as for APT input); otherwise the
/// programmed angles are kept (what the post does with G-code input) and only X Y Z are solved.
Figures repost(const std::string& path, const Machine& m, bool solve_ik) {
  const auto start = Clock::now();
  std::ifstream in(path, std::ios::binary);
  gcode::GcodeClReader reader(in, path, m, Setup{});
  std::FILE* sink = std::fopen("/dev/null", "wb");
  fmt::memory_buffer out;
  AxisPosition previous = home_of(m);
  long failures = 0;
  while (auto r = reader.next()) {
    const auto* mo = std::get_if<cl::Motion>(&*r);
    if (!mo) continue;
    AxisPosition q = home_of(m);
    if (solve_ik || !mo->rotary_rad) {
      const IkOutcome ik = solve(m, mo->point, Setup{}, previous);
      if (!ik.ok()) {
        ++failures;
        continue;
      }
      q = *ik.position;
    } else {
      q.rotary_rad = *mo->rotary_rad;
      q.linear_mm = linear_for(m, q.rotary_rad, mo->point.tip_mm, Setup{});
    }
    // the NC writer's word formatting (fixed_format.hpp)
    out.append(std::string_view(mo->rapid ? "G0" : "G1"));
    static constexpr char kLetters[] = "XYZAC";
    for (int k = 0; k < 5; ++k) {
      out.push_back(' ');
      out.push_back(kLetters[k]);
      append_fixed(out, k < 3 ? q.linear_mm[k] : rad_to_deg(q.rotary_rad[k - 3]), k < 3 ? 4 : 3);
    }
    out.push_back('\n');
    if (out.size() > (1 << 16)) {
      std::fwrite(out.data(), 1, out.size(), sink);
      out.clear();
    }
    previous = q;
  }
  std::fwrite(out.data(), 1, out.size(), sink);
  std::fclose(sink);
  if (failures) fmt::print("re-post: {} motions without an IK solution\n", failures);
  return {seconds_since(start), reader.lines_read()};
}

/// The real thing: `ncpost post` of the program as a machine-axis G-code input (parse, forward
/// kinematics to CL, inverse kinematics, the NC writer), written to a file beside the input.
Figures post_real(const std::string& path, const Machine& m) {
  const auto start = Clock::now();
  std::ifstream in(path, std::ios::binary);
  gcode::GcodeClReader reader(in, path, m, Setup{});
  NominalSolver solver(m, Setup{});
  const std::string out_path = path + ".post.nc";
  PostSummary summary;
  {
    AtomicFile out(out_path);
    NcWriter writer(out, dialect_named("fanuc"), "XYZAC");
    summary = post_program(reader, path, solver, writer, PostOptions{});
    out.commit();
  }
  const Figures f{seconds_since(start), reader.lines_read()};
  fmt::print("post: {} motions -> {} blocks ({:.1f} MB written)\n", summary.motions_in, summary.blocks_out,
             static_cast<double>(std::filesystem::file_size(out_path)) / 1e6);
  std::filesystem::remove(out_path);
  return f;
}

}  // namespace

int main(int argc, char** argv) {
  long blocks = 1'000'000;
  std::string path;
  bool keep = false, generate_only = false;
  std::string stage = "all";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--blocks" && i + 1 < argc)
      blocks = std::stol(argv[++i]);
    else if (a == "--file" && i + 1 < argc)
      path = argv[++i];
    else if (a == "--keep")
      keep = true;
    else if (a == "--generate-only")
      generate_only = keep = true;
    else if (a == "--stage" && i + 1 < argc)
      stage = argv[++i];
    else {
      std::cerr << "usage: parse_bench [--blocks N] [--file PATH] [--keep] [--generate-only] "
                   "[--stage lex|to-cl|re-post|re-post-ik|post|all]\n";
      return 1;
    }
  }
  if (path.empty())
    path = (std::filesystem::temp_directory_path() / fmt::format("ncpost_parse_bench_{}.ngc", ::getpid())).string();
  try {
    if (generate_only || !std::filesystem::exists(path)) generate(path, blocks);
    if (generate_only) {
      fmt::print("wrote {} ({:.1f} MB)\n", path, static_cast<double>(std::filesystem::file_size(path)) / 1e6);
      return 0;
    }
    const double megabytes = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
    const Machine m = parse_machine(kMachine, "bench-ac-trunnion.toml");
    fmt::print("file {} ({:.1f} MB)\n", path, megabytes);
    if (stage == "all" || stage == "lex") report("lex", lex(path), megabytes);
    if (stage == "all" || stage == "to-cl") report("to-CL", to_cl(path, m), megabytes);
    if (stage == "all" || stage == "re-post") report("re-post", repost(path, m, false), megabytes);
    if (stage == "all" || stage == "re-post-ik") report("+IK", repost(path, m, true), megabytes);
    if (stage == "all" || stage == "post") report("post", post_real(path, m), megabytes);
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    fmt::print("peak resident memory {:.1f} MB\n", static_cast<double>(usage.ru_maxrss) / 1024.0);
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    if (!keep) std::filesystem::remove(path);
    return 2;
  }
  if (!keep) std::filesystem::remove(path);
  return 0;
}
