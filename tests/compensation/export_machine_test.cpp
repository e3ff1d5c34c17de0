// SPDX-License-Identifier: Apache-2.0
// Issue 17, `ncpost export --format machine`: the location errors written into the machine file as
// a control's kinematics calibration writes them (pivot points and axis directions). The corrected
// file, read back by ncpost's own machine reader and used *nominally*, must move the tool as the
// original machine with the model: forward kinematics at random commands, and the same CL path
// posted both ways (corrected machine without a model, original machine with the model) gives the
// same commands and, run on the model's machine, the same tool poses within 0.5 µm.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <regex>
#include <sstream>

#include "cli_run.hpp"
#include "ncpost/compensation/export_machine.hpp"
#include "ncpost/compensation/model_json.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/machine/serial_post_machine.hpp"
#include "ncpost/postproc/post_request.hpp"
#include "test_paths.hpp"

using namespace ncpost;
using namespace ncpost::comp;

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

Machine exported_and_read_back(const MachineModel& model, MachineExport& out) {
  out = corrected_machine(model);
  const std::string text = format_machine_toml(out.corrected, {"test"});
  return parse_machine(text, "calibrated.toml");  // ncpost's own reader
}

/// Largest tip distance (mm) and axis angle (rad) between the corrected machine (nominal) and the
/// original with the model, over random commands within the limits.
std::pair<double, double> compare_forward(const MachineModel& model, const Machine& corrected, double tool_length_mm) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Setup setup{Vec3d(10, -20, 80), tool_length_mm};
  double tip = 0.0, axis = 0.0;
  for (int k = 0; k < 500; ++k) {
    AxisPosition q = home_of(corrected);
    for (int i = 0; i < static_cast<int>(corrected.axes.size()); ++i) {
      const Axis& a = corrected.axes[i];
      const double half = a.limits ? 0.5 * (a.limits->max - a.limits->min) : 3.14159;
      const double mid = a.limits ? 0.5 * (a.limits->max + a.limits->min) : 0.0;
      q[i] = mid + half * u(rng);
    }
    const ToolPoseT<double> nominal = forward(corrected, q, setup);
    const ToolPoseT<double> actual = model.tool_pose(q, setup);
    tip = std::max(tip, (nominal.tip_mm - actual.tip_mm).norm());
    axis = std::max(axis, std::atan2(nominal.axis.cross(actual.axis).norm(), nominal.axis.dot(actual.axis)));
  }
  return {tip, axis};
}

/// The axis words of every motion block (modal: a word not written keeps its value).
std::vector<AxisPosition> commands_of(const std::string& program, const Machine& m) {
  std::vector<AxisPosition> out;
  AxisPosition q = home_of(m);
  const std::regex word("([XYZABC])(-?[0-9]+\\.?[0-9]*)");
  std::istringstream in(program);
  std::string line;
  while (std::getline(in, line)) {
    if (line.find('(') != std::string::npos) line = line.substr(0, line.find('('));
    if (line.find("G28") != std::string::npos) continue;  // the end's return to the reference point
    bool any = false;
    for (auto it = std::sregex_iterator(line.begin(), line.end(), word); it != std::sregex_iterator(); ++it) {
      const int i = m.index_of((*it)[1].str()[0]);
      if (i < 0) continue;
      const double v = std::stod((*it)[2]);
      q[i] = m.axes[i].is_rotary() ? v * kDeg : v;
      any = true;
    }
    if (any) out.push_back(q);
  }
  return out;
}

std::string post_program(const Machine& machine, const std::optional<ErrorParameters>& model, double tool_length_mm) {
  PostRequest r;
  r.machine = serial_post_machine(machine, model);
  r.machine_source = "machine.toml";
  r.setup.workpiece_origin_mm = Vec3d(0, 0, 80);
  r.setup.tool_length_mm = tool_length_mm;
  r.tolerance_mm = std::nullopt;  // one block per CL motion: the same blocks both ways
  r.tolerance_is_default = false;
  r.threads = 1;
  std::istringstream in(test::read_text_file(test::source("samples/hemisphere_5axis.cls")));
  std::ostringstream out;
  post(in, out, r);
  return out.str();
}

}  // namespace

TEST_CASE("machine export: the AC trunnion's identified location errors as a calibrated machine file", "[export]") {
  const Machine m = load_machine(test::source("machines/ac-trunnion.toml"));
  const ModelFile file = read_model_json(test::source("samples/measurements/ac-trunnion/model.json"), &m);
  const MachineModel model(m, file.parameters);
  MachineExport out;
  const Machine corrected = exported_and_read_back(model, out);
  CHECK(corrected.name == "ac-trunnion-calibrated");
  CHECK(out.applied.size() == 8);
  CHECK(out.left_out.empty());
  const auto [tip, axis] = compare_forward(model, corrected, 0.0);
  CHECK(tip < 0.5e-3);
  CHECK(tip < 1e-8);  // the same rigid chain: exact to rounding
  CHECK(axis < 1e-10);

  // the hemisphere posted for the corrected machine (nominal) and for the original with the model
  const std::string calibrated = post_program(corrected, std::nullopt, 0.0);
  const std::string compensated = post_program(m, file.parameters, 0.0);
  const auto a = commands_of(calibrated, m);
  const auto b = commands_of(compensated, m);
  REQUIRE(a.size() == b.size());
  REQUIRE(a.size() > 400);
  // (the words may differ: at the first point both solutions, A±5° C±90°, are equally far from home
  // and the two posts may take either branch; the tool poses are what must agree)
  double pose = 0.0, tool_axis = 0.0, plain = 0.0;
  const Setup setup{Vec3d(0, 0, 80), 0.0};
  for (std::size_t k = 0; k < a.size(); ++k) {
    // both programs run on the machine the model describes
    const ToolPoseT<double> pa = model.tool_pose(a[k], setup), pb = model.tool_pose(b[k], setup);
    pose = std::max(pose, (pa.tip_mm - pb.tip_mm).norm());
    tool_axis = std::max(tool_axis, std::atan2(pa.axis.cross(pb.axis).norm(), pa.axis.dot(pb.axis)));
    plain = std::max(plain, (forward(m, b[k], setup).tip_mm - model.tool_pose(b[k], setup).tip_mm).norm());
  }
  CHECK(pose < 0.5e-3);
  CHECK(tool_axis < 5e-6);  // the 4-decimal words: 1e-4° is 1.7 µrad
  CHECK(plain > 0.02);      // what the location errors amount to (the plain post would be off by this)
}

TEST_CASE("machine export: zero errors of an outer axis turn the lines it carries; head pivots with a tool",
          "[export]") {
  SECTION("AC trunnion: EA0A turns the C line about A") {
    const Machine m = load_machine(test::source("machines/ac-trunnion.toml"));
    ErrorParameters p;
    p.set("EA0A", 200e-6);
    p.set("EY0A", 0.03);
    p.set("EX0C", -0.02);
    p.set("EA0C", 50e-6);
    p.set("ECC:h2:cos", 10e-6);  // a component error: left out, listed
    p.set("reversal:A", 20e-6);
    const MachineModel model(m, p);
    MachineExport out;
    const Machine corrected = exported_and_read_back(model, out);
    CHECK(out.left_out.size() == 2);
    ErrorParameters located;
    for (const char* n : {"EA0A", "EY0A", "EX0C", "EA0C"}) located.set(n, *p.get(n));
    const MachineModel location_only(m, located);
    const auto [tip, axis] = compare_forward(location_only, corrected, 0.0);
    CHECK(tip < 1e-8);
    CHECK(axis < 1e-10);
    // the C direction turned by EA0A + EA0C about X
    CHECK(corrected.axes[m.index_of('C')].direction.y() == Approx(-250e-6).margin(1e-9));
  }
  SECTION("gantry BC head: tool-side pivots stay relative to the gauge point") {
    const Machine m = load_machine(test::source("machines/gantry-bc-head.toml"));
    ErrorParameters p;
    p.set("EX0B", 0.015);
    p.set("EZ0B", -0.01);
    p.set("EA0B", 30e-6);
    p.set("EC0B", -40e-6);
    p.set("EB0B", 80e-6);
    p.set("EX0C", 0.02);
    p.set("EY0C", -0.012);
    p.set("EA0C", 25e-6);
    p.set("EB0C", -35e-6);
    p.set("EC0C", 60e-6);
    const MachineModel model(m, p);
    MachineExport out;
    const Machine corrected = exported_and_read_back(model, out);
    for (double tool : {0.0, 120.0, 250.0}) {
      INFO("tool length " << tool);
      const auto [tip, axis] = compare_forward(model, corrected, tool);
      CHECK(tip < 1e-8);
      CHECK(axis < 1e-10);
    }
  }
}

TEST_CASE("machine export on the command line", "[export][cli]") {
  const std::string out = "calibrated_export_test.toml";
  const std::string model = test::source("samples/measurements/ac-trunnion/model.json");
  REQUIRE(test::run_ncpost("export --format machine --machine " + test::source("machines/ac-trunnion.toml") + " -o " +
                               out + " " + model,
                           "export_machine.log") == 0);
  const Machine corrected = load_machine(out);
  CHECK(corrected.name == "ac-trunnion-calibrated");
  // the model made for the original machine is refused with the calibrated one (not applied twice)
  CHECK(test::run_ncpost(
            "post --machine " + out + " --model " + model + " -o x.nc " + test::source("samples/hemisphere_5axis.cls"),
            "export_machine.log") == 2);
  // without --machine: usage
  CHECK(test::run_ncpost("export --format machine -o y.toml " + model, "export_machine.log") == 1);
  // a model without location errors: bad input naming the model
  const std::string vmc = test::source("samples/measurements/vmcl600/model.json");
  CHECK(test::run_ncpost(
            "export --format machine --machine " + test::source("machines/vmcl600.toml") + " -o z.toml " + vmc,
            "export_machine.log") == 2);
  CHECK(test::read_text_file("export_machine.log").find(vmc + ": the model has no location error") !=
        std::string::npos);
}
