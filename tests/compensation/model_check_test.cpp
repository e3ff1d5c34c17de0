// SPDX-License-Identifier: Apache-2.0
// A model JSON applied to a machine must be that machine's and plausible (issue 14 item 10):
// another machine's name (or none), other axes, a value no machine could have (EB0A = 1000 rad),
// a number beyond double range (1e400) are exit 2 with FILE:LINE:COL; --force applies the model
// with a warning per overridden check.
#include <catch2/catch.hpp>

#include "cli_run.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "ncpost/compensation/model_json.hpp"
#include "ncpost/compensation/model_plausibility.hpp"
#include "ncpost/machines/machine_file.hpp"

namespace fs = std::filesystem;
using namespace ncpost;
using namespace ncpost::comp;

namespace {

const std::string kClean = std::string(NCPOST_SOURCE_DIR) + "/tests/data/scenarios/public-clean/";

std::string model(const std::string& machine_line, const std::string& parameter_line) {
  return "{\n" + machine_line + " \"parameters\": {\n  \"EY0A\": 0.025,\n" + parameter_line +
         "  \"EX0C\": -0.012\n },\n" + " \"effects_added\": []\n}\n";
}

std::string error_of(const std::string& text, const Machine& m) {
  try {
    parse_model_json(text, "m.json", &m);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("model JSON: the machine's name and axes") {
  const Machine m = load_machine(kClean + "machine.toml");
  CHECK(error_of(model(" \"machine\": \"public-clean\",\n", ""), m) == "(no error)");
  CHECK(error_of(model(" \"machine\": \"public-clean\",\n \"axes\": \"XYZAC\",\n", ""), m) == "(no error)");
  CHECK(error_of(model(" \"machine\": \"other\",\n", ""), m) ==
        "m.json:2:3: the model is of machine 'other', not 'public-clean': its errors are another machine's; identify "
        "this machine or give its model (--force applies it anyway)");
  CHECK(error_of(model("", ""), m) ==
        "m.json:1:1: the model names no machine (key \"machine\"); it may be of another machine than 'public-clean': "
        "identify it on this machine, or add \"machine\": \"public-clean\" if it is (--force applies it anyway)");
  CHECK(error_of(model(" \"machine\": \"public-clean\",\n \"axes\": \"XYZBC\",\n", ""), m) ==
        "m.json:3:3: the model is of axes XYZBC, the machine 'public-clean' has XYZAC: give this machine's model "
        "(--force applies it anyway)");
  // identify writes both keys
  ModelFile f;
  f.machine = m.name;
  f.axes = model_axes(m);
  CHECK(format_model_json(f).find("\"axes\": \"XYZAC\"") != std::string::npos);
}

TEST_CASE("model JSON: every value plausible for its kind, 1e400 a clear error") {
  const Machine m = load_machine(kClean + "machine.toml");
  const std::string name = " \"machine\": \"public-clean\",\n";
  CHECK(error_of(model(name, "  \"EB0A\": 1000,\n"), m) ==
        "m.json:5:4: 'EB0A' = 1000 acts by 1000 rad, more than any machine's error of this kind (at most 0.01 rad): "
        "a wrong unit (mm/rad, not µm/µrad or degrees) or a wrong file; correct the value (--force applies it anyway)");
  CHECK(error_of(model(name, "  \"EB0A\": 0.009,\n"), m) == "(no error)");
  CHECK(error_of(model(name, "  \"EZ0A\": 25,\n"), m).find("'EZ0A' = 25 acts by 25 mm") != std::string::npos);
  CHECK(error_of(model(name, "  \"EZ0A\": -1.5,\n"), m).find("(at most 1 mm)") != std::string::npos);
  // a polynomial term by its effect at 1000 mm of travel: 2e-3·1000 = 2 mm; 5e-4 gives 0.5 mm
  CHECK(error_of(model(name, "  \"EXX:p1\": 2e-3,\n"), m).find("acts by 2 mm at 1000 mm of travel") !=
        std::string::npos);
  CHECK(error_of(model(name, "  \"EXX:p1\": 5e-4,\n"), m) == "(no error)");
  CHECK(
      error_of(model(name, "  \"drift:Z:t:tau\": 0,\n"), m).find("outside the plausible time constants 1 .. 86400 s") !=
      std::string::npos);
  CHECK(error_of(model(name, "  \"drift:Z:t:lin\": 1e-3,\n"), m).find("acts by 28.8 mm after 28800 s") !=
        std::string::npos);
  CHECK(
      error_of(model(name, "  \"EB0A\": 1e400,\n"), m).rfind("m.json:5:11: a number beyond the range of a double", 0) ==
      0);
  CHECK(error_of("{\"machine\": \"public-clean\", \"parameters\": {}, \"fit\": {\"rms_after_um\": \"x\"}}", m)
            .find("'fit' has a value of the wrong type") != std::string::npos);

  // --force: read, applied, each overridden check kept as a warning
  ModelReadOptions force;
  force.force = true;
  const ModelFile f = parse_model_json(model(" \"machine\": \"other\",\n", "  \"EB0A\": 1000,\n"), "m.json", &m, force);
  CHECK(*f.parameters.get("EB0A") == 1000.0);
  REQUIRE(f.warnings.size() == 2);
  CHECK(f.warnings[0].rfind("m.json:2:3: the model is of machine 'other'", 0) == 0);
  CHECK(f.warnings[1].rfind("m.json:5:4: 'EB0A' = 1000 acts by 1000 rad", 0) == 0);
  // without a machine (reading for display) nothing is checked
  CHECK_NOTHROW(parse_model_json(model("", "  \"EB0A\": 1000,\n"), "m.json", nullptr));
}

TEST_CASE("post --model: another machine's or an implausible model is exit 2; --force applies it") {
  const fs::path dir = fs::temp_directory_path() / ("ncpost_model_check_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string d = dir.string() + "/";
  const std::string post = "post --machine " + kClean + "machine.toml --workpiece-origin 0,0,80 ";
  std::ofstream(d + "other.json") << model(" \"machine\": \"other\",\n", "");
  std::ofstream(d + "eb0a.json") << model(" \"machine\": \"public-clean\",\n", "  \"EB0A\": 1000,\n");
  CHECK(test::run_ncpost(post + "--model " + d + "other.json -o " + d + "o.nc " + kClean + "path.cls", d + "log") == 2);
  CHECK(test::read_text_file(d + "log").find(d + "other.json:2:3: the model is of machine 'other'") !=
        std::string::npos);
  CHECK_FALSE(fs::exists(d + "o.nc"));
  CHECK(test::run_ncpost(post + "--model " + d + "eb0a.json -o " + d + "o.nc " + kClean + "path.cls", d + "log") == 2);
  CHECK(test::read_text_file(d + "log").find(d + "eb0a.json:5:4: 'EB0A' = 1000") != std::string::npos);
  CHECK(test::run_ncpost("simulate --machine " + kClean + "machine.toml --model " + d + "other.json -o " + d +
                             "s.csv " + kClean + "sphere.csv",
                         d + "log") == 2);
  CHECK(test::run_ncpost(post + "--force --model " + d + "other.json -o " + d + "o.nc " + kClean + "path.cls",
                         d + "log") == 0);
  CHECK(test::read_text_file(d + "log").find("ncpost: warning: " + d +
                                             "other.json:2:3: the model is of machine 'other'") != std::string::npos);
  CHECK(fs::exists(d + "o.nc"));
  fs::remove_all(dir);
}
