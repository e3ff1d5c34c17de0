// SPDX-License-Identifier: Apache-2.0
// Measurement CSV and model JSON: strict readers (file:line errors), writers, round trips.
#include <catch2/catch.hpp>

#include "ncpost/compensation/measurement_csv.hpp"
#include "ncpost/compensation/model_json.hpp"
#include "ncpost/compensation/reversal.hpp"
#include "ncpost/machines/machine_file.hpp"

using namespace ncpost;
using namespace ncpost::comp;

namespace {
Machine ac() { return load_machine(std::string(NCPOST_SOURCE_DIR) + "/machines/ac-trunnion.toml"); }

const std::string kBallbar =
    "# type: ballbar\n# table_ball: 0.0000, -100.0000, 250.0000\n# tool_ball: 0, 0, 0\n# bar_length: 100.0\n"
    "# operator: someone\nt,X,Y,Z,A,C,L\n0.00,0.00000,0.00000,250.00000,0.00000,0.00000,100.000173\n"
    "0.50,0.00000,-1.57709,249.99503,0.36145,0.72289,100.000301\n";

std::string error_of(const std::string& text, bool plan = false) {
  try {
    parse_measurement_csv(text, "f.csv", ac(), {plan});
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}
}  // namespace

TEST_CASE("ballbar CSV is read, kept and written back") {
  const MeasurementSet s = parse_measurement_csv(kBallbar, "f.csv", ac());
  CHECK(s.type == MeasurementType::ballbar);
  REQUIRE(s.rows.size() == 2);
  CHECK(s.rows[1].command.rotary_rad[0] == Approx(deg_to_rad(0.36145)));
  CHECK(s.rows[1].value[0] == Approx(100.000301));
  CHECK(s.rows[1].line == 8);
  CHECK(s.meta("operator") == "someone");
  const std::string out = format_measurement_csv(s, ac());
  const MeasurementSet back = parse_measurement_csv(out, "g.csv", ac());
  CHECK(back.rows[1].value[0] == Approx(100.000301));
  CHECK(out.find("# operator: someone") != std::string::npos);
}

TEST_CASE("CSV errors name file and line") {
  CHECK(error_of("t,X\n") == "f.csv:1: missing '# type:' line before the header (ballbar, sphere or laser)");
  std::string missing = kBallbar;
  missing.replace(missing.find("# bar_length: 100.0\n"), 20, "");
  CHECK(error_of(missing).find("missing required key '# bar_length:'") != std::string::npos);
  std::string nan = kBallbar;
  nan.replace(nan.find("100.000301"), 10, "nan");
  CHECK(error_of(nan).rfind("f.csv:8:", 0) == 0);
  std::string fields = kBallbar + "1.0,0,0,250,0,0\n";
  CHECK(error_of(fields).rfind("f.csv:9: expected 7 fields", 0) == 0);
  std::string word = kBallbar + "1.0,0,abc,250,0,0,100\n";
  CHECK(error_of(word).find("expected a number for Y, found 'abc'") != std::string::npos);
  std::string no_axis = "# type: sphere\n# sphere: 1,2,3\nt,X,Y,Z,A,dx,dy,dz\n";
  CHECK(error_of(no_axis).find("missing column C") != std::string::npos);
  std::string no_values = "# type: sphere\n# sphere: 1,2,3\nt,X,Y,Z,A,C\n0,1,2,3,0,0\n";
  CHECK(error_of(no_values).find("missing value column") != std::string::npos);
  CHECK(error_of(no_values, true) == "no error");
}

TEST_CASE("model JSON: names checked against the machine, round trip") {
  const Machine m = ac();
  const std::string text =
      "{\n \"machine\": \"ac-trunnion\",\n \"parameters\": {\n  \"EY0C\": -0.02,\n  \"ECC:h2:cos\": 4e-5,\n"
      "  \"reversal:A\": 1e-5\n },\n \"effects_added\": [\"ECC:h2\"],\n \"note\": \"kept\"\n}\n";
  const ModelFile f = parse_model_json(text, "m.json", &m);
  CHECK(f.parameters.size() == 3);
  CHECK(*f.parameters.get("ECC:h2:cos") == 4e-5);
  const ModelFile back = parse_model_json(format_model_json(f), "n.json", &m);
  CHECK(back.parameters.names() == f.parameters.names());
  CHECK(back.extra.at("note") == "\"kept\"");  // the value's JSON text
  CHECK(back.effects_added == std::vector<std::string>{"ECC:h2"});

  std::string bad = text;
  bad.replace(bad.find("\"reversal:A\""), 12, "\"EZ0C\"");
  try {
    parse_model_json(bad, "m.json", &m);
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).rfind("m.json:6:", 0) == 0);
    CHECK(std::string(e.what()).find("along its own line") != std::string::npos);
  }
  std::string unknown = text;
  unknown.replace(unknown.find("\"reversal:A\""), 12, "\"EQ0C\"");
  CHECK_THROWS_AS(parse_model_json(unknown, "m.json", &m), InputError);
  std::string not_json = "{ \"parameters\": { \"EY0C\": } }";
  CHECK_THROWS_AS(parse_model_json(not_json, "m.json", &m), InputError);
}

TEST_CASE("reversal dead band") {
  // rising: 0; falling: +b; after a reversal the actual stands still inside the band
  const std::vector<double> c = {0, 1, 2, 1.99, 1.95, 1.5, 1.0, 1.2, 2.0};
  const auto off = dead_band_offsets<double>(c, 0.1);
  CHECK(off[2] == Approx(0.0));
  CHECK(off[3] == Approx(0.01));  // stands at 2
  CHECK(off[4] == Approx(0.05));
  CHECK(off[5] == Approx(0.1));  // band crossed: command + b
  CHECK(off[6] == Approx(0.1));
  CHECK(off[7] == Approx(-0.1 + 0.2 - 0.1 + 0.0).margin(1e-12));  // 1.1 actual stays until 1.2 > 1.1 → 0
  CHECK(off[8] == Approx(0.0));
}
