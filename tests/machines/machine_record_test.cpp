// SPDX-License-Identifier: Apache-2.0
// Issue 25 item 3: a machine file may name the physical machine by `serial` and `owner` ([machine]);
// both loaders accept them, they do not change the kinematics, and a non-string is refused at its line.
#include <catch2/catch.hpp>

#include "ac_trunnion_text.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/machines/machine_record.hpp"
#include "ncpost/machines/trr_xy_file.hpp"
#include "test_paths.hpp"
#include "text_file.hpp"

using namespace ncpost;

namespace {

std::string with_identity(const std::string& text, const std::string& lines) {
  std::string s = text;
  s.replace(s.find("[machine]\n"), 10, "[machine]\n" + lines);
  return s;
}

}  // namespace

TEST_CASE("serial and owner of a machine file are read and shown, not refused", "[identity]") {
  const std::string text =
      with_identity(testing::ac_trunnion_toml("ac"), "serial = \"AC-0815\"\nowner = \"Werkzeugbau Nord\"\n");
  const Machine with = parse_machine(text, "m.toml");
  const Machine without = parse_machine(testing::ac_trunnion_toml("ac"), "m.toml");
  CHECK(with.name == without.name);
  CHECK(with.axes.size() == without.axes.size());
  const MachineRecord id = parse_machine_record(text, "m.toml");
  CHECK(id.serial == "AC-0815");
  CHECK(id.owner == "Werkzeugbau Nord");
  const MachineRecord none = parse_machine_record(testing::ac_trunnion_toml("ac"), "m.toml");
  CHECK(none.serial.empty());
  CHECK(none.owner.empty());
  const std::string trr =
      with_identity(test::read_text_file(test::source("machines/trr-xy.toml")), "serial = \"T-1\"\n");
  CHECK_NOTHROW(parse_trr_xy_machine(trr, "t.toml"));
  CHECK(parse_machine_record(trr, "t.toml").serial == "T-1");
}

TEST_CASE("a serial that is not a string is refused at its line", "[identity]") {
  const std::string text = with_identity(testing::ac_trunnion_toml("ac"), "serial = 815\n");
  try {
    parse_machine_record(text, "m.toml");
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).rfind("m.toml:2:", 0) == 0);
    CHECK(std::string(e.what()).find("[machine] serial: expected a string") != std::string::npos);
  }
}

TEST_CASE("[tolerances] gives one acceptance tolerance per figure kind", "[identity]") {
  const std::string text = testing::ac_trunnion_toml("ac") + "[tolerances]\nG = 12\nA = 8.5\n";
  CHECK_NOTHROW(parse_machine(text, "m.toml"));
  const MachineRecord r = parse_machine_record(text, "m.toml");
  REQUIRE(r.tolerances_um.size() == 2);
  CHECK(r.tolerances_um.at("G") == 12.0);
  CHECK(r.tolerances_um.at("A") == 8.5);
  auto error_of = [](const std::string& t) {
    try {
      parse_machine_record(t, "m.toml");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK(error_of(testing::ac_trunnion_toml("ac") + "[tolerances]\nQ = 3\n").find("unknown key 'Q' in [tolerances]") !=
        std::string::npos);
  CHECK(error_of(testing::ac_trunnion_toml("ac") + "[tolerances]\nG = -3\n")
            .find("[tolerances] G: expected a number of µm") != std::string::npos);
  CHECK(error_of(testing::ac_trunnion_toml("ac") + "[tolerances]\nG = \"ten\"\n").find("[tolerances] G:") !=
        std::string::npos);
}
