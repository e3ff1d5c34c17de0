// The ncpost executable: exit codes of spec/cli.md, atomic output, help for every subcommand.
#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "test_paths.hpp"

namespace {

int run(const std::string& args, std::string* err = nullptr) {
  const std::string cmd = std::string(NCPOST_BINARY) + " " + args + " >cli_test.out 2>cli_test.err";
  const int rc = std::system(cmd.c_str());
  if (err) {
    std::ifstream e("cli_test.err");
    std::stringstream s;
    s << e.rdbuf();
    *err = s.str();
  }
  return WEXITSTATUS(rc);
}

bool exists(const std::string& p) { return std::ifstream(p).good(); }

void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

}  // namespace

using ncpost::test::shared;
using ncpost::test::source;

TEST_CASE("help for ncpost and every subcommand") {
  CHECK(run("--help") == 0);
  for (const char* sub : {"post", "preview", "identify", "simulate", "plan", "sensitivity"}) {
    INFO(sub);
    CHECK(run(std::string(sub) + " --help") == 0);
  }
}

TEST_CASE("exit codes: usage 1, bad input 2, infeasible 3; no partial output") {
  const std::string machine = source("machines/ac-trunnion.toml");
  std::string err;
  CHECK(run("post --bogus", &err) == 1);
  CHECK(run("post --machine " + machine, &err) == 1);  // missing INPUT

  write("cli_bad.cls", "GOTO/1,2,3\nGOTO/1,2.5.3,4\n");
  write("cli_out.nc", "GOOD OLD PROGRAM\n");
  CHECK(run("post --machine " + machine + " -o cli_out.nc cli_bad.cls", &err) == 2);
  CHECK_THAT(err, Catch::Contains("cli_bad.cls:2:") && Catch::Contains("^"));
  std::ifstream old("cli_out.nc");
  std::string first;
  std::getline(old, first);
  CHECK(first == "GOOD OLD PROGRAM");  // not clobbered

  write("cli_bad_machine.toml", "[machine]\nname = \"x\"\n");
  CHECK(run("post --machine cli_bad_machine.toml cli_bad.cls", &err) == 2);
  CHECK_THAT(err, Catch::Contains("cli_bad_machine.toml"));

  // a tool axis tilted 150 deg is beyond A's limits [-120, 120] in both solutions
  write("cli_far.cls", "GOTO/0,0,0,0,0.5,-0.8660254\n");
  CHECK(run("post --machine " + machine + " -o cli_new.nc cli_far.cls", &err) == 3);
  CHECK_THAT(err, Catch::Contains("cli_far.cls:1"));
  CHECK_FALSE(exists("cli_new.nc"));
}

TEST_CASE("post writes a program in each dialect") {
  for (const char* d : {"fanuc", "haas", "linuxcnc", "sinumerik", "heidenhain"}) {
    INFO(d);
    CHECK(run(std::string("post --machine ") + shared("data/scenarios/public-clean/machine.toml") +
              " --workpiece-origin 0,0,80 --dialect " + d + " -o cli_dialect.nc " +
              shared("data/scenarios/public-clean/path.cls")) == 0);
    std::ifstream in("cli_dialect.nc");
    std::stringstream s;
    s << in.rdbuf();
    const std::string text = s.str();
    CHECK(text.size() > 10000);
    if (std::string(d) == "heidenhain") CHECK_THAT(text, Catch::Contains("BEGIN PGM") && Catch::Contains("L X"));
    else CHECK_THAT(text, Catch::Contains("G1") && Catch::Contains("G93"));
  }
}
