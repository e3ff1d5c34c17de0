// SPDX-License-Identifier: Apache-2.0
// The TRR-XY machine file (docs/trr-xy.md "Machine file"): the shipped file loads with the seed's
// numbers; bad files fail with file, line and what was expected; the serial loader refuses it.
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

#include "ncpost/machines/machine_file.hpp"
#include "ncpost/machines/trr_xy_file.hpp"
#include "test_paths.hpp"
#include "text_edit.hpp"

using namespace ncpost;

using ncpost::test::replaced;

namespace {

std::string shipped_text() {
  std::ifstream in(test::source("machines/trr-xy.toml"));
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string error_of(const std::string& text) {
  try {
    parse_trr_xy_machine(text, "m.toml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("machines/trr-xy.toml loads with the seed's numbers") {
  const std::string path = test::source("machines/trr-xy.toml");
  CHECK(machine_file_kind(path) == "trr-xy");
  CHECK(machine_file_kind(test::source("machines/ac-trunnion.toml")) == "serial");
  const trr::Machine m = load_trr_xy_machine(path);
  CHECK(m.name == "trr-xy");
  CHECK(m.geometry.base_radius_mm == 495.0);
  CHECK(m.geometry.platform_radius_mm == 200.0);
  CHECK(m.geometry.link_length_mm == 1020.0);
  CHECK(m.geometry.ball_joint_height_mm == 142.0);
  CHECK(m.geometry.tool_offset_mm == 270.0);
  REQUIRE(m.table_limits[0]);
  CHECK(m.table_limits[0]->min == -400.0);
  CHECK(m.table_limits[1]->max == 400.0);
  for (const auto& l : m.slider_limits) {
    REQUIRE(l);
    CHECK(l->min == 0.0);
    CHECK(l->max == 600.0);
  }
}

TEST_CASE("the serial loader names the TRR-XY kind instead of a chain error") {
  try {
    load_machine(test::source("machines/trr-xy.toml"));
    FAIL("expected an InputError");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("trr-xy.toml:8:") != std::string::npos);
    CHECK(std::string(e.what()).find("TRR-XY parallel machine") != std::string::npos);
  }
}

TEST_CASE("bad TRR-XY files: file, line and what was expected") {
  const std::string good = shipped_text();
  CHECK(error_of(good).empty());
  CHECK(error_of(replaced(good, "link_length = 1020.0", "link_length = -1")).find("m.toml:13:") != std::string::npos);
  CHECK(error_of(replaced(good, "link_length = 1020.0", "link_length = -1")).find("expected a positive number") !=
        std::string::npos);
  CHECK(error_of(replaced(good, "link_length = 1020.0\n", "")).find("missing key 'link_length'") != std::string::npos);
  CHECK(error_of(replaced(good, "tool_offset = 270.0", "tool_offset = 270.0\nspindle = 1"))
            .find("unknown key 'spindle' in [trr_xy]") != std::string::npos);
  CHECK(error_of(replaced(good, "[axes.W]", "[axes.Z]")).find("axis 'Z'") != std::string::npos);
  CHECK(
      error_of(replaced(good, "[axes.W]\ntype = \"linear\"\nlimits = [0, 600]\n", "")).find("missing axis [axes.W]") !=
      std::string::npos);
  CHECK(error_of(replaced(good, "limits = [0, 600]", "limits = [600, 0]")).find("min < max") != std::string::npos);
  CHECK(error_of(replaced(good, "kind = \"trr-xy\"", "kind = \"serial\"\nchain = \"w b X t\""))
            .find("unknown key 'chain'") != std::string::npos);
  CHECK(error_of(replaced(good, "platform_radius = 200.0", "platform_radius = 600.0")).find("base_radius") !=
        std::string::npos);
  CHECK(error_of("[machine\nname=1").find("m.toml:1:") != std::string::npos);
}
