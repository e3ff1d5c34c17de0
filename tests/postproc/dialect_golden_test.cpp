// SPDX-License-Identifier: Apache-2.0
// Golden programs (issue 15 item 7): tests/data/golden/sample.apt (a tool change, a circle, a
// drilling cycle, simultaneous rotary moves in G93) posted on machines/ac-trunnion.toml in each of
// the five dialects, with and without --rtcp, must be byte for byte the reviewed program
// tests/data/golden/<dialect>.nc / <dialect>_rtcp.nc.
//
// The golden files change only on purpose. After a deliberate change of the output, regenerate them
// with
//   NCPOST_UPDATE_GOLDEN=1 ctest --test-dir build -R dialect_golden
// then read the diff (`git diff tests/data/golden`) line by line as a machinist would before
// committing it; the test fails while the variable is set, so an update is never silent.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <regex>
#include <string>

#include <sys/wait.h>

#include <filesystem>

#include "cli_run.hpp"
#include "temp_dir.hpp"
#include "test_paths.hpp"

using namespace ncpost;

namespace {

/// The program ncpost writes for the golden sample in `dialect` (with `extra` options), posted in
/// `dir` from copies of the sample and the machine file, so that its header names no folder.
std::string posted(const std::string& dir, const std::string& dialect, const std::string& extra) {
  test::write_text_file(dir + "/sample.apt", test::read_text_file(test::data("golden/sample.apt")));
  test::write_text_file(dir + "/ac-trunnion.toml", test::read_text_file(test::source("machines/ac-trunnion.toml")));
  const std::string nc = dialect + ".nc";
  const std::string cmd = "cd '" + dir + "' && " + NCPOST_BINARY +
                          " post --machine ac-trunnion.toml --workpiece-origin 0,0,80 --dialect " + dialect + extra +
                          " -o " + nc + " sample.apt > log.txt 2>&1";
  const int status = std::system(cmd.c_str());
  const int rc = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  INFO(test::read_text_file(dir + "/log.txt"));
  REQUIRE(rc == 0);
  return test::read_text_file(dir + "/" + nc);
}

/// `program` with the version in its first comment ("ncpost 0.1.0 from") made "ncpost VERSION from":
/// a new version alone does not change a golden program.
std::string versionless(const std::string& program) {
  static const std::regex version(R"(ncpost [0-9A-Za-z.+-]+ from )");
  return std::regex_replace(program, version, "ncpost VERSION from ", std::regex_constants::format_first_only);
}

}  // namespace

TEST_CASE("each dialect writes the reviewed golden program", "[post][dialect][golden]") {
  const bool update = std::getenv("NCPOST_UPDATE_GOLDEN") != nullptr;
  const std::string dir = test::make_temp_dir("dialect_golden");
  for (const char* d : {"fanuc", "haas", "linuxcnc", "sinumerik", "heidenhain"}) {
    for (const bool rtcp : {false, true}) {
      if (std::string(d) == "heidenhain" && !rtcp) continue;  // refused: no inverse-time feed (below)
      const std::string name = std::string(d) + (rtcp ? "_rtcp" : "");
      INFO(name);
      const std::string program = posted(dir, d, rtcp ? " --rtcp" : "");
      const std::string golden = test::data("golden/" + name + ".nc");
      if (update) test::write_text_file(golden, program);
      CHECK(versionless(program) == versionless(test::read_text_file(golden)));
    }
  }
  if (update) FAIL("NCPOST_UPDATE_GOLDEN is set: golden files rewritten; review `git diff tests/data/golden`");
}

TEST_CASE("Heidenhain without RTCP refuses a simultaneous move: Klartext has no inverse-time feed",
          "[post][dialect][golden]") {
  const std::string dir = test::make_temp_dir("dialect_golden_heidenhain");
  test::write_text_file(dir + "/sample.apt", test::read_text_file(test::data("golden/sample.apt")));
  test::write_text_file(dir + "/ac-trunnion.toml", test::read_text_file(test::source("machines/ac-trunnion.toml")));
  const std::string cmd = "cd '" + dir + "' && " + NCPOST_BINARY +
                          " post --machine ac-trunnion.toml --workpiece-origin 0,0,80 --dialect heidenhain"
                          " -o heidenhain.nc sample.apt > log.txt 2>&1";
  const int status = std::system(cmd.c_str());
  CHECK((WIFEXITED(status) ? WEXITSTATUS(status) : -1) == 3);
  const std::string log = test::read_text_file(dir + "/log.txt");
  CHECK(log.find("sample.apt:") != std::string::npos);
  CHECK(log.find("has no inverse-time feed (G93)") != std::string::npos);
  CHECK(log.find("--rtcp") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir + "/heidenhain.nc"));  // no program rather than a wrong feed
}
