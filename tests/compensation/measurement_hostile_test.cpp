// SPDX-License-Identifier: Apache-2.0
// Hostile measurement files (issue 14 item 5): a header without rows, time going backwards, a
// reading far beyond any instrument's range, the same file given twice or a copy of it. Each is
// exit 2 naming the file (and line:column), never a crash or a fit that reports success.
#include <catch2/catch.hpp>

#include "cli_run.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "ncpost/compensation/measurement_csv.hpp"
#include "ncpost/compensation/measurement_files.hpp"
#include "ncpost/machines/machine_file.hpp"

namespace fs = std::filesystem;
using namespace ncpost;

namespace {

const std::string kClean = std::string(NCPOST_SOURCE_DIR) + "/tests/data/scenarios/public-clean/";

struct TempDir {
  fs::path path = fs::temp_directory_path() / ("ncpost_meas_hostile_" + std::to_string(::getpid()));
  TempDir() { fs::create_directories(path); }
  ~TempDir() { fs::remove_all(path); }
  std::string file(const std::string& name) const { return (path / name).string(); }
};

void write(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

/// The public sphere file with line `line_no` (1-based) replaced by `with` ("" keeps it).
std::string sphere_with(int line_no, const std::string& with) {
  std::istringstream in(test::read_text_file(kClean + "sphere.csv"));
  std::string out, line;
  for (int n = 1; std::getline(in, line); ++n) out += (n == line_no ? with : line) + "\n";
  return out;
}

std::string message_of(const std::string& text, const std::string& name, const Machine& m) {
  try {
    comp::parse_measurement_csv(text, name, m);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("measurement CSV: no rows, time backwards, a reading out of range") {
  const Machine m = load_machine(kClean + "machine.toml");
  const std::string header = "# type: sphere\n# sphere: 120, 40, 80\nt,X,Y,Z,A,C,dx,dy,dz\n";
  CHECK(message_of(header, "empty.csv", m) ==
        "empty.csv:3: no rows after the header: the file holds no measurements (was the export cut short?)");
  CHECK(message_of(header + "\n# a comment\n", "empty.csv", m).rfind("empty.csv:3: no rows after the header", 0) == 0);
  // plans too: a plan without rows plans nothing
  CHECK_THROWS_AS(comp::parse_measurement_csv("# type: sphere\n# sphere: 1,2,3\nt,X,Y,Z,A,C\n", "p.csv", m, {true}),
                  InputError);
  // line 5 is the second row (t = 625): 600 goes backwards; equal times are refused too
  CHECK(message_of(sphere_with(5, "600.00,83.92305,94.64102,80.00000,0.00000,30.00000,-0.008949,-0.009072,0.001797"),
                   "s.csv", m) ==
        "s.csv:5:1: time t = 600.00 s is not after the previous row's t = 619 s (line 4): rows must be in recording "
        "order with increasing time stamps; sort the rows or correct the time column");
  CHECK(message_of(sphere_with(5, "619.00,83.92305,94.64102,80.00000,0.00000,30.00000,-0.008949,-0.009072,0.001797"),
                   "s.csv", m)
            .rfind("s.csv:5:1: time t = 619.00 s is not after", 0) == 0);
  CHECK(message_of(sphere_with(6, "631.00,25.35898,123.92305,80.00000,0.00000,60.00000,1e9,-0.023295,-0.001102"),
                   "s.csv", m) ==
        "s.csv:6:53: dx = 1e9 is 1e+09 mm from zero, beyond what the instrument can read (at most 5 mm): a typing or "
        "export error; correct or delete the row");
  // the ballbar's reading is the bar length: 102.5 on a 100 mm bar is 2.5 mm off (range ±2 mm)
  const std::string bb =
      "# type: ballbar\n# table_ball: 0, -100, 250\n# tool_ball: 0, 0, 0\n# bar_length: 100\n"
      "t,X,Y,Z,A,C,L\n0,0,0,250,0,0,100.0001\n0.5,0,-1.57709,249.99503,0.36145,0.72289,";
  CHECK_NOTHROW(comp::parse_measurement_csv(bb + "101.9\n", "b.csv", m));
  CHECK(message_of(bb + "102.5\n", "b.csv", m) ==
        "b.csv:7:42: L = 102.5 is 2.5 mm from the bar length, beyond what the instrument can read (at most 2 mm): a "
        "typing or export error; correct or delete the row");
}

TEST_CASE("identify refuses an empty file, the same file twice and a copy, with exit 2") {
  const TempDir dir;
  const std::string machine = "--machine " + kClean + "machine.toml -o " + dir.file("m.json") + " ";
  const std::string log = dir.file("log");
  write(dir.file("empty.csv"), "# type: sphere\n# sphere: 120, 40, 80\nt,X,Y,Z,A,C,dx,dy,dz\n");
  CHECK(test::run_ncpost("identify " + machine + dir.file("empty.csv"), log) == 2);
  CHECK(test::read_text_file(log).find(dir.file("empty.csv") + ":3: no rows after the header") != std::string::npos);

  const std::string sphere = kClean + "sphere.csv";
  const std::string same = kClean + "../public-clean/sphere.csv";  // another name, the same inode
  CHECK(test::run_ncpost("identify " + machine + sphere + " " + same, log) == 2);
  CHECK(test::read_text_file(log).find(same + ": the same file as '" + sphere + "', given twice") != std::string::npos);

  fs::copy_file(sphere, dir.file("copy.csv"));
  CHECK(test::run_ncpost("identify " + machine + sphere + " " + dir.file("copy.csv"), log) == 2);
  CHECK(test::read_text_file(log).find(dir.file("copy.csv") + ":4: holds the same rows as '" + sphere + "'") !=
        std::string::npos);

  write(dir.file("outlier.csv"),
        sphere_with(6, "631.00,25.35898,123.92305,80.00000,0.00000,60.00000,1e9,-0.023295,-0.001102"));
  CHECK(test::run_ncpost("identify --loss huber " + machine + dir.file("outlier.csv"), log) == 2);
  CHECK(test::read_text_file(log).find(dir.file("outlier.csv") + ":6:53: dx = 1e9") != std::string::npos);
  CHECK_FALSE(fs::exists(dir.file("m.json")));

  // the same file twice is refused by the library as well (device and inode, not the name)
  const Machine m = load_machine(kClean + "machine.toml");
  CHECK_THROWS_AS(comp::read_measurement_files({sphere, same}, m), InputError);
  CHECK(comp::read_measurement_files({sphere, kClean + "ballbar_h250.csv"}, m).size() == 2);
}
