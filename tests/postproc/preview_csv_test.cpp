// SPDX-License-Identifier: Apache-2.0
// ncpost preview --csv on the public dome path: one row per feed block with the columns of
// docs/cli.md, values equal to the library's exact nonlinear error of the same block.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "ncpost/compensation/nonlinear_error.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/read/apt/apt_reader.hpp"
#include "ncpost/postproc/verify/preview_blocks.hpp"
#include "test_paths.hpp"

using namespace ncpost;

namespace {

std::vector<std::vector<std::string>> read_csv(const std::string& path, std::string& header) {
  std::ifstream in(path);
  std::getline(in, header);
  std::vector<std::vector<std::string>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

}  // namespace

TEST_CASE("ncpost preview --csv on the dome path", "[preview]") {
  const std::string scenario = test::data("scenarios/public-clean/");
  const std::string cmd = std::string(NCPOST_BINARY) + " preview --machine " + scenario +
                          "machine.toml --workpiece-origin 0,0,80 --csv preview_csv_test.csv " + scenario +
                          "path.cls > preview_csv_test.out 2>&1";
  REQUIRE(WEXITSTATUS(std::system(cmd.c_str())) == 0);
  std::string header;
  const auto rows = read_csv("preview_csv_test.csv", header);
  CHECK(header.rfind("block,line,max_error_mm,at_t,harmonic_mm", 0) == 0);
  REQUIRE(rows.size() == 1200);  // 1201 motions, the first one positions the tool
  double largest = 0;
  int worst_line = 0;
  for (const auto& r : rows) {
    REQUIRE(r.size() == 8);
    const double e = std::stod(r[2]);
    if (e > largest) largest = e, worst_line = std::stoi(r[1]);
    CHECK(std::stod(r[3]) >= 0.0);
    CHECK(std::stod(r[3]) <= 1.0);
  }
  CHECK(largest == Approx(1.0367).margin(1e-3));
  CHECK(worst_line == 1089);

  // the same blocks through the library
  const Machine m = load_machine(scenario + "machine.toml");
  const Setup setup{Vec3d(0, 0, 80), 0.0};
  std::ifstream in(scenario + "path.cls");
  cl::AptReader reader(in, "path.cls");
  NominalSolver solver(m, setup);
  const preview::ModelEvaluator<NominalErrors> evaluator(m, setup);
  std::size_t i = 0;
  preview::run_preview(reader, "path.cls", solver, evaluator, [&](const preview::BlockRow& row) {
    REQUIRE(i < rows.size());
    CHECK(std::stoi(rows[i][0]) == static_cast<int>(row.block));
    CHECK(std::stoi(rows[i][1]) == row.line);
    CHECK(std::stod(rows[i][2]) == Approx(row.exact.max_error_mm).margin(1e-6));
    CHECK(std::stod(rows[i][4]) == Approx(row.harmonic_mm).margin(1e-6));
    ++i;
  });
  CHECK(i == rows.size());
}

TEST_CASE("ncpost preview: exit codes", "[preview]") {
  const std::string scenario = test::data("scenarios/public-clean/");
  auto run = [](const std::string& args) {
    return WEXITSTATUS(
        std::system((std::string(NCPOST_BINARY) + " preview " + args + " > preview_rc.out 2>&1").c_str()));
  };
  CHECK(run("--bogus") == 1);
  CHECK(run("--machine " + scenario + "machine.toml") == 1);  // no INPUT
  std::ofstream("preview_bad.cls") << "GOTO/1,2,3\nGOTO/1,2.5.3,4\n";
  CHECK(run("--machine " + scenario + "machine.toml --csv preview_bad.csv preview_bad.cls") == 2);
  CHECK_FALSE(std::ifstream("preview_bad.csv").good());  // no partial output
}

TEST_CASE("ncpost preview --model: the blocks of the compensated program on the actual machine", "[preview][model]") {
  const std::string scenario = test::data("scenarios/public-clean/");
  const std::string cmd = std::string(NCPOST_BINARY) + " preview --machine " + scenario +
                          "machine.toml --workpiece-origin 0,0,80 --model " + scenario +
                          "truth.json --csv preview_model_test.csv " + scenario +
                          "path.cls > preview_model_test.out 2>&1";
  REQUIRE(WEXITSTATUS(std::system(cmd.c_str())) == 0);
  std::string header;
  const auto rows = read_csv("preview_model_test.csv", header);
  REQUIRE(rows.size() == 1200);
  double largest = 0;
  for (const auto& r : rows) largest = std::max(largest, std::stod(r[2]));
  // the bow is a property of the kinematics; µm-size location errors change it by µm
  CHECK(largest == Approx(1.0367).margin(0.005));
}
