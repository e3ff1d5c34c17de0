// SPDX-License-Identifier: Apache-2.0
// Posting on the TRR-XY machine (issue 8): the NC program (X Y U V W) re-executed independently
// — parsed back from the file, every block interpolated linearly in X Y U V W at 200 points and
// run through the forward kinematics — stays within the tolerance of the CL path; --verify,
// --model, preview --csv and the out-of-reach exit code through the CLI.
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>

#include "ncpost/compensation/trr_model.hpp"
#include "ncpost/kinematics/trr_xy_inverse.hpp"
#include "ncpost/machines/trr_xy_file.hpp"
#include "ncpost/postproc/read/apt/apt_reader.hpp"
#include "cli_run.hpp"
#include "test_paths.hpp"
#include "trr_program.hpp"

using namespace ncpost;
using namespace ncpost::trr;

namespace {

const Vec3d kOrigin(0.0, 0.0, -300.0);

/// `ncpost ARGS`: the exit code; `err` (if given) gets what it printed.
int run(const std::string& args, std::string* err = nullptr) {
  const int rc = test::run_ncpost(args, "trr_post.log");
  if (err) *err = test::read_text_file("trr_post.log");
  return rc;
}

/// The motion blocks of the NC program at `path` (which must exist).
std::vector<Command> read_program(const std::string& path) {
  REQUIRE(std::ifstream(path).good());
  return test::read_trr_program(path);
}

std::string machine_path() { return test::trr_machine_path(); }
std::string sample_path() { return test::hemisphere_sample_path(); }

/// Largest distance of the executed tip from the CL path, over every block (200 points each).
double executed_deviation(const Kinematics& k, const std::vector<Command>& program, const std::vector<Vec3d>& path,
                          double* endpoint_mm = nullptr) {
  double worst = 0.0, worst_end = 0.0;
  std::optional<Rigidd> warm;
  const test::PolylineDistance distance_to_cl(path);
  for (std::size_t b = 0; b + 1 < program.size(); ++b) {
    for (int j = (b == 0 ? 0 : 1); j <= 200; ++j) {
      const double t = j / 200.0;
      const Command c = Command::from_words((1 - t) * program[b].words() + t * program[b + 1].words());
      const auto tp = k.tool(c.slider_mm, warm);
      if (!tp) FAIL("forward kinematics failed in block " << b);
      warm = tp->machine_T_plate;
      const double d = distance_to_cl(Kinematics::tip_in_workpiece(*tp, c, kOrigin));
      worst = std::max(worst, d);
      if (j == 200) worst_end = std::max(worst_end, d);
    }
  }
  if (endpoint_mm) *endpoint_mm = worst_end;
  return worst;
}

Errors some_errors() {
  Errors e;
  e.chain[0].gp = 2e-4;
  e.chain[1].at = -1.5e-4;
  e.chain[2].ar = 1e-4;
  e.chain[0].dl = 0.03;
  e.chain[1].dr = -0.02;
  e.chain[2].dts = 0.015;
  return e;
}

}  // namespace

TEST_CASE("the executed-deviation measure: PolylineDistance is the distance to the nearest of all segments") {
  // the hemisphere's CL path, and points scattered around it and far from it (a fixed sequence)
  const std::vector<Vec3d> path = test::read_cl_tips(sample_path());
  REQUIRE(path.size() == 435);
  const test::PolylineDistance fast(path);
  std::uint32_t state = 12345u;
  const auto next = [&state] {  // a small linear congruential sequence in [-1, 1)
    state = state * 1664525u + 1013904223u;
    return static_cast<double>(state >> 8) / static_cast<double>(1u << 23) - 1.0;
  };
  int far = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3d near_cl = path[static_cast<std::size_t>(i) % path.size()];
    const double spread_mm = (i % 4 == 0) ? 200.0 : 0.05;
    const Vec3d p = near_cl + spread_mm * Vec3d(next(), next(), next());
    const double every = test::distance_to_path(p, path);
    if (every > 1.0) ++far;
    INFO("point " << i);
    CHECK(fast(p) == Approx(every).margin(1e-12));
  }
  CHECK(far > 100);  // not only points next to the path
}

TEST_CASE("--tolerance 0.005: the executed tip stays within 5 um of the CL path") {
  const trr::Machine m = load_trr_xy_machine(machine_path());
  const Kinematics nominal(m);
  const std::vector<Vec3d> path = test::read_cl_tips(sample_path());
  REQUIRE(path.size() == 435);

  REQUIRE(run("post --machine " + machine_path() + " --workpiece-origin 0,0,-300 --tolerance none -o trr_plain.nc " +
              sample_path()) == 0);
  double end_plain = 0.0;
  const double plain = executed_deviation(nominal, read_program("trr_plain.nc"), path, &end_plain);

  std::string err;
  REQUIRE(run("post --machine " + machine_path() +
                  " --workpiece-origin 0,0,-300 --tolerance 0.005 --verify -o trr_tol.nc " + sample_path(),
              &err) == 0);
  const std::vector<Command> program = read_program("trr_tol.nc");
  double end_tol = 0.0;
  const double tol = executed_deviation(nominal, program, path, &end_tol);
  WARN("one block per CL motion: " << read_program("trr_plain.nc").size() << " blocks, largest deviation " << plain
                                   << " mm; --tolerance 0.005: " << program.size() << " blocks, largest deviation "
                                   << tol << " mm, block ends " << end_tol << " mm\n"
                                   << err);
  CHECK(plain > 0.05);      // the nonlinear error is large on this machine
  CHECK(end_plain < 5e-4);  // but the block ends are on the path (4-decimal words)
  CHECK(tol <= 0.005);
  CHECK(program.size() < 8 * 435);  // adaptive, not uniform dense output
  CHECK(err.find("after  (the written program re-executed") != std::string::npos);  // the common post's account
  CHECK(err.find("largest contour error 0.00") != std::string::npos);
}

TEST_CASE("--model: the commands make the machine with errors follow the CL path") {
  const trr::Machine m = load_trr_xy_machine(machine_path());
  const Errors truth = some_errors();
  const Kinematics actual(m, truth);
  {
    std::ofstream f("trr_model.json");
    f << comp::format_model_json(model_from_errors(truth, "trr-xy"));
  }
  const std::vector<Vec3d> path = test::read_cl_tips(sample_path());
  REQUIRE(run("post --machine " + machine_path() + " --workpiece-origin 0,0,-300 --tolerance 0.005 -o trr_nom.nc " +
              sample_path()) == 0);
  REQUIRE(run("post --machine " + machine_path() +
              " --workpiece-origin 0,0,-300 --tolerance 0.005 --model trr_model.json "
              "-o trr_comp.nc " +
              sample_path()) == 0);
  double end_nominal = 0.0, end_comp = 0.0;
  const double nominal = executed_deviation(actual, read_program("trr_nom.nc"), path, &end_nominal);
  const double compensated = executed_deviation(actual, read_program("trr_comp.nc"), path, &end_comp);
  WARN("on the machine with errors: nominal program " << nominal << " mm (block ends " << end_nominal
                                                      << "), compensated " << compensated << " mm (block ends "
                                                      << end_comp << ")");
  CHECK(end_nominal > 0.02);
  CHECK(end_comp < 5e-4);  // the 4-decimal words: up to 0.05 um each, through the head's gain
  CHECK(compensated <= 0.005);
}

TEST_CASE("preview --csv and --html on the TRR-XY machine: one row per feed block") {
  REQUIRE(run("preview --machine " + machine_path() +
              " --workpiece-origin 0,0,-300 --csv trr_preview.csv --html trr_preview.html " + sample_path()) == 0);
  std::ifstream h("trr_preview.html");
  std::stringstream hs;
  hs << h.rdbuf();
  CHECK(hs.str().find("<svg") != std::string::npos);
  CHECK(hs.str().find("<script") == std::string::npos);
  std::ifstream in("trr_preview.csv");
  std::string header;
  std::getline(in, header);
  CHECK(header.rfind("block,line,max_error_mm,at_t,harmonic_mm", 0) == 0);
  int rows = 0;
  double worst = 0.0;
  for (std::string line; std::getline(in, line); ++rows) {
    std::stringstream s(line);
    std::string field;
    for (int i = 0; i < 3; ++i) std::getline(s, field, ',');
    worst = std::max(worst, std::stod(field));
  }
  CHECK(rows == 433);  // 435 motions: the first is a rapid from nowhere, the second a rapid
  CHECK(worst > 0.05);
}

TEST_CASE("a CL point out of reach: exit 3 naming the line and the axis") {
  std::string err;
  CHECK(run("post --machine " + machine_path() + " --workpiece-origin 0,0,-300 -o trr_far.nc " +
                test::data("scenarios/public-clean/path.cls"),
            &err) == 3);
  CHECK(err.find("path.cls:729: V623.8594 is outside the limits [0, 600]") != std::string::npos);
  CHECK_FALSE(std::ifstream("trr_far.nc").good());
  std::ofstream("trr_bad_model.json") << "{\n \"machine\": \"trr-xy\",\n \"parameters\": {\"EX0C\": 0.01}\n}\n";
  CHECK(run("post --machine " + machine_path() + " --model trr_bad_model.json " + sample_path(), &err) == 2);
  CHECK(err.find("trr_bad_model.json:3:") != std::string::npos);
}

TEST_CASE("a TRR-XY model for another machine, or with an implausible value, is refused (exit 2); --force applies it") {
  std::string err;
  const std::string post = "post --machine " + machine_path() + " --workpiece-origin 0,0,-300 --tolerance none ";
  std::ofstream("trr_other.json") << "{\n \"machine\": \"other\",\n \"parameters\": {\"dl_a\": 0.01}\n}\n";
  CHECK(run(post + "--model trr_other.json -o trr_other.nc " + sample_path(), &err) == 2);
  CHECK(err.find("trr_other.json:2:") != std::string::npos);
  CHECK(err.find("machine 'other', this job's machine is 'trr-xy'") != std::string::npos);
  CHECK_FALSE(std::ifstream("trr_other.nc").good());
  std::ofstream("trr_huge.json") << "{\n \"machine\": \"trr-xy\",\n \"parameters\": {\n  \"dl_a\": 0.01,\n"
                                    "  \"gp_b\": 2.5\n }\n}\n";
  CHECK(run(post + "--verify-on trr_huge.json -o trr_huge.nc " + sample_path(), &err) == 2);
  CHECK(err.find("trr_huge.json:5:") != std::string::npos);
  CHECK(err.find("gp_b = 2.5 rad is not a plausible error") != std::string::npos);
  CHECK_FALSE(std::ifstream("trr_huge.nc").good());
  // --force: applied, with a warning naming the file and the value
  CHECK(run(post + "--force --model trr_other.json -o trr_forced.nc " + sample_path(), &err) == 0);
  CHECK(err.find("warning: trr_other.json:2: the model is for machine 'other'") != std::string::npos);
  CHECK(std::ifstream("trr_forced.nc").good());
}

TEST_CASE("a tolerance finer than the words can follow: exit 3 naming the line, at once (fuzz finding: 2^24 blocks)") {
  std::string err;
  CHECK(run("post --machine " + machine_path() + " --workpiece-origin 0,0,-300 --tolerance 1e-9 -o trr_nm.nc " +
                sample_path(),
            &err) == 3);
  CHECK(err.find("the move cannot be cut within the tolerance 1e-09 mm") != std::string::npos);
  CHECK(err.find("raise --tolerance") != std::string::npos);
  CHECK_FALSE(std::ifstream("trr_nm.nc").good());
}

// (drilling cycles are drilled by explicit moves since the common post: trr_pipeline_test.cpp)
TEST_CASE("CUTCOM on the TRR-XY machine: exit 2 naming the line, no program") {
  std::string err;
  std::ofstream("trr_cutcom.cls") << "UNITS/MM\nFEDRAT/MMPM,200\nGOTO/0,0,20,0,0,1\nCUTCOM/LEFT\nGOTO/10,0,0\n"
                                     "CUTCOM/OFF\nFINI\n";
  CHECK(run("post --machine " + machine_path() + " --workpiece-origin 0,0,-300 -o trr_cutcom.nc trr_cutcom.cls",
            &err) == 2);
  CHECK(err.find("trr_cutcom.cls:4:") != std::string::npos);
  CHECK(err.find("cutter radius compensation is not posted") != std::string::npos);
  CHECK_FALSE(std::ifstream("trr_cutcom.nc").good());
}
