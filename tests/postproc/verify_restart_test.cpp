// SPDX-License-Identifier: Apache-2.0
// Issue 13 item 8: `--verify` re-executes each block from where the previous block really ended.
// A rapid that keeps Z is written whole by the first of its two rapid blocks (the second changes no
// word); the feed that follows starts there, not at the position before the rapid (which gave a
// 10 mm false alarm on a correct program). Helices (CIRCLE with a Z change, G2/G3 with Z) run from
// where the rapid put the tool too.
#include <catch2/catch.hpp>

#include <regex>
#include <string>

#include "cli_run.hpp"
#include "temp_dir.hpp"
#include "test_paths.hpp"

namespace {

struct Verified {
  int rc = -1;
  double after_mm = -1.0, ends_mm = -1.0;
  std::string messages;
};

Verified verify(const std::string& name, const std::string& text, const std::string& machine,
                const std::string& origin) {
  static const std::string dir = ncpost::test::make_temp_dir("ncpost_verify_restart");
  const std::string input = ncpost::test::write_text_file(dir + "/" + name, text);
  Verified v;
  v.rc = ncpost::test::run_ncpost("post --machine " + ncpost::test::source("machines/" + machine + ".toml") +
                                      " --workpiece-origin " + origin + " --verify -o " + dir + "/out.nc " + input,
                                  dir + "/log");
  v.messages = ncpost::test::read_text_file(dir + "/log");
  static const std::regex after(R"(after .*largest contour error ([0-9.]+) mm.*block ends ([0-9.]+) mm)");
  std::smatch m;
  if (std::regex_search(v.messages, m, after)) {
    v.after_mm = std::stod(m[1].str());
    v.ends_mm = std::stod(m[2].str());
  }
  return v;
}

}  // namespace

TEST_CASE("--verify after a split rapid that keeps Z: no false alarm", "[post][verify]") {
  const Verified v = verify(
      "rapid.apt", "UNITS/MM\nFEDRAT/500\nRAPID\nGOTO/0,0,10\nRAPID\nGOTO/10,0,10\nGOTO/10,0,0\nGOTO/20,0,0\nFINI\n",
      "ac-trunnion", "0,0,80");
  INFO(v.messages);
  REQUIRE(v.rc == 0);
  CHECK(v.after_mm == Approx(0.0).margin(1e-4));  // was 10 mm
  CHECK(v.ends_mm == Approx(0.0).margin(1e-4));
}

TEST_CASE("--verify on helices after rapids: CIRCLE with a Z change and G2/G3 with Z", "[post][verify]") {
  const Verified apt =
      verify("helix.apt",
             "UNITS/MM\nFEDRAT/500\nRAPID\nGOTO/0,0,20\nRAPID\nGOTO/10,0,20\nGOTO/10,0,5\n"
             "CIRCLE/0,0,5,0,0,1,10\nGOTO/-10,0,3\nCIRCLE/0,0,3,0,0,1,10\nGOTO/10,0,1\nGOTO/20,0,1\nFINI\n",
             "vmcl600", "0,0,-100");
  INFO(apt.messages);
  REQUIRE(apt.rc == 0);
  CHECK(apt.after_mm <= 0.0002);  // 1 µm chords, 4-decimal words
  const Verified nc = verify("helix.nc",
                             "G21 G90 G17\nG0 X0 Y0 Z20\nG0 X10 Y0 Z20\nG1 Z5 F300\nG2 X10 Y0 Z2 I-10 J0\n"
                             "G3 X-10 Y0 Z1 I-10 J0\nG1 X0 Y0\nG0 Z10\nM30\n",
                             "vmcl600", "0,0,-100");
  INFO(nc.messages);
  REQUIRE(nc.rc == 0);
  CHECK(nc.after_mm <= 0.0002);
}
