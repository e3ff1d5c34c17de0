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
#include "ncpost/postproc/write/dialect.hpp"
#include "temp_dir.hpp"
#include "test_paths.hpp"
#include "text_edit.hpp"

using namespace ncpost;

using ncpost::test::replaced;

namespace {

const std::string kFanuc = test::read_text_file(test::source("postproc/dialects/fanuc.toml"));

const std::string kCl = "UNITS/MM\nLOADTL/3\nRAPID\nGOTO/0,0,50\nFEDRAT/MMPM,400\nGOTO/10,0,50\nFINI\n";

/// `ncpost post ... --dialect DIALECT` of kCl in `dir` (`env`: prefix such as "NCPOST_DIALECT_DIR=..");
/// the exit code, the program in *program and the messages in *log.
int post(const std::string& dir, const std::string& dialect, std::string* program, std::string* log,
         const std::string& env = "") {
  const std::string cl = test::write_text_file(dir + "/part.cls", kCl);
  const std::string cmd = env + NCPOST_BINARY + " post --machine '" + test::source("machines/vmcl600.toml") +
                          "' --dialect '" + dialect + "' -o '" + dir + "/out.nc' '" + cl + "' > '" + dir +
                          "/log.txt' 2>&1";
  const int status = std::system(cmd.c_str());
  const int rc = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  *program = rc == 0 ? test::read_text_file(dir + "/out.nc") : "";
  *log = test::read_text_file(dir + "/log.txt");
  return rc;
}

}  // namespace

TEST_CASE("a user's copy of fanuc.toml with M99 and a header line writes that program", "[dialect][file]") {
  const std::string dir = test::make_temp_dir("dialect_file");
  std::string text =
      replaced(kFanuc, "end = [\"M5\", \"M9\", \"G91 G28 Z0\", \"G90\", \"M30\"]", "end = [\"M5\", \"M99\"]");
  text = replaced(text, "start = [\"O0001 ({program})\", ", "start = [\"O0001 ({program})\", \"(SHOP: CELL 4)\", ");
  const std::string mine = test::write_text_file(dir + "/my-fanuc.toml", text);
  std::string program, log, fanuc;
  REQUIRE(post(dir, mine, &program, &log) == 0);
  REQUIRE(post(dir, "fanuc", &fanuc, &log) == 0);
  // the same program but for the header line and the end
  std::string expected = replaced(fanuc, "O0001 (NCPOST)\n", "O0001 (NCPOST)\n(SHOP: CELL 4)\n");
  expected = replaced(expected, "\nM5\nM9\nG91 G28 Z0\nG90\nM30\n%\n", "\nM5\nM99\n%\n");
  CHECK(program == expected);
  // the start and the end exactly: the edited blocks, then the built-in file's blocks
  CHECK_THAT(program, Catch::StartsWith("%\nO0001 (NCPOST)\n(SHOP: CELL 4)\n(ncpost "));
  CHECK_THAT(program, Catch::Contains(")\nG90 G21 G94 G17 G40 G49 G80\nT3 M6\nG43 H3\nG0 X"));
  CHECK_THAT(program, Catch::EndsWith("\nG94 G1 X10.0000 F400.0\nM5\nM99\n%\n"));
  CHECK_THAT(fanuc, Catch::EndsWith("\nG94 G1 X10.0000 F400.0\nM5\nM9\nG91 G28 Z0\nG90\nM30\n%\n"));
}

TEST_CASE("a dialect file is validated: file:line:col, exit 2, no program", "[dialect][file]") {
  const std::string dir = test::make_temp_dir("dialect_file_bad");
  struct Case {
    std::string from, to, message;
  };
  const Case cases[] = {
      {"line_numbers = false", "line_numbers = false\nblock_skip = true",
       ":18:1: unknown key 'block_skip' in [blocks]"},
      {"linear_decimals = 4", "linear_decimals = \"4\"", ":22:19: linear_decimals in [blocks]: expected an integer"},
      {"angle_decimals = 4", "angle_decimals = 12", ":23:18: angle_decimals in [blocks] is 12: expected 0 to 6"},
      {"end = [\"M5\", \"M9\", \"G91 G28 Z0\", \"G90\", \"M30\"]", "end = \"M30\"",
       ":14:7: end in [program]: expected a list of blocks"},
      {"call = [\"T{tool} M6\"]", "call = [\"T{tool} M6 H{length}\"]", ":53:9: unknown placeholder '{length}'"},
      {"replaced = \"()%;\"        # characters that must not appear in a comment ...\nreplacements = \"[]  \"",
       "replaced = \"(%;\"\nreplacements = \"[  \"",
       ":47:12: replaced in [comments]: expected ')' among the characters"},
      {"\n[dwell]", "\n[dwel]", ":90:2: unknown section [dwel]"},  // (line 90 since [tool] set_offset)
      {"style = \"parentheses\"", "style = \"braces\"", "expected \"parentheses\" or \"semicolon\""},
      // the words that were C++ before: motion, feed, block numbers, arcs, spindle, cycles
      {"feed_modal = true", "feed_modal = \"yes\"", ":33:14: feed_modal in [motion]: expected true or false"},
      {"rapid_feed = \"\"", "rapid_feed = \"\"\nrapid_word = \"G00\"", ":31:1: unknown key 'rapid_word' in [motion]"},
      {"rapid = \"G0\"", "rapid = \"G1\"",
       ":29:9: modal in [motion]: expected false when rapid and linear are the same"},
      {"feed_letter = \"F\"", "feed_letter = \"\"", ":31:15: feed_letter in [motion]: expected a word"},
      {"number_format = \"N{n} \"", "number_format = \"N \"",
       ":18:17: number_format in [blocks]: expected the number's place"},
      {"number_format = \"N{n} \"", "number_format = \"N{line} \"",
       ":18:17: unknown placeholder '{line}' in number_format"},
      {"planes = [\"G17\", \"G18\", \"G19\"]", "planes = [\"G17\", \"G18\"]",
       ":42:10: planes in [arcs]: expected three words"},
      {"cancel = \"G80\"", "cancel = 80", ":85:10: cancel in [cycles]: expected a string"},
      // a missing placeholder would lose a word of the program
      {"call = [\"T{tool} M6\"]", "call = [\"M6\"]",
       ":53:8: call in [tool] names no {tool}: the tool number would not be written"},
      {"start = [\"S{rpm} {turn}\"]", "start = [\"S{rpm} M3\"]", ":62:9: start in [spindle] names no {turn}"},
      {"start = [\"S{rpm} {turn}\"]", "start = [\"S{rpm} {turn}\"]\nafter_call = [\"{turn}\"]",
       ":63:14: after_call in [spindle]: expected no such key: [tool] call names no {rpm}"},
      // a tool call that takes the speed (Klartext TOOL CALL 6 Z S2000) needs the blocks after it
      {"call = [\"T{tool} M6\"]", "call = [\"T{tool} M6 S{rpm}\"]", ":61:1: missing key 'after_call' in [spindle]"},
      {"inverse_time = \"G93\"     # inverse-time feed of simultaneous moves (\"\": none; such a cut then needs "
       "--rtcp)\n",
       "", ":26:1: missing key 'inverse_time' in [motion]"},
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
  test::write_text_file(
      dir + "/fanuc.toml",
      replaced(kFanuc, "end = [\"M5\", \"M9\", \"G91 G28 Z0\", \"G90\", \"M30\"]", "end = [\"M99\"]"));
  std::string program, log;
  REQUIRE(post(dir, "fanuc", &program, &log, "NCPOST_DIALECT_DIR='" + dir + "' ") == 0);
  CHECK_THAT(program, Catch::EndsWith("\nM99\n%\n"));
  REQUIRE(post(dir, "haas", &program, &log, "NCPOST_DIALECT_DIR='" + dir + "' ") == 0);  // not there: embedded
  CHECK_THAT(program, Catch::EndsWith("\nM30\n%\n"));
}
