// SPDX-License-Identifier: Apache-2.0
// Issue 25 item 3: measurement conditions in the data files' headers (temperature, expansion,
// instrument, serial, operator, date), the correction of lengths to 20 °C (ISO 1) against hand
// calculations, the notices for unknown keys and the warning for files measured at different
// temperatures.
#include <catch2/catch.hpp>

#include "ncpost/compensation/measurement_csv.hpp"
#include "ncpost/compensation/measurement_files.hpp"
#include "ncpost/compensation/thermal_correction.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "temp_dir.hpp"

using namespace ncpost;
using namespace ncpost::comp;

namespace {

Machine ac() { return load_machine(std::string(NCPOST_SOURCE_DIR) + "/machines/ac-trunnion.toml"); }
Machine vmc() { return load_machine(std::string(NCPOST_SOURCE_DIR) + "/machines/vmcl600.toml"); }

const std::string kConditions =
    "# temperature: 23.5\n# material_expansion: 11.5e-6\n# instrument: QC20-W ballbar\n# serial: B1234\n"
    "# operator: A. Meier\n# date: 2026-11-20T09:30\n";

/// A ballbar file on the AC trunnion: keys, then `extra` header lines, then two rows with L given.
std::string ballbar(const std::string& extra, const std::string& l1 = "100.004025",
                    const std::string& l2 = "100.000000") {
  return "# type: ballbar\n# table_ball: 0, -100, 250\n# tool_ball: 0, 0, 0\n# bar_length: 100.0\n" + extra +
         "t,X,Y,Z,A,C,L\n0.00,0,0,250,0,0," + l1 + "\n0.50,0,-1.57709,249.99503,0.36145,0.72289," + l2 + "\n";
}

std::string error_of(const std::string& text) {
  try {
    parse_measurement_csv(text, "f.csv", ac());
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("the six condition keys are read and kept", "[conditions]") {
  const MeasurementSet s = parse_measurement_csv(ballbar(kConditions), "f.csv", ac());
  REQUIRE(s.conditions.temperature_c);
  CHECK(*s.conditions.temperature_c == 23.5);
  REQUIRE(s.conditions.expansion_per_k);
  CHECK(*s.conditions.expansion_per_k == 11.5e-6);
  CHECK(s.conditions.instrument == "QC20-W ballbar");
  CHECK(s.conditions.serial == "B1234");
  CHECK(s.conditions.operator_name == "A. Meier");
  CHECK(s.conditions.date == "2026-11-20T09:30");
  CHECK(s.notices.empty());
  // written back with the file (simulate writes the plan's header)
  const std::string out = format_measurement_csv(s, ac());
  for (const char* line :
       {"# temperature: 23.5", "# material_expansion: 11.5e-6", "# serial: B1234", "# date: 2026-11-20T09:30"})
    CHECK(contains(out, line));
}

TEST_CASE("ballbar lengths corrected to 20 °C: hand calculation", "[conditions]") {
  MeasurementSet s = parse_measurement_csv(ballbar(kConditions), "f.csv", ac());
  correct_to_20c(s);
  REQUIRE(s.corrected_to_20c);
  // f = 1 + 11.5e-6 /K × (23.5 − 20) K = 1 + 40.25e-6 = 1.00004025
  // row 1: L_T = 100.004025 mm → L_20 = 100.004025 / 1.00004025 = 100.000000 mm (100 × f = 100.004025)
  CHECK(s.rows[0].value[0] == Approx(100.0).epsilon(0).margin(1e-9));
  // row 2: L_T = 100.000000 mm → L_20 = 100 / 1.00004025 = 100 × (1 − 40.25e-6 + (40.25e-6)²) = 99.995975162 mm
  CHECK(s.rows[1].value[0] == Approx(99.995975162).epsilon(0).margin(1e-9));
  // largest change: 100.004025 − 100 = 4.025 µm (row 1); row 2 changes by 4.0248 µm
  CHECK(s.thermal_correction_max_um == Approx(4.025).margin(1e-6));
  correct_to_20c(s);  // a second call changes nothing
  CHECK(s.rows[0].value[0] == Approx(100.0).epsilon(0).margin(1e-9));
}

TEST_CASE("no correction without the coefficient, and none for a file at 20 °C", "[conditions]") {
  MeasurementSet only_t = parse_measurement_csv(ballbar("# temperature: 23.5\n"), "f.csv", ac());
  correct_to_20c(only_t);
  CHECK_FALSE(only_t.corrected_to_20c);
  CHECK(only_t.rows[0].value[0] == 100.004025);
  MeasurementSet at_20 =
      parse_measurement_csv(ballbar("# temperature: 20\n# material_expansion: 11.5e-6\n"), "f.csv", ac());
  correct_to_20c(at_20);
  CHECK(at_20.corrected_to_20c);
  CHECK(at_20.rows[0].value[0] == 100.004025);  // f = 1 exactly
}

TEST_CASE("laser positioning lines corrected to 20 °C, straightness lines not: hand calculation", "[conditions]") {
  const std::string head =
      "# type: laser\n# axis: X\n# tool_point: 0, 0, 0\n# temperature: 25\n# material_expansion: 10e-6\n";
  const std::string rows =
      "t,run,X,Y,Z,e_um\n0,1,0,0,0,0.0\n1,1,100,0,0,5.0\n2,1,200,0,0,12.0\n3,2,0,0,0,1.0\n4,2,100,0,0,6.0\n";
  MeasurementSet pos = parse_measurement_csv(head + "# component: X\n" + rows, "p.csv", vmc());
  correct_to_20c(pos);
  REQUIRE(pos.corrected_to_20c);
  // f = 1 + 10e-6 × (25 − 20) = 1.00005. Run 1 zeroed at X = 0, e = 0:
  //   X = 100: the laser read 100.005 mm → 100.005 / 1.00005 = 100.000 mm → e_20 = 0 µm
  //   X = 200: read 200.012 mm → 200.012 / 1.00005 = 200.002 (200 × 1.00005 = 200.010; 0.002 / 1.00005 = 0.0019999)
  //            → e_20 = 1000 × (200.0019999 − 200) = 1.9999 µm
  CHECK(pos.rows[0].value[0] == Approx(0.0).margin(1e-9));
  CHECK(pos.rows[1].value[0] == Approx(0.0).margin(1e-6));
  CHECK(pos.rows[2].value[0] == Approx(1.9999).margin(1e-4));
  // run 2 zeroed at its own first row (e_0 = 1.0 µm kept): read 100 + 0.005 mm → 100.000 mm → e_20 = 1.0 µm
  CHECK(pos.rows[3].value[0] == Approx(1.0).margin(1e-9));
  CHECK(pos.rows[4].value[0] == Approx(1.0).margin(1e-6));
  CHECK(pos.thermal_correction_max_um == Approx(10.0001).margin(1e-3));  // row 3: 12 − 1.9999
  MeasurementSet straight = parse_measurement_csv(head + "# component: Y\n" + rows, "s.csv", vmc());
  correct_to_20c(straight);
  CHECK_FALSE(straight.corrected_to_20c);
  CHECK(straight.rows[2].value[0] == 12.0);
}

TEST_CASE("sphere probing is not corrected (read through the machine's own scales)", "[conditions]") {
  MeasurementSet s = parse_measurement_csv(
      "# type: sphere\n# sphere: 120, 40, 80\n# temperature: 24\n"
      "# material_expansion: 11.5e-6\nt,X,Y,Z,A,C,dx,dy,dz\n0,120,40,80,0,0,0.001,0.002,0.003\n",
      "s.csv", ac());
  correct_to_20c(s);
  CHECK_FALSE(s.corrected_to_20c);
  CHECK(s.rows[0].value[2] == 0.003);
}

TEST_CASE("simulate's expansion and identify's correction are inverse", "[conditions]") {
  MeasurementSet s = parse_measurement_csv(ballbar(kConditions), "f.csv", ac());
  const double l2 = s.rows[1].value[0];
  expand_to_measuring_temperature(s);
  CHECK(s.rows[1].value[0] == Approx(l2 * (1.0 + 11.5e-6 * 3.5)).epsilon(0).margin(1e-12));
  correct_to_20c(s);
  CHECK(s.rows[1].value[0] == Approx(l2).epsilon(0).margin(1e-12));
}

TEST_CASE("comments, unknown keys and keys after the column line", "[conditions]") {
  const MeasurementSet s = parse_measurement_csv(
      ballbar("# measured after 30 min warm-up\n# checked by the shift lead: ok\n# humidity: 45 %\n") +
          "# temperature: 21\n",
      "f.csv", ac());
  // a comment: no 'word:' at its start (a phrase before the colon is not a key)
  REQUIRE(s.notices.size() == 2);
  CHECK(contains(s.notices[0], "f.csv:7: unknown key '# humidity:'"));
  CHECK(s.meta("humidity") == "45 %");  // kept
  CHECK(contains(s.notices[1], "f.csv:11: '# temperature:' after the column line"));
  CHECK_FALSE(s.conditions.temperature_c);
  const MeasurementSet sphere_with_bar = parse_measurement_csv(
      "# type: sphere\n# sphere: 1, 2, 3\n# bar_length: 100\nt,X,Y,Z,A,C,dx,dy,dz\n0,1,2,3,0,0,0,0,0\n", "s.csv", ac());
  REQUIRE(sphere_with_bar.notices.size() == 1);
  CHECK(contains(sphere_with_bar.notices[0], "s.csv:3: '# bar_length:' is not used in a sphere file"));
}

TEST_CASE("condition keys that cannot be honoured are refused at their line", "[conditions]") {
  CHECK(contains(error_of(ballbar("# temperature: 74\n")), "f.csv:5: temperature 74 °C is outside"));
  CHECK(contains(error_of(ballbar("# temperature: warm\n")), "f.csv:5: expected a number for temperature"));
  CHECK(contains(error_of(ballbar("# temperature: 22\n# material_expansion: 11.5\n")),
                 "f.csv:6: material_expansion 11.5 is not a linear expansion coefficient"));
  CHECK(contains(error_of(ballbar("# material_expansion: 11.5e-6\n")),
                 "f.csv:5: material_expansion without '# temperature:'"));
  CHECK(contains(error_of(ballbar("# date: 20.11.2026\n")), "f.csv:5: date '20.11.2026' is not ISO 8601"));
  CHECK(contains(error_of(ballbar("# date: 2026-02-29\n")), "is not ISO 8601"));  // 2026 is no leap year
  CHECK(error_of(ballbar("# date: 2028-02-29T23:59:60Z\n")) == "no error");
  CHECK(error_of(ballbar("# date: 2026-11-20T09:30+01:00\n")) == "no error");
  CHECK(contains(error_of(ballbar("# temperature: 22\n# temperature: 23\n")),
                 "f.csv:6: '# temperature:' given twice (first on line 5)"));
  CHECK(contains(error_of(ballbar("# Temperature: 22\n")), "f.csv:5: key 'Temperature': header keys are lower case"));
}

TEST_CASE("files of one identification more than 1 K apart are warned about", "[conditions]") {
  MeasurementSet a = parse_measurement_csv(ballbar("# temperature: 22.0\n"), "a.csv", ac());
  MeasurementSet b = parse_measurement_csv(ballbar("# temperature: 22.8\n"), "b.csv", ac());
  CHECK(temperature_warnings({a, b}).empty());  // 0.8 K
  MeasurementSet c = parse_measurement_csv(ballbar("# temperature: 23.5\n"), "c.csv", ac());
  const auto w = temperature_warnings({a, b, c});
  REQUIRE(w.size() == 1);
  CHECK(contains(w[0], "1.5 K apart (a.csv at 22 °C, c.csv at 23.5 °C)"));
  MeasurementSet none = parse_measurement_csv(ballbar(""), "n.csv", ac());
  const auto w2 = temperature_warnings({a, none});
  REQUIRE(w2.size() == 1);
  CHECK(contains(w2[0], "no '# temperature:' in n.csv"));
  CHECK(temperature_warnings({none, none}).empty());
}

TEST_CASE("read_measurement_files corrects each file to 20 °C", "[conditions]") {
  const std::string dir = test::make_temp_dir("ncpost_conditions");
  const std::string path = test::write_text_file(dir + "/b.csv", ballbar(kConditions));
  const auto sets = read_measurement_files({path}, ac());
  REQUIRE(sets.size() == 1);
  CHECK(sets[0].corrected_to_20c);
  CHECK(sets[0].rows[0].value[0] == Approx(100.0).epsilon(0).margin(1e-9));
}
