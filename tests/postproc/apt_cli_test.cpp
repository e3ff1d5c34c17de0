// SPDX-License-Identifier: Apache-2.0
// The ncpost executable on the APT input rules: FINI required (--allow-unterminated), empty
// input, an over-long line (bounded output), NX MSYS (--msys apply|ignore and the hint).
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "cli_run.hpp"
#include "test_paths.hpp"

namespace fs = std::filesystem;
using ncpost::test::read_text_file;
using ncpost::test::run_ncpost;

namespace {

struct TempDir {
  fs::path path;
  TempDir() {
    std::string t = (fs::temp_directory_path() / "ncpost_apt_cli_XXXXXX").string();
    path = ::mkdtemp(t.data());
  }
  ~TempDir() { fs::remove_all(path); }
  std::string file(const std::string& name, const std::string& text) const {
    std::ofstream(path / name, std::ios::binary) << text;
    return (path / name).string();
  }
  std::string at(const std::string& name) const { return (path / name).string(); }
};

}  // namespace

TEST_CASE("ncpost post: a CL file must end with FINI; empty and over-long input are refused") {
  const TempDir d;
  const std::string post = "post --machine " + ncpost::test::source("machines/vmcl600.toml") +
                           " --workpiece-origin -100,-100,-100 -o " + d.at("out.nc") + " ";
  const std::string log = d.at("log.txt");
  const std::string cut = d.file("cut.apt", "UNITS/MM\nFEDRAT/500\nGOTO/0,0,10\nGOTO/10,0,10\n");
  CHECK(run_ncpost(post + cut, log) == 2);
  CHECK_THAT(read_text_file(log), Catch::Contains("cut.apt:4: file ends without FINI: truncated?"));
  CHECK_FALSE(fs::exists(d.at("out.nc")));
  CHECK(run_ncpost(post + "--allow-unterminated " + cut, log) == 0);
  CHECK_THAT(read_text_file(d.at("out.nc")),
             Catch::Contains("X-100.0000 Y-100.0000 Z-90.0000") && Catch::Contains("X-90.0000\n"));
  fs::remove(d.at("out.nc"));

  CHECK(run_ncpost(post + d.file("empty.apt", ""), log) == 2);
  CHECK_THAT(read_text_file(log), Catch::Contains("empty.apt: the input is empty"));
  CHECK_FALSE(fs::exists(d.at("out.nc")));

  const std::string longline = d.file("long.apt", "GOTO/1,2,3\nPPRINT/" + std::string(3u << 20, 'A') + "\nFINI\n");
  CHECK(run_ncpost(post + longline, log) == 2);
  const std::string err = read_text_file(log);
  CHECK_THAT(err, Catch::Contains("long.apt:2:1: line too long"));
  CHECK(err.size() < 800);
  CHECK_FALSE(fs::exists(d.at("out.nc")));

  // CR-only line ends and a byte order mark: read like LF, no BOM in the program
  CHECK(run_ncpost(post + d.file("cr.apt", "\xEF\xBB\xBFUNITS/MM\rFEDRAT/500\rGOTO/0,0,10\rGOTO/10,0,10\rFINI\r"),
                   log) == 0);
  const std::string nc = read_text_file(d.at("out.nc"));
  CHECK(nc.find("\xEF\xBB\xBF") == std::string::npos);
  CHECK_THAT(nc, Catch::Contains("X-100.0000 Y-100.0000 Z-90.0000") && Catch::Contains("X-90.0000\n"));
}

TEST_CASE("ncpost post: an NX MSYS that flips the MCS") {
  const TempDir d;
  const std::string post = "post --machine " + ncpost::test::source("machines/vmcl600.toml") +
                           " --workpiece-origin -100,-100,-100 -o " + d.at("out.nc") + " ";
  const std::string log = d.at("log.txt");
  const std::string cls = d.file("flip.cls",
                                 "TOOL PATH/OP1,TOOL,MILL\nMSYS/0,0,0,1,0,0,0,-1,0\nFEDRAT/MMPM,500\n"
                                 "GOTO/10,-20,-5,0,0,-1\nGOTO/30,-20,-5,0,0,-1\nEND-OF-PATH\n");
  CHECK(run_ncpost(post + cls, log) == 3);  // as written the tool points down: the message names MSYS
  CHECK_THAT(read_text_file(log),
             Catch::Contains("flip.cls:2: the file's MSYS rotates the MCS") && Catch::Contains("--msys apply"));
  CHECK(run_ncpost(post + "--msys apply " + cls, log) == 0);
  const std::string nc = read_text_file(d.at("out.nc"));
  // (10,-20,-5) in the flipped MCS is (10,20,5) absolute: machine X-90 Y-80 Z-95 with the origin at -100
  CHECK_THAT(nc, Catch::Contains("X-90.0000 Y-80.0000 Z-95.0000") && Catch::Contains("X-70.0000\n"));
}
