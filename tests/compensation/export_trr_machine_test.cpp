// SPDX-License-Identifier: Apache-2.0
// `ncpost export --format machine` on the TRR-XY machine (issue 16): the model's 30 parameters
// folded into the machine file as its calibration ([trr_xy.calibration]). The file, read back by
// ncpost's own TRR-XY reader and used *nominally*, must move the tool as the original machine with
// the model: forward kinematics at 500 reachable poses to 1e-8 mm, and the hemisphere posted both
// ways (corrected machine without a model, original machine with the model) gives the same
// commands. The one-axis formats, which a TRR-XY model cannot fill, are usage errors naming what it
// supports.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <random>

#include "cli_run.hpp"
#include "ncpost/compensation/export_trr_machine.hpp"
#include "ncpost/compensation/trr_model.hpp"
#include "ncpost/kinematics/trr_xy_inverse.hpp"
#include "ncpost/machines/trr_xy_file.hpp"
#include "test_paths.hpp"
#include "trr_program.hpp"

using namespace ncpost;
using namespace ncpost::trr;

namespace {

const Vec3d kOrigin(0.0, 0.0, -300.0);

Errors some_errors() {
  Errors e;
  e.chain[0].gp = 2e-4;
  e.chain[1].at = -1.5e-4;
  e.chain[2].ar = 1e-4;
  e.chain[0].dl = 0.03;
  e.chain[1].dr = -0.02;
  e.chain[2].dts = 0.015;
  e.chain[0].ds = -0.012;
  e.chain[1].drs = 0.008;
  return e;
}

void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

int run(const std::string& args, std::string* log = nullptr) {
  const int rc = test::run_ncpost(args, "export_trr.log");
  if (log) *log = test::read_text_file("export_trr.log");
  return rc;
}

struct Gap {
  double tcp_mm = 0.0, axis_rad = 0.0;
};

/// Largest TCP distance and axis angle between `a` and `b` at the commands of 500 random reachable
/// CL points (tilts to 30°, TCP heights −100 to −400 mm), solved on `a`.
Gap compare_forward(const Kinematics& a, const Kinematics& b) {
  std::mt19937 rng(16);
  std::uniform_real_distribution<double> tilt(0.0, deg_to_rad(30.0)), azimuth(0.0, 2 * kPi), z(-400.0, -100.0);
  Gap gap;
  int solved = 0;
  for (int i = 0; i < 500; ++i) {
    const double t = tilt(rng), az = azimuth(rng);
    ClPoint cl;
    cl.axis = Vec3d(std::sin(t) * std::cos(az), std::sin(t) * std::sin(az), std::cos(t));
    cl.tip_mm = Vec3d(0, 0, z(rng));
    const InverseOutcome ik = inverse(a, cl, Vec3d::Zero());
    if (!ik.ok()) continue;
    ++solved;
    const auto pa = a.tool(ik.command->slider_mm, ik.machine_T_plate);
    const auto pb = b.tool(ik.command->slider_mm, ik.machine_T_plate);
    REQUIRE(pa);
    REQUIRE(pb);
    gap.tcp_mm = std::max(gap.tcp_mm, (pa->tcp_mm - pb->tcp_mm).norm());
    gap.axis_rad = std::max(gap.axis_rad, std::atan2(pa->axis.cross(pb->axis).norm(), pa->axis.dot(pb->axis)));
  }
  CHECK(solved > 400);
  return gap;
}

}  // namespace

TEST_CASE("TRR-XY machine export: the corrected machine moves as the original with the model", "[export][trr]") {
  const trr::Machine m = load_trr_xy_machine(test::trr_machine_path());
  const Errors model = some_errors();
  const comp::TrrMachineExport out = comp::corrected_trr_machine(m, model);
  CHECK(out.corrected.name == "trr-xy-calibrated");
  CHECK(out.applied == std::vector<std::string>{"ds_a", "gp_a", "dl_a", "dr_b", "at_b", "drs_b", "ar_c", "dts_c"});
  const trr::Machine read_back =
      parse_trr_xy_machine(comp::format_trr_machine_toml(out.corrected, {"test"}), "calibrated.toml");
  for (int k = 0; k < kParameterCount; ++k) CHECK(read_back.calibration[k] == model[k]);  // 17 digits: exact
  CHECK(read_back.slider_limits[2]->max == 600.0);

  const Kinematics corrected(read_back), original_with_model(m, model), original(m);
  const Gap same = compare_forward(corrected, original_with_model);
  const Gap plain = compare_forward(original, original_with_model);
  WARN("corrected vs original + model: " << same.tcp_mm << " mm, " << same.axis_rad
                                         << " rad; original vs original + "
                                            "model: "
                                         << plain.tcp_mm << " mm, " << plain.axis_rad << " rad");
  CHECK(same.tcp_mm < 1e-8);
  CHECK(same.axis_rad < 1e-10);
  CHECK(plain.tcp_mm > 0.02);  // what the model amounts to

  // a calibrated machine file takes a further model on top of its calibration
  const comp::TrrMachineExport twice = comp::corrected_trr_machine(read_back, model);
  CHECK(twice.corrected.calibration.chain[0].dl == Approx(0.06).margin(1e-15));
  CHECK(twice.corrected.name == "trr-xy-calibrated-calibrated");
  CHECK_THROWS_AS(comp::corrected_trr_machine(m, Errors{}), std::invalid_argument);
}

TEST_CASE("TRR-XY machine export on the command line: posted for it = posted with --model", "[export][trr][cli]") {
  const std::string machine = test::trr_machine_path(), sample = test::hemisphere_sample_path();
  write("trr_model.json", comp::format_model_json(model_from_errors(some_errors(), "trr-xy")));
  std::string log;
  REQUIRE(run("export --format machine --machine " + machine + " -o trr_calibrated.toml trr_model.json", &log) == 0);
  CHECK(log.find("exported 8 parameter(s)") != std::string::npos);
  const trr::Machine corrected = load_trr_xy_machine("trr_calibrated.toml");
  CHECK(corrected.name == "trr-xy-calibrated");

  const std::string job = " --workpiece-origin 0,0,-300 --tolerance none ";
  REQUIRE(run("post --machine trr_calibrated.toml" + job + "-o trr_calibrated.nc " + sample) == 0);
  REQUIRE(run("post --machine " + machine + job + "--model trr_model.json -o trr_with_model.nc " + sample) == 0);
  REQUIRE(run("post --machine " + machine + job + "-o trr_plain.nc " + sample) == 0);
  const std::vector<Command> a = test::read_trr_program("trr_calibrated.nc");
  const std::vector<Command> b = test::read_trr_program("trr_with_model.nc");
  const std::vector<Command> plain = test::read_trr_program("trr_plain.nc");
  REQUIRE(a.size() == b.size());
  REQUIRE(a.size() > 400);
  double words = 0.0, words_plain = 0.0;
  int differing = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double d = (a[i].words() - b[i].words()).cwiseAbs().maxCoeff();
    words = std::max(words, d);
    differing += d > 0.0;
    words_plain = std::max(words_plain, (plain[i].words() - b[i].words()).cwiseAbs().maxCoeff());
  }
  WARN(a.size() << " blocks; largest word difference " << words << " mm in " << differing
                << " blocks (the plain post differs by " << words_plain << " mm)");
  CHECK(words <= 1.0001e-4);  // at most one unit of the 4th decimal, where a value sits on a rounding boundary
  CHECK(words_plain > 0.01);
  // run on the machine of the model, the calibrated program follows the path as the compensated one
  const trr::Machine m = load_trr_xy_machine(machine);
  const Kinematics truth(m, some_errors());
  const std::vector<Vec3d> path = test::read_cl_tips(sample);
  const auto dev_a = test::trr_executed_deviation(truth, a, path, kOrigin, 10);
  const auto dev_b = test::trr_executed_deviation(truth, b, path, kOrigin, 10);
  REQUIRE(dev_a);
  REQUIRE(dev_b);
  CHECK(std::abs(*dev_a - *dev_b) < 1e-3);

  // the model made for the original machine is refused with the calibrated one (not applied twice)
  CHECK(run("post --machine trr_calibrated.toml" + job + "--model trr_model.json -o x.nc " + sample) == 2);
}

TEST_CASE("TRR-XY export: formats a TRR-XY model cannot fill are usage errors naming what it supports",
          "[export][trr][cli]") {
  const std::string machine = test::trr_machine_path();
  write("trr_model.json", comp::format_model_json(model_from_errors(some_errors(), "trr-xy")));
  for (const std::string format : {"linuxcnc", "siemens"}) {
    for (const std::string with_machine : {"--machine " + machine + " ", std::string()}) {
      std::string log;
      CHECK(run("export --format " + format + " " + with_machine + "-o t.txt trr_model.json", &log) == 1);
      CHECK(log.find("--format " + format + ": a TRR-XY model holds the 30 geometric parameters") != std::string::npos);
      CHECK(log.find("it supports --format machine") != std::string::npos);
    }
  }
  std::string log;
  CHECK(run("export --format csv --machine " + machine + " -o t.txt trr_model.json", &log) == 1);
  CHECK(log.find("--format: expected machine for a TRR-XY model") != std::string::npos);
  CHECK(run("export --format machine -o t.toml trr_model.json", &log) == 1);  // the machine file to correct
  CHECK(log.find("needs --machine") != std::string::npos);
  CHECK(run("export --format machine --axis X --machine " + machine + " -o t.toml trr_model.json") == 1);
  // a model of zero errors: nothing to fold in, bad input naming the model
  write("zero_model.json", comp::format_model_json(model_from_errors(Errors{}, "trr-xy")));
  CHECK(run("export --format machine --machine " + machine + " -o t.toml zero_model.json", &log) == 2);
  CHECK(log.find("zero_model.json: every parameter of the model is zero") != std::string::npos);
  CHECK_FALSE(std::ifstream("t.toml").good());
}

TEST_CASE("TRR-XY machine file: [trr_xy.calibration] names and values checked with their line", "[export][trr]") {
  const std::string head =
      "[machine]\nname = \"t\"\nkind = \"trr-xy\"\n\n[trr_xy]\nbase_radius = 495.0\n"
      "platform_radius = 200.0\nlink_length = 1020.0\nball_joint_height = 142.0\ntool_offset = 270.0\n"
      "\n[trr_xy.calibration]\n";
  const std::string axes =
      "\n[axes.X]\ntype = \"linear\"\n[axes.Y]\ntype = \"linear\"\n[axes.U]\ntype = \"linear\"\n"
      "[axes.V]\ntype = \"linear\"\n[axes.W]\ntype = \"linear\"\n";
  const trr::Machine ok = parse_trr_xy_machine(head + "dl_b = 0.25\nat_c = -1e-4\n" + axes, "m.toml");
  CHECK(ok.calibration.chain[1].dl == 0.25);
  CHECK(ok.calibration.chain[2].at == -1e-4);
  auto line_of = [&](const std::string& calibration) {
    try {
      (void)parse_trr_xy_machine(head + calibration + axes, "m.toml");
    } catch (const InputError& e) {
      return e.where().line;
    }
    return -1;
  };
  CHECK(line_of("dl_b = 0.1\ndl_d = 0.1\n") == 14);  // not a parameter
  CHECK(line_of("dl_b = \"0.1\"\n") == 13);          // not a number
  CHECK(line_of("dl_a = -900.0\n") == 12);           // a 120 mm link cannot reach: no home pose
}
