// SPDX-License-Identifier: Apache-2.0
// Dialects as files (issue 16 item 4): a user's copy of fanuc.toml, edited, changes the program as
// edited; a dialect file is validated like a machine file (file:line:col, exit 2); the built-in
// dialects come from the embedded copies whatever the working directory, or from
// $NCPOST_DIALECT_DIR when that holds an edited copy.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <string>

#include <sys/wait.h>

#include "cli_run.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/postproc/dialect.hpp"
#include "temp_dir.hpp"
#include "test_paths.hpp"

using namespace ncpost;

namespace {

const std::string kFanuc = test::read_text_file(test::source("postproc/dialects/fanuc.toml"));

/// `text` with its first `from` replaced by `to` (REQUIREs that it occurs).
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

const std::string kCl = "UNITS/MM\nLOADTL/3\nRAPID\nGOTO/0,0,50\nFEDRAT/MMPM,400\nGOTO/10,0,50\nFINI\n";

/// `ncpost post ... --dialect DIALECT` of kCl in `dir` (`env`: prefix such as "NCPOST_DIALECT_DIR=..");
/// the exit code, the program in *program and the messages in *log.
int post(const std::string& dir, const std::string& dialect, std::string* program, std::string* log,
         const std::string& env = "") {
  const std::string cl = test::write_text_file(dir + "/part.cls", kCl);
  const std::string cmd = env + NCPOST_BINARY + " post --machine '" + test::source("machines/vmcl600.toml") +
                          "' --dialect '" + dialect + "' -o '" + dir + "/out.nc' '" + cl + "' > '" + dir + "/log.txt' 2>&1";
  const int status = std::system(cmd.c_str());
  const int rc = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  *program = rc == 0 ? test::read_text_file(dir + "/out.nc") : "";
  *log = test::read_text_file(dir + "/log.txt");
  return rc;
}

}  // namespace

TEST_CASE("a user's copy of fanuc.toml with M99 and a header line writes that program", "[dialect][file]") {
  const std::string dir = test::make_temp_dir("dialect_file");
  std::string text = replaced(kFanuc, "end = [\"M30\"]", "end = [\"M99\"]");
  text = replaced(text, "start = [\"O0001 ({program})\", ", "start = [\"O0001 ({program})\", \"(SHOP: CELL 4)\", ");
  const std::string mine = test::write_text_file(dir + "/my-fanuc.toml", text);
  std::string program, log, fanuc;
  REQUIRE(post(dir, mine, &program, &log) == 0);
  REQUIRE(post(dir, "fanuc", &fanuc, &log) == 0);
  // the same program but for the header line and the end
  std::string expected = replaced(fanuc, "O0001 (NCPOST)\n", "O0001 (NCPOST)\n(SHOP: CELL 4)\n");
  expected = replaced(expected, "\nM30\n%\n", "\nM99\n%\n");
  CHECK(program == expected);
  CHECK_THAT(program, Catch::StartsWith("%\nO0001 (NCPOST)\n(SHOP: CELL 4)\n") && Catch::EndsWith("G1 X10.0000 F400.0\nM99\n%\n"));
}

TEST_CASE("a dialect file is validated: file:line:col, exit 2, no program", "[dialect][file]") {
  const std::string dir = test::make_temp_dir("dialect_file_bad");
  struct Case {
    std::string from, to, message;
  };
  const Case cases[] = {
      {"line_numbers = false", "line_numbers = false\nblock_skip = true", ":16:1: unknown key 'block_skip' in [blocks]"},
      {"linear_decimals = 4", "linear_decimals = \"4\"", ":17:19: linear_decimals in [blocks]: expected an integer"},
      {"angle_decimals = 4", "angle_decimals = 12", ":18:18: angle_decimals in [blocks] is 12: expected 0 to 6"},
      {"end = [\"M30\"]", "end = \"M30\"", ":12:7: end in [program]: expected a list of blocks"},
      {"call = [\"T{tool} M6\"]", "call = [\"T{tool} M6 H{length}\"]", ":28:9: unknown placeholder '{length}'"},
      {"replaced = \"()%;\"        # characters that must not appear in a comment ...\nreplacements = \"[]  \"",
       "replaced = \"(%;\"\nreplacements = \"[  \"", ":22:12: replaced in [comments]: expected ')' among the characters"},
      {"\n[dwell]", "\n[dwel]", ":47:2: unknown section [dwel]"},
      {"style = \"parentheses\"", "style = \"braces\"", "expected \"parentheses\" or \"semicolon\""},
  };
  for (const Case& c : cases) {
    INFO(c.to);
    const std::string file = test::write_text_file(dir + "/bad.toml", replaced(kFanuc, c.from, c.to));
    std::string program, log;
    CHECK(post(dir, file, &program, &log) == 2);
    CHECK_THAT(log, Catch::Contains("bad.toml") && Catch::Contains(c.message));
    CHECK(program.empty());
  }
  std::string program, log;
  CHECK(post(dir, dir + "/missing.toml", &program, &log) == 2);
  CHECK_THAT(log, Catch::Contains("missing.toml") && Catch::Contains("cannot open the dialect file"));
  CHECK(post(dir, "fanuk", &program, &log) == 1);
  CHECK_THAT(log, Catch::Contains("fanuc, haas, linuxcnc, sinumerik, heidenhain"));
}

TEST_CASE("built-in dialects: the embedded copies, or an edited copy in $NCPOST_DIALECT_DIR", "[dialect][file]") {
  for (const std::string& name : builtin_dialect_names()) {
    INFO(name);
    const Dialect d = dialect_named(name);
    CHECK(d.name == name);
    // the embedded copy is the shipped file
    CHECK(parse_dialect(test::read_text_file(test::source("postproc/dialects/" + name + ".toml")), name).program_end ==
          d.program_end);
  }
  const std::string dir = test::make_temp_dir("dialect_env");
  test::write_text_file(dir + "/fanuc.toml", replaced(kFanuc, "end = [\"M30\"]", "end = [\"M99\"]"));
  std::string program, log;
  REQUIRE(post(dir, "fanuc", &program, &log, "NCPOST_DIALECT_DIR='" + dir + "' ") == 0);
  CHECK_THAT(program, Catch::EndsWith("\nM99\n%\n"));
  REQUIRE(post(dir, "haas", &program, &log, "NCPOST_DIALECT_DIR='" + dir + "' ") == 0);  // not there: embedded
  CHECK_THAT(program, Catch::EndsWith("\nM30\n%\n"));
}
