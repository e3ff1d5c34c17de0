// SPDX-License-Identifier: Apache-2.0
// Machine files: every shipped machine loads; bad files fail with file, line and what was expected.
#include <catch2/catch.hpp>

#include "ncpost/machines/machine_file.hpp"
#include "test_paths.hpp"
#include "text_edit.hpp"
#include "ac_trunnion_text.hpp"

using namespace ncpost;

using ncpost::test::replaced;

namespace {

std::string error_of(const std::string& text) {
  try {
    parse_machine(text, "m.toml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const std::string kGood = ncpost::testing::ac_trunnion_toml("t");

}  // namespace

TEST_CASE("every shipped machine and the scenario machines load") {
  for (const char* name : test::kShippedMachines) {
    INFO(name);
    const Machine m = load_machine(test::source(std::string("machines/") + name + ".toml"));
    CHECK(m.name == name);
  }
  const Machine ac = load_machine(test::data("scenarios/public-clean/machine.toml"));
  REQUIRE(ac.rotary_count() == 2);
  CHECK(ac.rotary(0).letter == 'A');
  CHECK(ac.rotary(1).letter == 'C');
  CHECK(ac.rotary(0).limits->max == Approx(deg_to_rad(120)));
  CHECK(ac.rotary(1).continuous());
  // chain "w C' A' Y' b X Z t": from the bed outward Y, A, C on the table; X, Z on the tool
  CHECK(ac.workpiece_side == std::vector<int>{1, 3, 4});
  CHECK(ac.tool_side == std::vector<int>{0, 2});
}

TEST_CASE("a head machine puts its rotary axes on the tool side") {
  const Machine m = load_machine(test::source("machines/gantry-bc-head.toml"));
  CHECK(m.rotary(0).side == Side::tool);
  CHECK(m.rotary(0).letter == 'B');
  CHECK(m.tool_side == std::vector<int>{0, 2, 4, 3});  // X Z C B
}

TEST_CASE("bad machine files name the line and what was expected") {
  CHECK(error_of(kGood).empty());
  CHECK_THAT(error_of(replaced(kGood, "direction = [1, 0, 0]", "direction = [1, 1, 0]")),
             Catch::Contains("m.toml:12") && Catch::Contains("unit vector"));
  CHECK_THAT(error_of(replaced(kGood, "[axes.C]\ntype = \"rotary\"\ndirection = [0, 0, 1]\npivot = [0, 0, 0]\n", "")),
             Catch::Contains("'C' has no [axes.C]"));
  CHECK_THAT(error_of(replaced(kGood, "limits = [-120, 120]", "limits = [120, -120]")),
             Catch::Contains("m.toml:14") && Catch::Contains("min < max"));
  CHECK_THAT(error_of(replaced(kGood, "limits = [-120, 120]", "limit = [-120, 120]")),
             Catch::Contains("m.toml:14") && Catch::Contains("unknown key 'limit'"));
  CHECK_THAT(error_of(replaced(kGood, "chain = \"w C' A' Y' b X Z t\"", "chain = \"w C' A Y' b X Z t\"")),
             Catch::Contains("m.toml:3") && Catch::Contains("must be primed"));
  CHECK_THAT(
      error_of(replaced(kGood, "type = \"rotary\"\ndirection = [0, 0, 1]", "type = \"rotory\"\ndirection = [0, 0, 1]")),
      Catch::Contains("\"linear\" or \"rotary\""));
  CHECK_THAT(error_of(replaced(kGood, "direction = [0, 0, 1]", "direction = [1, 0, 0]")), Catch::Contains("parallel"));
  CHECK_THAT(error_of("[machine\nname=1"), Catch::Contains("m.toml:1"));
  CHECK_THAT(error_of(replaced(kGood, "chain = \"w C' A' Y' b X Z t\"", "chain = \"w Y' C' A' b X Z t\"")),
             Catch::Contains("carried by a rotary axis"));
}
