// SPDX-License-Identifier: Apache-2.0
// Issue 7: the table parameter kind (EXX:t:<pos>) and the laser CSV additions (`# axis:`,
// `# line:`, column `approach`): names, interpolation, model JSON and CSV round trips, bad input.
#include <catch2/catch.hpp>

#include "laser_test_support.hpp"
#include "ncpost/compensation/error_model.hpp"
#include "ncpost/compensation/measurement_csv.hpp"
#include "ncpost/compensation/model_json.hpp"
#include "ncpost/compensation/parameter_name.hpp"

using namespace ncpost;

TEST_CASE("laser: table parameter names", "[laser][format]") {
  const Machine m = test::vmcl600();
  const comp::ParseResult r = comp::parse_parameter_name("ECY:t:-12.5", m);
  REQUIRE(r.spec);
  CHECK(r.spec->kind == comp::ParameterKind::table);
  CHECK(r.spec->axis_index == 1);
  CHECK(r.spec->component == 5);
  CHECK(r.spec->at_mm == -12.5);
  CHECK(r.spec->is_angle());
  CHECK(comp::effect_of("ECY:t:-12.5") == "ECY:t");
  CHECK(comp::table_parameter_name('X', 'X', -275.0) == "EXX:t:-275");
  CHECK(comp::table_parameter_name('B', 'Z', 12.5) == "EBZ:t:12.5");
  CHECK(comp::table_parameter_name('Y', 'X', -1e-7) == "EYX:t:0");
  CHECK_FALSE(comp::parse_parameter_name("EXA:t:10", m).spec);  // no A axis
  CHECK_FALSE(comp::parse_parameter_name("EXX:t:abc", m).spec);
  CHECK_THROWS_AS(comp::ModelLayout(m, {"EXX:t:10", "EXX:t:10.0"}), std::invalid_argument);
}

TEST_CASE("laser: tables interpolate linearly and hold their end values", "[laser][format]") {
  const Machine m = test::vmcl600();
  const comp::ModelLayout layout(m, {"EXX:t:100", "EXX:t:-100", "EXX:t:0", "ECX:t:-100", "ECX:t:100"});
  const std::vector<double> v{2e-3, 1e-3, 0.0, 4e-5, -2e-5};
  const comp::ErrorFunctor<double> f(layout, v.data());
  CHECK(f(0, 50.0, false).motion_mm.x() == Approx(1e-3));
  CHECK(f(0, -50.0, false).motion_mm.x() == Approx(0.5e-3));
  CHECK(f(0, 250.0, false).motion_mm.x() == Approx(2e-3));
  CHECK(f(0, -150.0, false).motion_mm.x() == Approx(1e-3));
  CHECK(f(0, 0.0, false).motion_rad.z() == Approx(1e-5));
  CHECK(f(1, 50.0, false).motion_mm.x() == 0.0);  // other axis untouched
  // model JSON round trip keeps the names
  comp::ModelFile file;
  file.machine = m.name;
  for (std::size_t i = 0; i < v.size(); ++i) file.parameters.set(layout.names()[i], v[i]);
  const comp::ModelFile back = comp::parse_model_json(comp::format_model_json(file), "t.json", &m);
  CHECK(back.parameters.names() == file.parameters.names());
  CHECK(*back.parameters.get("ECX:t:100") == -2e-5);
}

TEST_CASE("laser: plan CSV round trip with axis, line and approach; bad rows refused", "[laser][format]") {
  const Machine m = test::vmcl600();
  comp::LaserPlanOptions o;
  o.runs = 2;
  const auto plans = comp::plan_laser(m, o);
  REQUIRE(plans.size() == 27);
  const comp::MeasurementSet& x2 = plans[3].set;  // X2_pos
  CHECK(plans[3].name == "X2_pos");
  const std::string text = comp::format_measurement_csv(x2, m);
  const comp::MeasurementSet back = comp::parse_measurement_csv(text, "X2_pos.csv", m, {true});
  REQUIRE(back.rows.size() == x2.rows.size());
  CHECK(back.meta("axis") == "X");
  CHECK(back.meta("line") == x2.meta("line"));
  for (std::size_t k = 0; k < back.rows.size(); ++k) {
    CHECK(back.rows[k].approach == x2.rows[k].approach);
    CHECK(back.rows[k].run == x2.rows[k].run);
    CHECK(back.rows[k].command[0] == Approx(x2.rows[k].command[0]));
  }
  // forward then backward, every target twice per run
  CHECK(x2.rows.front().approach == 1);
  CHECK(x2.rows.back().approach == -1);
  // a row off the declared line, a bad approach value (columns t,run,approach,X,Y,Z)
  CHECK(text.find("t,run,approach,X,Y,Z\n") != std::string::npos);
  const auto first_row = text.find('\n', text.find("t,run")) + 1;
  const std::string row = text.substr(first_row, text.find('\n', first_row) - first_row);
  auto with_field = [&](int index, const std::string& value) {
    std::vector<std::string> f;
    std::size_t at = 0;
    for (std::size_t comma; (comma = row.find(',', at)) != std::string::npos; at = comma + 1)
      f.push_back(row.substr(at, comma - at));
    f.push_back(row.substr(at));
    f[static_cast<std::size_t>(index)] = value;
    std::string joined;
    for (const auto& x : f) joined += (joined.empty() ? "" : ",") + x;
    return text.substr(0, first_row) + joined + text.substr(first_row + row.size());
  };
  CHECK_NOTHROW(comp::parse_measurement_csv(with_field(0, "0.00"), "same.csv", m, {true}));
  CHECK_THROWS_AS(comp::parse_measurement_csv(with_field(4, "9.00000"), "off.csv", m, {true}), InputError);
  CHECK_THROWS_AS(comp::parse_measurement_csv(with_field(2, "2"), "wrong.csv", m, {true}), InputError);
}
