// SPDX-License-Identifier: Apache-2.0
// Issue 25 item 5: the one-page summary of an identification carries the machine, the conditions,
// the key figures with U (k = 2) and their ISO 14253-1 verdicts, and a signature block. Figures
// worked out by hand: a one-way C run with ΔL = 6 cos 2C µm has G = 12 µm exactly.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <cmath>
#include <string>

#include "ncpost/compensation/identify_summary.hpp"
#include "ncpost/compensation/measurement_csv.hpp"
#include "ncpost/machines/machine_file.hpp"

using namespace ncpost;
using namespace ncpost::comp;

namespace {

MeasurementSet one_way_ballbar(const Machine& m) {
  std::string csv =
      "# type: ballbar\n# table_ball: 0, -100, 0\n# tool_ball: 0, 0, 0\n# bar_length: 100\n"
      "# instrument_uncertainty: 0.2\n# date: 2026-11-20T09:30\n# temperature: 20.4\n"
      "# operator: A. Metrologist\nt,X,Y,Z,A,C,L\n";
  for (int c = 0; c < 360; c += 10)
    csv += fmt::format("{},0,0,0,0,{},{:.9f}\n", c, c, 100.0 + 6e-3 * std::cos(2.0 * c * M_PI / 180.0));
  return parse_measurement_csv(csv, "ballbar_c.csv", m);
}

/// One C run of the test of one_way_ballbar in one file: counter-clockwise 0…350° (step 10°) or
/// clockwise 350…0°, ΔL = 6 cos 2C + lift µm.
MeasurementSet c_run(const Machine& m, bool clockwise, double lift_um, double bar_mm, const std::string& file) {
  std::string csv = fmt::format(
      "# type: ballbar\n# table_ball: 0, -100, 0\n# tool_ball: 0, 0, 0\n# bar_length: {}\n"
      "# instrument_uncertainty: 0.2\nt,X,Y,Z,A,C,L\n",
      bar_mm);
  for (int k = 0; k < 36; ++k) {
    const int c = clockwise ? 350 - 10 * k : 10 * k;
    csv +=
        fmt::format("{},0,0,0,0,{},{:.9f}\n", k, c, bar_mm + 1e-3 * (6.0 * std::cos(2.0 * c * M_PI / 180.0) + lift_um));
  }
  return parse_measurement_csv(csv, file, m);
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("identification summary: machine, conditions, figures with U and verdicts, signatures", "[summary]") {
  const Machine m = load_machine(std::string(NCPOST_SOURCE_DIR) + "/machines/ac-trunnion.toml");
  const std::vector<MeasurementSet> sets{one_way_ballbar(m)};
  IdentifyResult r;
  r.parameters.set("EY0A", 0.025);  // mm: 25 µm, u 0.05 µm → U 0.1 µm
  r.uncertainty.set("EY0A", 5e-5);
  r.parameters.set("EB0A", 30e-6);  // rad: 30 µrad, u 0.3 µrad → U 0.6 µrad
  r.uncertainty.set("EB0A", 3e-7);
  r.files.push_back({"ballbar_c.csv", MeasurementType::ballbar, 36, 20.0, 46.0, 0.5, 1.4});
  IdentifyReportInputs in;
  in.pass_tolerance_um = 5.0;
  in.tolerances.by_kind_um["G"] = 10.0;
  in.machine_record.serial = "SN-0042";
  const IdentificationSummary s = identification_summary(m, sets, r, in, "out/identify.html");
  const std::string html = summary_page_html(s);
  CHECK(has(html, "ac-trunnion"));
  CHECK(has(html, "SN-0042"));
  CHECK(has(html, "2026-11-20T09:30"));
  CHECK(has(html, "20.40 °C"));
  CHECK(has(html, "A. Metrologist"));
  // G = 2 × 6 µm; U = 2 × √2 × 0.2 / 2 = 0.28 µm (instrument only); 12 − 0.28 > 10: FAIL
  CHECK(has(html, "ballbar_c.csv: G (ISO 230-4)</td><td>12.00 ± 0.28"));
  CHECK(has(html, "G ≤ 10 µm</td><td class=\"fail\">FAIL"));
  // the largest deviation ± U of one reading (0.2 µm) against 5 µm: 46 FAIL, 1.4 PASS
  CHECK(has(html, "machine as it is</td><td>46.00 ± 0.20"));
  CHECK(has(html, "with the model</td><td>1.40 ± 0.20"));
  CHECK(has(html, "class=\"pass\">PASS"));
  CHECK(has(html, "parameter EY0A</td><td>25.000 ± 0.100 µm"));
  CHECK(has(html, "parameter EB0A</td><td>30.000 ± 0.600 µrad"));
  CHECK(has(html, "approved by"));
  CHECK(has(html, "@page{size:A4"));
  CHECK(has(html, "href=\"identify.html\""));
  CHECK(summary_path("out/identify.html") == "out/identify-summary.html");
  CHECK(summary_path("out.d/report") == "out.d/report-summary.html");
}

TEST_CASE("laser identification summary: one row per positioning line, the worst verdict of its kinds", "[summary]") {
  const Machine m = load_machine(std::string(NCPOST_SOURCE_DIR) + "/machines/vmcl600.toml");
  const MeasurementSet set = parse_measurement_csv(
      "# type: laser\n# axis: X\n# component: X\n# tool_point: 0, 0, 0\n# instrument_uncertainty: 0.4\n"
      "t,run,X,Y,Z,e_um\n0,1,0,0,0,0\n1,1,100,0,0,1\n",
      "x1.csv", m);
  LaserIdentifyResult r;
  Iso230Figures g;
  g.axis = 'X';
  g.file = "x1.csv";
  g.accuracy_A_um = 12.0;
  g.reversal_B_um = 3.0;
  g.systematic_E_um = 10.0;
  g.mean_bidirectional_M_um = 8.0;
  g.repeatability_R_um = 4.0;
  Iso230Target t;
  t.s_up_um = 0.5;
  t.s_down_um = 0.3;
  t.runs_up = t.runs_down = 5;
  g.targets = {t};
  r.iso230 = {g};
  IdentifyReportInputs in;
  in.tolerances.by_kind_um = {{"A", 10.0}, {"B", 5.0}};
  const std::string html = summary_page_html(laser_identification_summary(m, {set}, r, in, "laser.html"));
  // U of A: 2 √((√2 × 0.2)² + (√2 × 0.5 / √5)²) = 2 √(0.08 + 0.1) = 0.85; 12 − 0.85 > 10: FAIL;
  // B: 3 + 2 √(0.08 + 0.1) ≤ 5: PASS; the row shows the worse
  CHECK(has(html,
            "x1.csv: ISO 230-2 of X</td><td>A 12.00 ± 0.85; B 3.00 ± 0.85; E 10.00 ± 0.85; M 8.00 ± 0.85; R 4.00 ± "));
  CHECK(has(html, " µm (U lacks temperature)</td>"));  // said once for the row
  CHECK(has(html, "A ≤ 10, B ≤ 5 µm</td><td class=\"fail\">FAIL"));
}

TEST_CASE("identification summary: the hysteresis H of a clockwise and a counter-clockwise run in two files",
          "[summary]") {
  const Machine m = load_machine(std::string(NCPOST_SOURCE_DIR) + "/machines/ac-trunnion.toml");
  // the same angles both ways, the clockwise run lifted by 1.5 µm: H = 1.5 µm (ISO 230-4: the
  // largest radial difference of the two directions at one angle)
  const std::vector<MeasurementSet> pair{c_run(m, false, 0.0, 100.0, "ccw.csv"), c_run(m, true, 1.5, 100.0, "cw.csv")};
  IdentifyResult r;
  const std::string html = summary_page_html(identification_summary(m, pair, r, {}, "out/id.html"));
  CHECK(has(html, "ccw.csv with cw.csv: hysteresis H</td><td>1.50 µm"));
  CHECK_FALSE(has(html, "cw.csv with ccw.csv"));  // one row per pair
  // not a pair: two runs the same way, or another bar
  const std::vector<MeasurementSet> same_way{c_run(m, false, 0.0, 100.0, "a.csv"),
                                             c_run(m, false, 1.5, 100.0, "b.csv")};
  CHECK_FALSE(has(summary_page_html(identification_summary(m, same_way, r, {}, "out/id.html")), "hysteresis"));
  const std::vector<MeasurementSet> other_bar{c_run(m, false, 0.0, 100.0, "a.csv"),
                                              c_run(m, true, 1.5, 150.0, "b.csv")};
  CHECK_FALSE(has(summary_page_html(identification_summary(m, other_bar, r, {}, "out/id.html")), "hysteresis"));
}
