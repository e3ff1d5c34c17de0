// SPDX-License-Identifier: Apache-2.0
// One loader for a machine file of any kind (ncpost/machines/load.hpp): the file's [machine] kind
// picks the registry's row, the kinematics are those its kind's own parser reads, and a file of a
// kind the registry has not goes to the default (serial) parser, which refuses it at the line.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "ncpost/machines/load.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/machines/trr_xy_file.hpp"
#include "temp_dir.hpp"
#include "test_paths.hpp"

using namespace ncpost;

namespace {

/// The kind a machine file's text names (a line `kind = "..."`), read here without TOML: "serial"
/// when it names none.
std::string kind_in_text(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    const auto at = line.find("kind = \"");
    if (line.rfind("kind", 0) == 0 && at != std::string::npos) {
      const auto begin = at + 8;
      return line.substr(begin, line.find('"', begin) - begin);
    }
  }
  return "serial";
}

}  // namespace

TEST_CASE("machines::load: the registry's kinds, the default first", "[load]") {
  CHECK(machines::kinds() == std::vector<std::string>{"serial", "trr-xy"});
}

TEST_CASE("machines::load: every shipped machine file loads as its kind, as its kind's parser reads it", "[load]") {
  int serial = 0, trr_xy = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::source("machines"))) {
    if (entry.path().extension() != ".toml") continue;
    const std::string path = entry.path().string();
    INFO(path);
    const machines::LoadedMachine m = machines::load(path);
    CHECK(m.kind == kind_in_text(path));
    CHECK(machines::kind_of(path) == m.kind);
    if (m.kind == "serial") {
      const Machine& k = std::get<Machine>(m.kinematics);
      const Machine own = load_machine(path);
      CHECK(k.name == own.name);
      CHECK(k.chain == own.chain);
      REQUIRE(k.axes.size() == own.axes.size());
      for (std::size_t i = 0; i < k.axes.size(); ++i) CHECK(k.axes[i].letter == own.axes[i].letter);
      ++serial;
    } else {
      const trr::Machine& k = std::get<trr::Machine>(m.kinematics);
      const trr::Machine own = load_trr_xy_machine(path);
      CHECK(k.name == own.name);
      CHECK(k.geometry.base_radius_mm == own.geometry.base_radius_mm);
      CHECK(machines::load_as<trr::Machine>(path).name == own.name);
      ++trr_xy;
    }
  }
  CHECK(serial >= 10);
  CHECK(trr_xy == 1);
}

TEST_CASE("machines::load: a kind the registry has not is refused at its line by the default parser", "[load]") {
  const std::string dir = test::make_temp_dir("ncpost_load");
  const std::string path = test::write_text_file(dir + "/m.toml", "[machine]\nname = \"m\"\nkind = \"five-bar\"\n");
  CHECK(machines::kind_of(path) == "serial");
  try {
    (void)machines::load(path);
    FAIL("loaded a machine of an unknown kind");
  } catch (const InputError& e) {
    CHECK(e.where().file == path);
    CHECK(e.where().line == 3);
    CHECK(std::string(e.what()).find("five-bar") != std::string::npos);
  }
  std::filesystem::remove_all(dir);
}
