// SPDX-License-Identifier: Apache-2.0
// Issue 25 item 2: the location errors of a table-table machine written into the controls'
// kinematics, checked by a round trip through an independent implementation of each control's
// kinematics fed with the numbers read back from the exported text.
//
// LinuxCNC xyzac-trt / xyzbc-trt (trtfuncs.c, restated here in our own form): the world point W is
// the joint point J turned about the tilt line (A along X through (·, yr + dy, zr + dz), or B along Y
// through (xr + dx, ·, zr + dz)) and then about the C line (through (xr, yr) along Z), each by minus
// its command times s, s = +1 for conventional-directions = 0 (the table turns right-handed about
// +X/+Y, +Z) and -1 for 1: W = Rc(-s·c) · (Rt(-s·t) · (J - p_t) + p_t - p_c) + p_c.
// SINUMERIK CYCLE800 type P: M_T_table = Trans(l2) Rot(v1,θ1) Trans(l3) Rot(v2,θ2) Trans(l4), and the
// tip in the table frame is M_T_table⁻¹ · (X, Y, Z).
// Expected: the control's tip equals ncpost's model (the held terms for LinuxCNC, the whole
// location model for Siemens) within 0.1 µm at 200 random poses; the left-out effects in the file
// equal this test's own evaluation at the poses of the documented rule (docs/formats.md).
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <regex>
#include <sstream>

#include "ncpost/compensation/export_cycle800.hpp"
#include "ncpost/compensation/export_linuxcnc_trt.hpp"
#include "ncpost/compensation/model_json.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "cli_run.hpp"
#include "temp_dir.hpp"
#include "test_paths.hpp"

using namespace ncpost;
using namespace ncpost::comp;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
const ExportSource kSource{"model.json", "machine.toml", "test"};

/// Rotation of a point about a line (point p, unit direction u) by angle (right-handed), Rodrigues.
Vec3d turned(const Vec3d& x, const Vec3d& p, const Vec3d& u, double angle) {
  const Vec3d v = x - p;
  return p + v * std::cos(angle) + u.cross(v) * std::sin(angle) + u * u.dot(v) * (1.0 - std::cos(angle));
}

/// `setp module.pin value` lines of a HAL file.
std::map<std::string, double> hal_pins(const std::string& text) {
  std::map<std::string, double> pins;
  const std::regex line(R"(^setp [a-z-]+\.([a-z-]+) (\S+)$)");
  std::istringstream in(text);
  for (std::string s; std::getline(in, s);) {
    std::smatch m;
    if (std::regex_match(s, m, line)) pins[m[1]] = std::stod(m[2]);
  }
  return pins;
}

/// LinuxCNC's trt forward kinematics: joints (mm, deg) -> world point (mm).
Vec3d trt_world(const std::map<std::string, double>& pin, char tilt, const Vec3d& joint, double tilt_deg,
                double c_deg) {
  const double s = pin.count("conventional-directions") && pin.at("conventional-directions") == 1.0 ? -1.0 : 1.0;
  const Vec3d c_point(pin.at("x-rot-point"), pin.at("y-rot-point"), pin.at("z-rot-point"));
  const Vec3d tilt_point = tilt == 'A' ? Vec3d(0.0, c_point.y() + pin.at("y-offset"), c_point.z() + pin.at("z-offset"))
                                       : Vec3d(c_point.x() + pin.at("x-offset"), 0.0, c_point.z() + pin.at("z-offset"));
  const Vec3d tilt_axis = tilt == 'A' ? Vec3d::UnitX() : Vec3d::UnitY();
  const Vec3d after_tilt = turned(joint, tilt_point, tilt_axis, -s * tilt_deg * kDeg);
  return turned(after_tilt, c_point, Vec3d::UnitZ(), -s * c_deg * kDeg);
}

/// `$TC_CARRk[1]=value` lines.
std::map<int, double> carr_values(const std::string& text) {
  std::map<int, double> v;
  const std::regex line(R"(^\$TC_CARR(\d+)\[1\]=(-?[0-9.]+)$)");
  std::istringstream in(text);
  for (std::string s; std::getline(in, s);) {
    std::smatch m;
    if (std::regex_match(s, m, line)) v[std::stoi(m[1])] = std::stod(m[2]);
  }
  return v;
}

Vec3d carr_vector(const std::map<int, double>& v, int first) { return {v.at(first), v.at(first + 1), v.at(first + 2)}; }

/// The tip in the table frame by the CYCLE800 type-P chain.
Vec3d cycle800_tip(const std::map<int, double>& v, const Vec3d& linear_mm, double theta1, double theta2) {
  const Vec3d l2 = carr_vector(v, 4), l3 = carr_vector(v, 15), l4 = carr_vector(v, 18);
  const Vec3d v1 = carr_vector(v, 7).normalized(), v2 = carr_vector(v, 10).normalized();
  // M_T_table⁻¹ = Trans(-l4) Rot(v2,-θ2) Trans(-l3) Rot(v1,-θ1) Trans(-l2)
  Vec3d x = linear_mm - l2;
  x = turned(x, Vec3d::Zero(), v1, -theta1) - l3;
  x = turned(x, Vec3d::Zero(), v2, -theta2) - l4;
  return x;
}

/// Random commands within the limits (a rotary axis without limits over one turn).
std::vector<AxisPosition> random_poses(const Machine& m, int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<AxisPosition> out;
  for (int k = 0; k < n; ++k) {
    AxisPosition q = AxisPosition::zero(m.rotary_count());
    for (int i = 0; i < static_cast<int>(m.axes.size()); ++i) {
      const Axis& a = m.axes[static_cast<std::size_t>(i)];
      const double lo = a.limits ? a.limits->min : (a.is_rotary() ? -kPi : -300.0);
      const double hi = a.limits ? a.limits->max : (a.is_rotary() ? kPi : 300.0);
      q[i] = 0.5 * (lo + hi) + 0.5 * (hi - lo) * u(rng);
    }
    out.push_back(q);
  }
  return out;
}

/// The documented rule for the left-out effects (docs/formats.md), written here on its own:
/// linear axes at the quarter points of their travel (±100 mm without limits), the inner rotary axis
/// at its limits and 0, the outer at 0/90/180/270°.
std::vector<AxisPosition> rule_poses(const Machine& m, int inner, int outer) {
  auto linear = [](const Axis& a) {
    if (!a.limits) return std::vector<double>{-100.0, 100.0};
    const double span = a.limits->max - a.limits->min;
    return std::vector<double>{a.limits->min + span / 4.0, a.limits->max - span / 4.0};
  };
  const Axis& t = m.axes[static_cast<std::size_t>(inner)];
  const std::vector<double> tilt =
      t.limits ? std::vector<double>{t.limits->min, 0.0, t.limits->max} : std::vector<double>{-kPi / 2, 0.0, kPi / 2};
  std::vector<AxisPosition> out;
  for (double x : linear(m.axes[0]))
    for (double y : linear(m.axes[1]))
      for (double z : linear(m.axes[2]))
        for (double a : tilt)
          for (double c : {0.0, 90.0, 180.0, 270.0}) {
            AxisPosition q = AxisPosition::zero(m.rotary_count());
            q[0] = x, q[1] = y, q[2] = z, q[inner] = a, q[outer] = c * kDeg;
            out.push_back(q);
          }
  return out;
}

Vec3d model_tip(const MachineModel& model, const AxisPosition& q) { return model.tool_pose(q, Setup{}).tip_mm; }

/// "  NAME   12.345 um  why" and "all together: 12.345 um" lines of an exported file.
std::map<std::string, double> reported_effects(const std::string& text) {
  std::map<std::string, double> out;
  const std::regex term(R"(^[#;]\s+(\S+)\s+([0-9.]+) um  .*$)");
  const std::regex together(R"(^[#;]\s+all together: ([0-9.]+) um.*$)");
  std::istringstream in(text);
  for (std::string s; std::getline(in, s);) {
    std::smatch m;
    if (std::regex_match(s, m, together))
      out["together"] = std::stod(m[1]);
    else if (std::regex_match(s, m, term))
      out[m[1]] = std::stod(m[2]);
  }
  return out;
}

ErrorParameters params(std::initializer_list<std::pair<const char*, double>> list) {
  ErrorParameters p;
  for (const auto& [name, value] : list) p.set(name, value);
  return p;
}

std::string text_of(const std::string& path) {
  std::ifstream in(path);
  REQUIRE(in.good());
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

Machine shipped(const std::string& name) { return load_machine(test::source("machines/" + name + ".toml")); }

}  // namespace

TEST_CASE("linuxcnc-trt: the line offsets alone put the tip where the model does (xyzac, pivots off the origin)") {
  const Machine m = shipped("linuxcnc-xyzac-trt");  // C through (10, 20, 30), A through (·, 25, 45)
  const MachineModel model(m, params({{"EY0A", 0.031}, {"EZ0A", -0.017}, {"EX0C", 0.022}, {"EY0C", -0.041}}));
  const TrtKinematics k = linuxcnc_trt_kinematics(model);
  const std::string text = format_linuxcnc_trt(k, model, kSource);
  const auto pin = hal_pins(text);
  REQUIRE(pin.size() == 6);
  CHECK(text.find("conventional-directions 1") == std::string::npos);
  CHECK(text.find("Left out: nothing") != std::string::npos);
  double worst_um = 0.0;
  for (const AxisPosition& q : random_poses(m, 200, 25)) {
    const Vec3d w = trt_world(pin, 'A', q.linear_mm, q[3] / kDeg, q[4] / kDeg);
    worst_um = std::max(worst_um, (w - model_tip(model, q)).norm() * 1e3);
  }
  CHECK(worst_um < 0.1);
  // and the nominal values of the machine file (the peer test's parameters) plus the offsets
  CHECK(pin.at("x-rot-point") == Approx(10.022).margin(1e-9));
  CHECK(pin.at("y-offset") == Approx(5.0 + 0.031 + 0.041).margin(1e-9));
}

TEST_CASE("linuxcnc-trt: the bundled AC-trunnion identification, tilts left out with their effect") {
  const Machine m = shipped("ac-trunnion");
  const ModelFile file = read_model_json(test::source("samples/measurements/ac-trunnion/model.json"), &m);
  const MachineModel model(m, file.parameters);
  const TrtKinematics k = linuxcnc_trt_kinematics(model);
  const std::string text = format_linuxcnc_trt(k, model, kSource);
  const auto pin = hal_pins(text);
  // the held terms: the model with the offsets only, against LinuxCNC fed with the file
  ErrorParameters offsets;
  for (const char* n : {"EY0A", "EZ0A", "EX0C", "EY0C"}) offsets.set(n, *file.parameters.get(n));
  const MachineModel held(m, offsets);
  double worst_um = 0.0;
  for (const AxisPosition& q : random_poses(m, 200, 26)) {
    const Vec3d w = trt_world(pin, 'A', q.linear_mm, q[3] / kDeg, q[4] / kDeg);
    worst_um = std::max(worst_um, (w - model_tip(held, q)).norm() * 1e3);
  }
  CHECK(worst_um < 0.1);
  // the left-out effects: this test's own evaluation at the documented poses
  const std::map<std::string, double> reported = reported_effects(text);
  const std::vector<AxisPosition> poses = rule_poses(m, 3, 4);
  REQUIRE(poses.size() == 96);
  double together_um = 0.0;
  for (const AxisPosition& q : poses)
    together_um = std::max(
        together_um, (trt_world(pin, 'A', q.linear_mm, q[3] / kDeg, q[4] / kDeg) - model_tip(model, q)).norm() * 1e3);
  REQUIRE(reported.count("together"));
  CHECK(reported.at("together") == Approx(together_um).margin(0.002));
  CHECK(together_um > 10.0);  // tilts of 25..44 µrad at a few hundred mm: tens of µm, not a rounding
  for (const char* tilt : {"EB0A", "EC0A", "EA0C", "EB0C"}) {
    ErrorParameters without = file.parameters;
    without.erase(tilt);
    const MachineModel other(m, without);
    double effect_um = 0.0;
    for (const AxisPosition& q : poses)
      effect_um = std::max(effect_um, (model_tip(model, q) - model_tip(other, q)).norm() * 1e3);
    INFO(tilt);
    REQUIRE(reported.count(tilt));
    CHECK(reported.at(tilt) == Approx(effect_um).margin(0.002));
  }
  CHECK(reported.size() == 5);
}

TEST_CASE("linuxcnc-trt: xyzbc with the conventional directions (Haas-like B C table), zero errors left out") {
  const Machine m = shipped("haas-umc750");  // B along -Y, C along -Z: conventional-directions = 1
  const MachineModel model(
      m,
      params(
          {{"EX0B", 0.027}, {"EZ0B", -0.013}, {"EX0C", -0.019}, {"EY0C", 0.033}, {"EB0B", 40e-6}, {"EC0C", -30e-6}}));
  const TrtKinematics k = linuxcnc_trt_kinematics(model);
  CHECK(k.module == "xyzbc-trt-kins");
  const std::string text = format_linuxcnc_trt(k, model, kSource);
  const auto pin = hal_pins(text);
  REQUIRE(pin.count("conventional-directions"));
  CHECK(text.find("HOME_OFFSET") != std::string::npos);
  const MachineModel held(m, params({{"EX0B", 0.027}, {"EZ0B", -0.013}, {"EX0C", -0.019}, {"EY0C", 0.033}}));
  double worst_um = 0.0;
  for (const AxisPosition& q : random_poses(m, 200, 27)) {
    const Vec3d w = trt_world(pin, 'B', q.linear_mm, q[3] / kDeg, q[4] / kDeg);
    worst_um = std::max(worst_um, (w - model_tip(held, q)).norm() * 1e3);
  }
  CHECK(worst_um < 0.1);
  const auto reported = reported_effects(text);
  REQUIRE(reported.count("EB0B"));
  REQUIRE(reported.count("EC0C"));
  CHECK(reported.at("EB0B") > 1.0);  // the zero error of B turns the table: it matters
}

TEST_CASE("siemens-cycle800: the record holds offsets, tilts and zero errors (type P)") {
  for (const std::string name : {"linuxcnc-xyzac-trt", "haas-umc750", "ac-trunnion"}) {
    const Machine m = shipped(name);
    const char t = m.rotary(0).letter;
    ErrorParameters p;
    const std::string tl(1, t);
    if (t == 'A') {
      p = params({{"EY0A", 0.021}, {"EZ0A", -0.015}, {"EB0A", 35e-6}, {"EC0A", -28e-6}, {"EA0A", 22e-6}});
    } else {
      p = params({{"EX0B", 0.021}, {"EZ0B", -0.015}, {"EA0B", 35e-6}, {"EC0B", -28e-6}, {"EB0B", 22e-6}});
    }
    for (const auto& [n, v] : {std::pair<const char*, double>{"EX0C", -0.012},
                               {"EY0C", 0.019},
                               {"EA0C", -25e-6},
                               {"EB0C", 44e-6},
                               {"EC0C", 17e-6}})
      p.set(n, v);
    const MachineModel model(m, p);
    const Cycle800Record r = cycle800_record(model);
    const std::string text = format_cycle800(r, model, kSource);
    const auto v = carr_values(text);
    REQUIRE(v.size() == 18);
    CHECK(text.find("$TC_CARR23[1]=\"P\"") != std::string::npos);
    CHECK(text.find("Left out: nothing") != std::string::npos);
    double worst_um = 0.0;
    for (const AxisPosition& q : random_poses(m, 200, 28)) {
      const Vec3d tip = cycle800_tip(v, q.linear_mm, q[3], q[4]);
      worst_um = std::max(worst_um, (tip - model_tip(model, q)).norm() * 1e3);
    }
    INFO(name << ": " << worst_um << " um");
    std::cout << "CYCLE800 " << name << ": " << worst_um << " um at 200 random poses\n";
    CHECK(worst_um < 0.1);
  }
}

TEST_CASE("siemens-cycle800: a function of position is left out with the effect this test evaluates") {
  const Machine m = shipped("ac-trunnion");
  const ModelFile file = read_model_json(test::source("samples/measurements/ac-trunnion/model.json"), &m);
  ErrorParameters p = file.parameters;
  p.set("EXC:h2:cos", 0.004);  // a 4 µm radial wobble of C, twice a turn
  const MachineModel model(m, p);
  const Cycle800Record r = cycle800_record(model);
  const std::string text = format_cycle800(r, model, kSource);
  const auto v = carr_values(text);
  const auto reported = reported_effects(text);
  REQUIRE(reported.count("together"));
  double together_um = 0.0;
  for (const AxisPosition& q : rule_poses(m, 3, 4))
    together_um = std::max(together_um, (cycle800_tip(v, q.linear_mm, q[3], q[4]) - model_tip(model, q)).norm() * 1e3);
  CHECK(reported.at("together") == Approx(together_um).margin(0.002));
  CHECK(together_um > 1.0);
}

TEST_CASE("the README's example files (docs/exports/) are the bundled AC-trunnion identification's") {
  const Machine m = shipped("ac-trunnion");
  const ModelFile file = read_model_json(test::source("samples/measurements/ac-trunnion/model.json"), &m);
  const MachineModel model(m, file.parameters);
  ErrorParameters offsets;
  for (const char* n : {"EY0A", "EZ0A", "EX0C", "EY0C"}) offsets.set(n, *file.parameters.get(n));
  const MachineModel held(m, offsets);
  const auto pin = hal_pins(text_of(test::source("docs/exports/ac-trunnion-xyzac-trt.hal")));
  const auto carr = carr_values(text_of(test::source("docs/exports/ac-trunnion-cycle800.spf")));
  REQUIRE(pin.size() == 6);
  REQUIRE(carr.size() == 18);
  double trt_um = 0.0, cycle800_um = 0.0;
  for (const AxisPosition& q : random_poses(m, 100, 29)) {
    trt_um = std::max(trt_um,
                      (trt_world(pin, 'A', q.linear_mm, q[3] / kDeg, q[4] / kDeg) - model_tip(held, q)).norm() * 1e3);
    cycle800_um =
        std::max(cycle800_um, (cycle800_tip(carr, q.linear_mm, q[3], q[4]) - model_tip(model, q)).norm() * 1e3);
  }
  std::cout << "docs/exports round trip at 100 random poses: xyzac-trt " << trt_um << " um (held terms), CYCLE800 "
            << cycle800_um << " um (whole model)\n";
  CHECK(trt_um < 0.1);
  CHECK(cycle800_um < 0.1);
}

/// The lines of a file that carry numbers or the left-out list (not the header naming paths and version).
std::string body_of(const std::string& text) {
  std::string out;
  std::istringstream in(text);
  for (std::string s; std::getline(in, s);)
    if (s.rfind("setp", 0) == 0 || s.rfind("$TC_CARR", 0) == 0 || s.find(" um") != std::string::npos) out += s + "\n";
  return out;
}

TEST_CASE(
    "ncpost export --format linuxcnc-trt | siemens-cycle800: exit codes, and the docs/exports files are current") {
  const std::string dir = test::make_temp_dir("export_kinematics");
  const std::string model = test::source("samples/measurements/ac-trunnion/model.json");
  const std::string machine = test::source("machines/ac-trunnion.toml");
  const std::string log = dir + "/log.txt";
  for (const auto& [format, docs_file] :
       {std::pair<std::string, std::string>{"linuxcnc-trt", "ac-trunnion-xyzac-trt.hal"},
        {"siemens-cycle800", "ac-trunnion-cycle800.spf"}}) {
    const std::string out = dir + "/" + docs_file;
    REQUIRE(test::run_ncpost("export --format " + format + " --machine " + machine + " -o " + out + " " + model, log) ==
            0);
    const std::string written = text_of(out);
    INFO(format);
    CHECK(!body_of(written).empty());
    CHECK(body_of(written) == body_of(text_of(test::source("docs/exports/" + docs_file))));
    // --axis belongs to the one-axis tables; no --machine: refused before anything is written
    CHECK(test::run_ncpost(
              "export --format " + format + " --axis C --machine " + machine + " -o " + dir + "/x " + model, log) == 1);
    CHECK(test::run_ncpost("export --format " + format + " -o " + dir + "/x " + model, log) == 1);
    CHECK_FALSE(std::ifstream(dir + "/x").good());
  }
  // the LinuxCNC warning names the tilts on stderr
  test::run_ncpost("export --format linuxcnc-trt --machine " + machine + " -o " + dir + "/y.hal " + model, log);
  CHECK(text_of(log).find("EB0C       up to") != std::string::npos);
}

TEST_CASE("kinematics exports refuse machines they cannot describe") {
  const Machine head = shipped("gantry-bc-head");
  const MachineModel model(head, params({{"EX0C", 0.01}}));
  CHECK_THROWS_AS(linuxcnc_trt_kinematics(model), ExportRefusal);
  CHECK_THROWS_AS(cycle800_record(model), ExportRefusal);
  const Machine ac = shipped("ac-trunnion");
  const MachineModel no_location(ac, params({{"EXC:h2:cos", 0.004}}));
  CHECK_THROWS_AS(linuxcnc_trt_kinematics(no_location), ExportRefusal);
  CHECK_THROWS_AS(cycle800_record(no_location), ExportRefusal);
}
