// SPDX-License-Identifier: Apache-2.0
// Issue 17, `ncpost export --format siemens`: the SINUMERIK LEC table ($AA_ENC_COMP) applied as the
// Function Manual (Extended Functions, K3 "Interpolatory compensation") says the control applies it:
// the compensation value, interpolated linearly between equidistant points from $AA_ENC_COMP_MIN
// every $AA_ENC_COMP_STEP (the first and last values held beyond them), modifies the measured
// actual position, and "a positive compensation value causes the corresponding machine axis to
// move in the negative direction": the position loop settles where m + c(m) = n. The axis must then
// actually be at n within 0.5 µm at every point.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <regex>
#include <sstream>

#include "ncpost/compensation/export_siemens.hpp"
#include "ncpost/compensation/model_json.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "test_paths.hpp"

using namespace ncpost;
using namespace ncpost::comp;

namespace {

struct Lec {
  std::vector<double> values;
  double step = 0.0, min = 0.0, max = 0.0;
};

/// The assignments of the program, as the control reads them.
Lec read_lec(const std::string& text, const std::string& axis_name) {
  Lec lec;
  std::map<int, double> values;
  const std::regex value("^\\$AA_ENC_COMP\\[0,(\\d+)," + axis_name + "\\]=(\\S+)$");
  const std::regex param("^\\$AA_ENC_COMP_(STEP|MIN|MAX)\\[0," + axis_name + "\\]=(\\S+)$");
  std::istringstream in(text);
  std::string line;
  std::smatch m;
  while (std::getline(in, line)) {
    if (std::regex_match(line, m, value)) values[std::stoi(m[1])] = std::stod(m[2]);
    if (std::regex_match(line, m, param)) {
      const double v = std::stod(m[2]);
      if (m[1] == "STEP")
        lec.step = v;
      else if (m[1] == "MIN")
        lec.min = v;
      else
        lec.max = v;
    }
  }
  for (int n = 0; n < static_cast<int>(values.size()); ++n) {
    REQUIRE(values.count(n) == 1);
    lec.values.push_back(values[n]);
  }
  return lec;
}

double lec_value(const Lec& lec, double position) {
  if (position <= lec.min) return lec.values.front();
  const double k = (position - lec.min) / lec.step;
  const auto i = static_cast<std::size_t>(std::floor(k));
  if (i + 1 >= lec.values.size()) return lec.values.back();
  return lec.values[i] + (k - i) * (lec.values[i + 1] - lec.values[i]);
}

/// Where the tool actually is along the linear axis at measured (encoder) position m.
double actual_position(const MachineModel& model, int axis, double m) {
  AxisPosition q;
  q[axis] = m;
  return model.tool_pose(q, Setup{}).tip_mm.dot(model.machine().axes[axis].direction);
}

/// Largest |actual − commanded| over every point and midway, with the table; and without it.
std::pair<double, double> apply_lec(const MachineModel& model, int axis, const Lec& lec) {
  double with = 0.0, without = 0.0;
  for (std::size_t k = 0; 2 * k + 1 < 2 * lec.values.size(); ++k)
    for (double f : {0.0, 0.5}) {
      const double n = lec.min + (k + f) * lec.step;
      if (n > lec.max + 1e-9) continue;
      double m = n;
      for (int it = 0; it < 50; ++it) m = n - lec_value(lec, m);  // the loop: m + c(m) = n
      with = std::max(with, std::abs(actual_position(model, axis, m) - n));
      without = std::max(without, std::abs(actual_position(model, axis, n) - n));
    }
  return {with, without};
}

}  // namespace

TEST_CASE("siemens export: +10 µm EXX at X=100 is a value of +0.010 and the axis lands on nominal", "[export]") {
  const Machine m = load_machine(test::source("machines/vmcl600.toml"));
  ErrorParameters p;
  p.set("EXX:t:0", 0.0);
  p.set("EXX:t:100", 0.010);
  p.set("EXX:t:200", 0.004);
  p.set("reversal:X", 0.003);
  const MachineModel model(m, p);
  const SiemensLecTable table = siemens_lec_table(model, 'X');
  const std::string text = format_siemens_lec(table, model, {"model.json", "vmcl600.toml", "test"});
  const Lec lec = read_lec(text, "X1");
  CHECK(lec.min == -300.0);
  CHECK(lec.max == 300.0);
  CHECK(lec.step == 100.0);  // the model's nodes and the travel ends on one grid
  REQUIRE(lec.values.size() == 7);
  CHECK(lec.values[4] == Approx(0.010).margin(1e-9));  // X = 100: the error itself, positive
  const auto [with, without] = apply_lec(model, 0, lec);
  CHECK(without == Approx(0.010).margin(1e-9));
  CHECK(with < 1e-6);
  // the sign the other way round would double it
  double m_wrong = 100.0;
  for (int it = 0; it < 50; ++it) m_wrong = 100.0 + lec_value(lec, m_wrong);
  CHECK(actual_position(model, 0, m_wrong) - 100.0 == Approx(0.020).margin(2e-6));
  // the reversal is one direction's only: listed as left out, with the value
  CHECK(text.find("reversal:X (0.003 mm") != std::string::npos);
  CHECK(text.find("$AA_ENC_COMP_IS_MODULO[0,X1]=0") != std::string::npos);
  CHECK(text.rfind("%_N_AX_EEC_INI\n", 0) == 0);
  CHECK(text.substr(text.size() - 4) == "M17\n");
}

TEST_CASE("siemens export: the VMCL600 laser model, X Y Z within 0.5 µm at every point", "[export]") {
  const Machine m = load_machine(test::source("machines/vmcl600.toml"));
  const ModelFile file = read_model_json(test::source("samples/measurements/vmcl600/model.json"), &m);
  const MachineModel model(m, file.parameters);
  for (char letter : {'X', 'Y', 'Z'}) {
    INFO("axis " << letter);
    const SiemensLecTable table = siemens_lec_table(model, letter);
    const Lec lec =
        read_lec(format_siemens_lec(table, model, {"model.json", "", "test"}), std::string(1, letter) + "1");
    const auto [with, without] = apply_lec(model, m.index_of(letter), lec);
    CHECK(without > 0.005);
    CHECK(with < 0.5e-3);
    CHECK(table.nodes_on_grid);
    CHECK(table.landing.with_file < 1e-6);  // the file's own round trip, moving up
  }
}

TEST_CASE("siemens export: an axis with only a reversal has nothing for the table", "[export]") {
  const Machine m = load_machine(test::source("machines/vmcl600.toml"));
  ErrorParameters p;
  p.set("reversal:Y", 0.003);
  const MachineModel model(m, p);
  CHECK_THROWS_AS(siemens_lec_table(model, 'Y'), ExportRefusal);
  CHECK_THROWS_AS(siemens_lec_table(model, 'X'), ExportRefusal);
}
