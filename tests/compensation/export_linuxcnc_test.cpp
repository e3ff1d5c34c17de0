// SPDX-License-Identifier: Apache-2.0
// Issue 17, `ncpost export --format linuxcnc`: the exported COMP_FILE applied the way LinuxCNC
// applies it (usrmotintf.cc usrmotLoadComp: rows of three numbers until the first other line,
// COMP_FILE_TYPE 1 trims; control.c compute_screw_comp: the trim of the direction of motion,
// interpolated linearly in the commanded position, the end trims held beyond the rows, added to
// the commanded position) on the machine the model describes: the axis lands on the commanded
// position within 0.5 µm at every row, where the model alone is off by micrometres. A sign error
// would double the error instead.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "axis_actual_position.hpp"
#include "cli_run.hpp"
#include "ncpost/compensation/export_linuxcnc.hpp"
#include "ncpost/compensation/model_json.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "test_paths.hpp"

using namespace ncpost;
using namespace ncpost::comp;

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

/// What LinuxCNC loads from a COMP_FILE: rows of three numbers up to the first other line.
std::vector<std::array<double, 3>> load_like_linuxcnc(const std::string& text) {
  std::vector<std::array<double, 3>> rows;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::array<double, 3> r{};
    if (std::sscanf(line.c_str(), "%lf %lf %lf", &r[0], &r[1], &r[2]) != 3) break;
    rows.push_back(r);
  }
  return rows;
}

/// compute_screw_comp: the trim at commanded position n moving forward (or in reverse).
double linuxcnc_trim(const std::vector<std::array<double, 3>>& rows, double n, bool forward) {
  const int c = forward ? 1 : 2;
  if (n < rows.front()[0]) return rows.front()[c];
  for (std::size_t i = 0; i + 1 < rows.size(); ++i)
    if (n < rows[i + 1][0])
      return rows[i][c] + (rows[i + 1][c] - rows[i][c]) * (n - rows[i][0]) / (rows[i + 1][0] - rows[i][0]);
  return rows.back()[c];
}

using test::actual_position;

struct Residual {
  double max_compensated = 0.0;  ///< mm or rad
  double max_model = 0.0;        ///< the model's own error without the table
};

/// Applies the file at every row and midway between rows, both directions.
Residual apply_file(const MachineModel& model, char letter, const std::string& text) {
  const int axis = model.machine().index_of(letter);
  const bool rotary = model.machine().axes[axis].is_rotary();
  const double unit = rotary ? kDeg : 1.0;
  const auto rows = load_like_linuxcnc(text);
  REQUIRE(rows.size() >= 2);
  REQUIRE(rows.size() <= 256);
  for (std::size_t i = 0; i + 1 < rows.size(); ++i) REQUIRE(rows[i][0] < rows[i + 1][0]);  // ascending
  std::vector<double> nominals;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    nominals.push_back(rows[i][0]);
    if (i + 1 < rows.size()) nominals.push_back(0.5 * (rows[i][0] + rows[i + 1][0]));
  }
  Residual r;
  for (double n_file : nominals)
    for (bool forward : {true, false}) {
      const double n = n_file * unit;
      const double motor = (n_file + linuxcnc_trim(rows, n_file, forward)) * unit;
      const double turn = rotary ? 2.0 * 3.14159265358979323846 : 0.0;  // a rotary position modulo one turn
      auto off = [&](double actual) { return std::abs(rotary ? std::remainder(actual - n, turn) : actual - n); };
      r.max_compensated = std::max(r.max_compensated, off(actual_position(model, axis, motor, !forward)));
      r.max_model = std::max(r.max_model, off(actual_position(model, axis, n, !forward)));
    }
  return r;
}

}  // namespace

TEST_CASE("linuxcnc export: +10 µm EXX at X=100 gives a trim of -10 µm and the axis lands on nominal", "[export]") {
  const Machine m = load_machine(test::source("machines/vmcl600.toml"));
  ErrorParameters p;
  p.set("EXX:t:0", 0.0);
  p.set("EXX:t:100", 0.010);
  p.set("EXX:t:200", 0.004);
  p.set("reversal:X", 0.003);
  p.set("EYX:t:100", 0.002);  // not a positioning error: listed as left out
  const MachineModel model(m, p);
  const LinuxcncCompTable table = linuxcnc_comp_table(model, 'X');
  const std::string text = format_linuxcnc_comp(table, model, {"model.json", "vmcl600.toml", "test"});
  const auto rows = load_like_linuxcnc(text);
  // the table covers the travel (-300..300) and the model's nodes
  REQUIRE(rows.front()[0] == Approx(-300.0));
  REQUIRE(rows.back()[0] == Approx(300.0));
  bool found = false;
  for (const auto& r : rows)
    if (r[0] == 100.0) {
      found = true;
      // forward: the axis goes 10 µm too far, the command 10 µm short (exactly -9.999 µm: the error at 99.99)
      CHECK(r[1] == Approx(-0.010).margin(2e-6));
      CHECK(r[2] == Approx(-0.013).margin(2e-6));  // reverse: and the 3 µm play on top
    }
  CHECK(found);
  // uncompensated the axis is 10 µm long at X=100; compensated on nominal; the other sign would be 20 µm off
  const int x = 0;
  CHECK(actual_position(model, x, 100.0, false) - 100.0 == Approx(0.010).margin(1e-9));
  CHECK(actual_position(model, x, 100.0 + linuxcnc_trim(rows, 100.0, true), false) - 100.0 == Approx(0.0).margin(1e-7));
  CHECK(actual_position(model, x, 100.0 - linuxcnc_trim(rows, 100.0, true), false) - 100.0 ==
        Approx(0.020).margin(3e-6));
  const Residual r = apply_file(model, 'X', text);
  CHECK(r.max_model > 0.012);
  CHECK(r.max_compensated < 0.5e-3);
  // exact at the rows, and between them but for the second-order effect of the kinks at the nodes
  CHECK(r.max_compensated < 2e-6);
  // notes after the rows (LinuxCNC stops at the first other line), naming type and sign and the left-out term
  CHECK(text.find("COMP_FILE_TYPE = 1") != std::string::npos);
  CHECK(text.find("Sign: trim = -(the model's positioning error of X)") != std::string::npos);
  CHECK(text.find("EYX:t (") != std::string::npos);
  CHECK(text.find("Left out (NOT compensated by this file): 1 term(s)") != std::string::npos);
}

TEST_CASE("linuxcnc export: the VMCL600 laser model, X Y Z within 0.5 µm at every row", "[export]") {
  const Machine m = load_machine(test::source("machines/vmcl600.toml"));
  const ModelFile file = read_model_json(test::source("samples/measurements/vmcl600/model.json"), &m);
  const MachineModel model(m, file.parameters);
  for (char letter : {'X', 'Y', 'Z'}) {
    INFO("axis " << letter);
    const LinuxcncCompTable table = linuxcnc_comp_table(model, letter);
    const std::string text = format_linuxcnc_comp(table, model, {"model.json", "", "test"});
    const Residual r = apply_file(model, letter, text);
    CHECK(r.max_model > 0.005);         // the model's error is micrometres ...
    CHECK(r.max_compensated < 0.5e-3);  // ... the table takes it below 0.5 µm
    CHECK(table.axis.reversal > 0.0);   // the laser model's reversal is in the reverse column
    CHECK(table.axis.left_out.size() >= 5);
  }
}

TEST_CASE("linuxcnc export: rotary axes (continuous C one turn, A within its limits)", "[export]") {
  const Machine m = load_machine(test::source("machines/ac-trunnion.toml"));
  ErrorParameters p;
  p.set("ECC:h1:cos", 40e-6);
  p.set("ECC:h2:sin", -25e-6);
  p.set("ECC:h4:cos", 8e-6);
  p.set("reversal:C", 30e-6);
  p.set("EAA:h1:sin", 20e-6);
  p.set("EY0C", 0.02);  // location: left out of a one-axis table
  const MachineModel model(m, p);
  for (char letter : {'C', 'A'}) {
    INFO("axis " << letter);
    const LinuxcncCompTable table = linuxcnc_comp_table(model, letter);
    const std::string text = format_linuxcnc_comp(table, model, {"model.json", "ac-trunnion.toml", "test"});
    const auto rows = load_like_linuxcnc(text);
    CHECK(rows.front()[0] == Approx(letter == 'C' ? 0.0 : -120.0));
    CHECK(rows.back()[0] == Approx(letter == 'C' ? 360.0 : 120.0));
    const Residual r = apply_file(model, letter, text);
    CHECK(r.max_model > (letter == 'C' ? 50e-6 : 15e-6));
    // at a radius of 250 mm, 0.5 µm is 2 µrad: at the rows exact, between them the interpolation of the harmonics
    CHECK(r.max_compensated * 250.0 < 0.5e-3);
  }
  const LinuxcncCompTable c = linuxcnc_comp_table(model, 'C');
  CHECK(c.axis.continuous);
  CHECK(c.axis.left_out.size() == 1);
  CHECK(c.axis.left_out[0].rfind("EY0C (", 0) == 0);
}

TEST_CASE("linuxcnc export on the command line: refusals and the file", "[export][cli]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("ncpost_export_cli_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string d = dir.string() + "/";
  const std::string model = test::source("samples/measurements/vmcl600/model.json");
  const std::string machine = " --machine " + test::source("machines/vmcl600.toml");
  REQUIRE(test::run_ncpost("export --format linuxcnc --axis X" + machine + " -o " + d + "x.comp " + model, d + "log") ==
          0);
  const std::string text = test::read_text_file(d + "x.comp");
  CHECK(text.rfind("-300.000000 ", 0) == 0);  // a row first: no comment before the rows
  CHECK(test::read_text_file(d + "log").find("EZX:t (") != std::string::npos);  // left-out terms on stderr
  // without --machine a three-axis model is read against X Y Z (the table then covers the model's nodes)
  REQUIRE(test::run_ncpost("export --format linuxcnc --axis Y -o " + d + "y.comp " + model, d + "log") == 0);
  // several axes have tables: --axis is needed (usage)
  CHECK(test::run_ncpost("export --format linuxcnc" + machine + " -o " + d + "z.comp " + model, d + "log") == 1);
  // the axis the machine lacks; an axis without a table: bad input, naming the model file
  CHECK(test::run_ncpost("export --format linuxcnc --axis C" + machine + " -o " + d + "c.comp " + model, d + "log") ==
        2);
  CHECK(test::read_text_file(d + "log").find(model + ": the machine 'vmcl600' has no axis C (its axes: XYZ)") !=
        std::string::npos);
  CHECK(test::run_ncpost("export --format linuxcnc --axis Q" + machine + " -o " + d + "c.comp " + model, d + "log") ==
        1);
  const std::string ac = test::source("samples/measurements/ac-trunnion/model.json");
  const std::string ac_machine = " --machine " + test::source("machines/ac-trunnion.toml");
  CHECK(test::run_ncpost("export --format linuxcnc --axis X" + ac_machine + " -o " + d + "x2.comp " + ac, d + "log") ==
        2);
  const std::string log = test::read_text_file(d + "log");
  CHECK(log.find(ac + ": the model has no positioning error (EXX) and no reversal (reversal:X)") != std::string::npos);
  CHECK(!fs::exists(d + "x2.comp"));
  // the output is the input: refused before anything is written (usage, as for every command)
  CHECK(test::run_ncpost("export --format linuxcnc --axis X" + machine + " -o " + model + " " + model, d + "log") == 1);
  CHECK(test::read_text_file(d + "log").find("model.json") != std::string::npos);
  CHECK(test::run_ncpost("export --format heidenhain --axis X" + machine + " -o " + d + "h " + model, d + "log") == 1);
  fs::remove_all(dir);
}

TEST_CASE("linuxcnc export: a polynomial error is sampled over the limits, within 0.5 µm between rows too",
          "[export]") {
  const Machine m = load_machine(test::source("machines/vmcl600.toml"));
  ErrorParameters p;
  p.set("EXY:p1", 20e-6);   // straightness of Y in X: left out of the Y table
  p.set("EYY:p1", 40e-6);   // 40 µm/m scale error
  p.set("EYY:p2", 1.5e-7);  // a bow: 6.6 µm at the ends
  p.set("EYY:p3", -2e-10);
  p.set("reversal:Y", 0.002);
  const MachineModel model(m, p);
  const LinuxcncCompTable table = linuxcnc_comp_table(model, 'Y');
  CHECK_FALSE(table.axis.piecewise_linear);
  CHECK(table.rows.size() <= 256);
  CHECK(table.rows.front()[0] == Approx(-210.0));
  CHECK(table.rows.back()[0] == Approx(210.0));
  REQUIRE(table.axis.left_out.size() == 1);
  CHECK(table.axis.left_out[0].rfind("EXY:p1 (", 0) == 0);
  const Residual r = apply_file(model, 'Y', format_linuxcnc_comp(table, model, {"m.json", "", "test"}));
  CHECK(r.max_model > 0.012);
  CHECK(r.max_compensated < 0.5e-3);
  // without limits in the machine file a polynomial has no end: refused, naming the machine
  Machine unlimited = m;
  unlimited.axes[1].limits.reset();
  const MachineModel open_model(unlimited, p);
  try {
    (void)linuxcnc_comp_table(open_model, 'Y');
    FAIL("no refusal");
  } catch (const ExportRefusal& e) {
    CHECK(e.source == ExportRefusal::Source::machine);
  }
}
