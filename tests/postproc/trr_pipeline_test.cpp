// SPDX-License-Identifier: Apache-2.0
// The TRR-XY machine through the common post (issue 16: one pipeline, TrrSolver): the hemisphere
// spiral with --tolerance 0.005 --verify --report, the program re-executed independently (parsed
// back, X Y U V W interpolated linearly, forward kinematics) within the tolerance; --verify-on a
// machine with errors; the same program with one and two threads; a drilling cycle drilled by
// explicit moves.
#include <catch2/catch.hpp>

#include <fstream>
#include <regex>
#include <sstream>

#include "ncpost/compensation/trr_model.hpp"
#include "ncpost/machines/trr_xy_file.hpp"
#include "ncpost/postproc/read/apt/apt_reader.hpp"
#include "cli_run.hpp"
#include "test_paths.hpp"
#include "trr_program.hpp"

using namespace ncpost;
using namespace ncpost::trr;

namespace {

const Vec3d kOrigin(0.0, 0.0, -300.0);

int run(const std::string& args, std::string* err = nullptr) {
  const int rc = test::run_ncpost(args, "trr_pipeline.log");
  if (err) *err = test::read_text_file("trr_pipeline.log");
  return rc;
}

std::string machine_path() { return test::trr_machine_path(); }
std::string sample_path() { return test::hemisphere_sample_path(); }
std::string post_args() { return "post --machine " + machine_path() + " --workpiece-origin 0,0,-300 "; }

/// Largest distance of the executed tip from the CL path over every block (100 points each).
double executed_deviation(const Kinematics& k, const std::vector<Command>& program, const std::vector<Vec3d>& path) {
  const std::optional<double> worst = test::trr_executed_deviation(k, program, path, kOrigin);
  REQUIRE(worst);
  return *worst;
}

/// The figure after `label` ("largest contour error") on the line that starts with `line_start`.
double figure(const std::string& text, const std::string& line_start) {
  const std::regex re(line_start + "[^\n]*largest contour error ([0-9.]+) mm");
  std::smatch m;
  REQUIRE(std::regex_search(text, m, re));
  return std::stod(m[1].str());
}

std::string text_of(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("TRR-XY through the common post: --tolerance 0.005 --verify --report") {
  const Kinematics nominal(load_trr_xy_machine(machine_path()));
  const std::vector<Vec3d> path = test::read_cl_tips(sample_path());
  std::string err;
  REQUIRE(run(post_args() + "--tolerance 0.005 --verify --report trr_pipe.html -o trr_pipe.nc " + sample_path(),
              &err) == 0);
  const std::vector<Command> program = test::read_trr_program("trr_pipe.nc");
  const double executed = executed_deviation(nominal, program, path);
  const double before = figure(err, "before"), after = figure(err, "after ");
  WARN(program.size() << " blocks; executed independently: " << executed << " mm\n" << err);
  CHECK(program.size() > 435);
  CHECK(program.size() < 8 * 435);
  CHECK(executed <= 0.005);
  CHECK(before > 0.05);  // one block per CL motion bows far on this machine
  CHECK(after <= 0.005);
  CHECK(after > 0.0);
  const std::string nc = text_of("trr_pipe.nc");
  CHECK(nc.find(" Z") == std::string::npos);   // the words are X Y U V W
  CHECK(nc.find("G43") == std::string::npos);  // the tool length is in the kinematics
  const std::string html = text_of("trr_pipe.html");
  CHECK(html.find("<svg") != std::string::npos);
  CHECK(html.find("trr-xy") != std::string::npos);
}

TEST_CASE("TRR-XY: --verify-on a machine with errors, and --model of the same machine") {
  Errors e;
  e.chain[0].gp = 2e-4;
  e.chain[1].at = -1.5e-4;
  e.chain[0].dl = 0.03;
  e.chain[1].dr = -0.02;
  std::ofstream("trr_pipe_truth.json") << comp::format_model_json(model_from_errors(e, "trr-xy"));
  std::string err;
  REQUIRE(run(post_args() + "--tolerance 0.005 --verify-on trr_pipe_truth.json -o trr_nominal.nc " + sample_path(),
              &err) == 0);
  const double nominal_on_truth = figure(err, "after ");
  CHECK(err.find("the machine of trr_pipe_truth.json") != std::string::npos);
  REQUIRE(run(post_args() +
                  "--tolerance 0.005 --model trr_pipe_truth.json --verify-on trr_pipe_truth.json -o trr_comp.nc " +
                  sample_path(),
              &err) == 0);
  const double compensated_on_truth = figure(err, "after ");
  WARN("on the machine with errors: nominal program " << nominal_on_truth << " mm, compensated "
                                                      << compensated_on_truth);
  CHECK(nominal_on_truth > 0.02);
  CHECK(compensated_on_truth <= 0.005);
  // the independent check agrees
  const Kinematics truth(load_trr_xy_machine(machine_path()), e);
  CHECK(executed_deviation(truth, test::read_trr_program("trr_comp.nc"), test::read_cl_tips(sample_path())) <= 0.005);
}

TEST_CASE("TRR-XY: the same program with one and two threads") {
  REQUIRE(run(post_args() + "--tolerance 0.005 --threads 1 -o trr_t1.nc " + sample_path()) == 0);
  REQUIRE(run(post_args() + "--tolerance 0.005 --threads 2 -o trr_t2.nc " + sample_path()) == 0);
  CHECK(text_of("trr_t1.nc") == text_of("trr_t2.nc"));
}

TEST_CASE("TRR-XY: a drilling cycle is drilled by explicit moves along the tool axis") {
  std::ofstream("trr_pipe_cycle.cls") << "UNITS/MM\nFEDRAT/MMPM,200\nSPINDL/RPM,1000\nGOTO/0,0,20,0,0,1\n"
                                         "CYCLE/DRILL,FEDTO,5,RAPTO,2\nGOTO/10,0,0\nCYCLE/OFF\nFINI\n";
  std::string err;
  REQUIRE(run(post_args() + "--tolerance none -o trr_pipe_cycle.nc trr_pipe_cycle.cls", &err) == 0);
  const Kinematics nominal(load_trr_xy_machine(machine_path()));
  // the tip visits the hole: down to the bottom (z -5) at x 10 and back
  double lowest = 1e9;
  std::optional<Rigidd> warm;
  for (const Command& c : test::read_trr_program("trr_pipe_cycle.nc")) {
    const auto tp = nominal.tool(c.slider_mm, warm);
    REQUIRE(tp);
    const Vec3d tip = Kinematics::tip_in_workpiece(*tp, c, kOrigin);
    if (std::abs(tip.x() - 10.0) < 1e-3 && std::abs(tip.y()) < 1e-3) lowest = std::min(lowest, tip.z());
  }
  CHECK(lowest == Approx(-5.0).margin(1e-3));
  CHECK(text_of("trr_pipe_cycle.nc").find("G81") == std::string::npos);
}

TEST_CASE("TRR-XY: re-posting its own G-code output gives back the program (X Y U V W input)") {
  std::string err;
  REQUIRE(run(post_args() + "--tolerance 0.005 -o trr_src.nc " + sample_path(), &err) == 0);
  // one block per motion of the program: the words read back through the forward kinematics and
  // solved again are the same words, to the last decimal
  REQUIRE(run(post_args() + "--tolerance none -o trr_again.nc trr_src.nc", &err) == 0);
  const std::vector<Command> source = test::read_trr_program("trr_src.nc");
  const std::vector<Command> again = test::read_trr_program("trr_again.nc");
  REQUIRE(again.size() == source.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < source.size(); ++i)
    worst = std::max(worst, (again[i].words() - source[i].words()).cwiseAbs().maxCoeff());
  WARN("re-posted " << again.size() << " blocks; largest word change " << worst << " mm\n" << err);
  CHECK(worst <= 1.5e-4);
  // with the tolerance and --verify: the program already meets it (few or no blocks added)
  REQUIRE(run(post_args() + "--tolerance 0.005 --verify -o trr_again_tol.nc trr_src.nc", &err) == 0);
  CHECK(figure(err, "after ") <= 0.005);
  const std::size_t blocks = test::read_trr_program("trr_again_tol.nc").size();
  CHECK(blocks >= source.size());
  CHECK(blocks <= source.size() + source.size() / 20);
}

TEST_CASE("TRR-XY preview of its own G-code output: every block within the tolerance it was posted with") {
  std::string err;
  REQUIRE(run(post_args() + "--tolerance 0.005 -o trr_prev_src.nc " + sample_path(), &err) == 0);
  REQUIRE(run("preview --machine " + machine_path() + " --workpiece-origin 0,0,-300 trr_prev_src.nc", &err) == 0);
  const std::regex re("([0-9]+) blocks previewed; largest nonlinear error ([0-9.]+) mm");
  std::smatch m;
  REQUIRE(std::regex_search(err, m, re));
  WARN(err);
  CHECK(std::stoi(m[1].str()) > 435);
  CHECK(std::stod(m[2].str()) <= 0.005);
  CHECK(std::stod(m[2].str()) > 0.0);
}

TEST_CASE("TRR-XY G-code input: words of another machine, arcs and cycles are input errors naming the line") {
  std::string err;
  std::ofstream("trr_z.nc") << "G90 G21 G94\nG0 X0 Y0 U280 V280 W280\nG1 Z5 F100\nM30\n";
  CHECK(run(post_args() + "-o trr_z_out.nc trr_z.nc", &err) == 2);
  CHECK(err.find("trr_z.nc:3:") != std::string::npos);
  CHECK(err.find("no Z axis") != std::string::npos);
  std::ofstream("trr_arc.nc") << "G90 G21 G94\nG0 X0 Y0 U280 V280 W280\nG2 X10 Y0 I5 J0 F100\nM30\n";
  CHECK(run(post_args() + "-o trr_arc_out.nc trr_arc.nc", &err) == 2);
  CHECK(err.find("trr_arc.nc:3:") != std::string::npos);
  std::ofstream("trr_far.nc") << "G90 G21 G94\nG0 X0 Y0 U280 V280 W620\nM30\n";
  CHECK(run(post_args() + "-o trr_far_out.nc trr_far.nc", &err) == 3);
  CHECK(err.find("trr_far.nc:2:") != std::string::npos);
  CHECK_FALSE(std::ifstream("trr_far_out.nc").good());
}
