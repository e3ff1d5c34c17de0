// SPDX-License-Identifier: Apache-2.0
// The version is defined once, by project(ncpost VERSION ...) in CMakeLists.txt: ncpost::version(),
// `ncpost --version`, the NC program header and the tests' own working folder follow it.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "cli_run.hpp"
#include "ncpost/version.hpp"
#include "test_paths.hpp"

TEST_CASE("version: ncpost::version() is the CMake project version") {
  const std::string cmake = ncpost::test::read_text_file(ncpost::test::source("CMakeLists.txt"));
  std::smatch m;
  REQUIRE(std::regex_search(cmake, m, std::regex(R"(project\(ncpost VERSION ([0-9]+)\.([0-9]+)\.([0-9]+))")));
  CHECK(ncpost::version() == m[1].str() + "." + m[2].str() + "." + m[3].str());
  CHECK(ncpost::version_major == std::stoi(m[1].str()));
  CHECK(ncpost::version_minor == std::stoi(m[2].str()));
  CHECK(ncpost::version_patch == std::stoi(m[3].str()));
}

TEST_CASE("version: --version and the NC program header print it") {
  REQUIRE(ncpost::test::run_ncpost("--version", "version.log") == 0);
  CHECK(ncpost::test::read_text_file("version.log") == "ncpost " + ncpost::version() + "\n");
  REQUIRE(ncpost::test::run_ncpost("post --machine " + ncpost::test::source("machines/ac-trunnion.toml") +
                                       " --workpiece-origin 0,0,80 -o version.nc " +
                                       ncpost::test::source("samples/hemisphere_5axis.cls"),
                                   "post.log") == 0);
  const std::string nc = ncpost::test::read_text_file("version.nc");
  CHECK(nc.find("(ncpost " + ncpost::version() + " from ") != std::string::npos);
}

TEST_CASE("version: each test runs in its own working folder") {
  // files written by a relative name cannot collide with another test's under ctest -j
  CHECK(std::filesystem::current_path() == std::filesystem::path(NCPOST_TEST_TMP_ROOT) / "postproc_version_test");
}
