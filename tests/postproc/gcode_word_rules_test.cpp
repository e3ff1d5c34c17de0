// SPDX-License-Identifier: Apache-2.0
// Issue 24: G-code words whose meaning is the control's convention, read by a declared rule.
//  - Two T words in one block (`T01 T02 M06`, NX's Mazak posts): with --tool-words load-next the first
//    is the tool the M06 loads, the second the one pre-selected, which the next change must load;
//    without it the block is refused naming the option.
//  - Coordinates without a decimal point: --integer-words units (X20 = 20 mm), increments (IS-B:
//    X20 = 0.020 mm, 0.0001 in, 0.001 deg), auto (units; a program that also writes whole numbers
//    with a point is refused, naming both lines). Expected values are computed here from those rules;
//    posted programs are read back with the tests' own executor (nc_executor.hpp).
#include <catch2/catch.hpp>

#include <algorithm>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cl_records.hpp"
#include "cli_run.hpp"
#include "input_output_tips.hpp"
#include "nc_executor.hpp"
#include "shipped_machines.hpp"
#include "temp_dir.hpp"
#include "test_paths.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/postproc/read/gcode/gcode_cl_reader.hpp"

using namespace ncpost;
using namespace ncpost::test;

namespace {

gcode::GcodeReaderOptions rules(cl::ToolWords tools, cl::IntegerWords integers) {
  gcode::GcodeReaderOptions o;
  o.tool_words = tools;
  o.integer_words = integers;
  return o;
}

std::vector<cl::Record> read_all(const std::string& text, const gcode::GcodeReaderOptions& o) {
  std::istringstream in(text);
  gcode::GcodeClReader r(in, "t.nc", vmcl600(), Setup{}, o);
  return all_records(r);
}

/// The InputError of reading `text` (line and message); fails the test when it reads.
InputError refusal(const std::string& text, const gcode::GcodeReaderOptions& o) {
  try {
    read_all(text, o);
  } catch (const InputError& e) {
    return e;
  }
  FAIL("read without an error");
  throw;  // unreachable
}

std::vector<int> tools_changed(const std::vector<cl::Record>& records) {
  std::vector<int> tools;
  for (const cl::ToolChange& t : only<cl::ToolChange>(records)) tools.push_back(t.number);
  return tools;
}

/// The T words of `T<n> M6` blocks of a written program, in order.
std::vector<int> written_tool_calls(const std::string& program) {
  static const std::regex call(R"(\bT(\d+) M6\b)");
  std::vector<int> tools;
  for (std::sregex_iterator it(program.begin(), program.end(), call), end; it != end; ++it)
    tools.push_back(std::stoi((*it)[1].str()));
  return tools;
}

// three changes in the Mazak form: each pre-selects the tool the next one loads
const char* const kMazakChanges =
    "%\nO0001\nG21 G90 G17 G94\nT01 T02 M06\nG0 X10. Y10. Z50. S1000 M3\nG43 Z30. H01\nG1 Z-1. F200\n"
    "X40.\nG0 Z50.\nT02 T03 M06\nG43 Z30. H02\nG0 X20. Y20.\nG1 Z-2. F200\nG0 Z50.\nT03 T03 M06\n"
    "G43 Z30. H03\nG0 X30. Y5.\nG1 Z-3. F200\nG0 Z50.\nM30\n%\n";

}  // namespace

TEST_CASE("tool words: T01 T02 M06 is refused naming --tool-words, and load-next loads the first T") {
  const InputError e = refusal(kMazakChanges, rules(cl::ToolWords::one, cl::IntegerWords::units));
  CHECK(e.where().line == 4);
  CHECK(e.where().column == 5);  // the second T word
  CHECK_THAT(e.detail(), Catch::Contains("--tool-words load-next"));
  // the rule: the first T of each M06 block is the tool it loads
  CHECK(tools_changed(read_all(kMazakChanges, rules(cl::ToolWords::load_next, cl::IntegerWords::units))) ==
        std::vector<int>{1, 2, 3});
}

TEST_CASE("tool words: a pre-selection the next change does not load is refused naming both lines") {
  std::string text = kMazakChanges;
  text.replace(text.find("T02 T03 M06"), 11, "T04 T03 M06");  // T02 was pre-selected at line 4
  const InputError e = refusal(text, rules(cl::ToolWords::load_next, cl::IntegerWords::units));
  CHECK(e.where().line == 10);
  CHECK_THAT(e.detail(), Catch::Contains("loads T4") && Catch::Contains("line 4 pre-selected T2"));
  // a T word alone between them selects anew: then the change may load it
  text.replace(text.find("G0 Z50.\nT04"), 8, "G0 Z50.\nT4\n");
  CHECK(tools_changed(read_all(text, rules(cl::ToolWords::load_next, cl::IntegerWords::units))) ==
        std::vector<int>{1, 4, 3});
  // two T words without M06: not a change, refused
  const InputError without_change = refusal("G0 X0. Y0. Z50.\nT01 T02\nM30\n", rules(cl::ToolWords::load_next, {}));
  CHECK(without_change.where().line == 2);
  CHECK_THAT(without_change.detail(), Catch::Contains("without M06"));
}

TEST_CASE("tool words: the Mazak changes posted with load-next call the loaded tools and cut where the input does") {
  const std::string dir = make_temp_dir("tool_words");
  const std::string in = write_text_file(dir + "/in.nc", kMazakChanges);
  const PostRun r = run_post(
      "--machine " + source("machines/vmcl600.toml") + " --tolerance none --dialect fanuc --tool-words load-next", in,
      dir + "/out.nc", dir + "/log");
  INFO(r.log);
  REQUIRE(r.exit_code == 0);
  CHECK(written_tool_calls(r.program) == std::vector<int>{1, 2, 3});
  ControlSpec spec;
  spec.offsets["G54"] = {{'X', 0.0}, {'Y', 0.0}, {'Z', 0.0}};
  CHECK(compare_tips(kMazakChanges, spec, "G54", "vmcl600.toml", r.program) == 13);
}

TEST_CASE("integer words: auto reads units, and refuses a program that also writes whole numbers with a point") {
  // grbl / LinuxCNC style: trailing zeros stripped, never a point on a whole number: units
  const std::string stripped = "G21 G90 G94\nG0 X20 Y12.5 Z5\nG1 Z-1 F100\nX-35\nM30\n";
  const auto ms = only<cl::Motion>(read_all(stripped, rules(cl::ToolWords::one, cl::IntegerWords::automatic)));
  REQUIRE(ms.size() == 3);
  CHECK(ms[0].point.tip_mm.x() == Approx(20.0));
  CHECK(ms[2].point.tip_mm.x() == Approx(-35.0));
  // a writer that puts a point on whole numbers (X0., Z50.) and then writes X20: refused at X20, naming Z50.'s line
  const std::string mixed = "G21 G90 G94\nG0 X0. Y0. Z50.\nG1 Z-1.5 F100\nX20\nM30\n";
  const InputError e = refusal(mixed, rules(cl::ToolWords::one, cl::IntegerWords::automatic));
  CHECK(e.where().line == 4);
  CHECK(e.where().column == 1);
  CHECK_THAT(e.detail(), Catch::Contains("X20 has no decimal point") && Catch::Contains("t.nc:2") &&
                             Catch::Contains("--integer-words increments") && Catch::Contains("0.02 mm"));
  // the same words the other way round: refused at the point, naming the bare word's line
  const InputError other = refusal("G0 X20 Y0 Z50\nG1 Z-1.5 F100\nX0.\nM30\n", rules({}, cl::IntegerWords::automatic));
  CHECK(other.where().line == 3);
  CHECK_THAT(other.detail(), Catch::Contains("X20 at t.nc:1"));
  // a value computed by an expression is a number in units: no evidence either way
  const auto computed =
      only<cl::Motion>(read_all("#1 = 20\nG0 X#1 Y0 Z50\nG1 X20 F100\nM30\n", rules({}, cl::IntegerWords::automatic)));
  REQUIRE(computed.size() == 2);
  CHECK(computed[1].point.tip_mm.x() == Approx(20.0));
}

TEST_CASE("integer words: a dialect whose control reads units ([input] integer_words) makes auto read units") {
  const std::string dir = make_temp_dir("integer_words_dialect");
  const std::string in = write_text_file(dir + "/in.nc", "G21 G90 G94\nG0 X0. Y0. Z50.\nG1 Z-1.5 F100\nX20\nM30\n");
  const std::string args = "--machine " + source("machines/vmcl600.toml") + " --tolerance none --dialect ";
  for (const char* dialect : {"linuxcnc", "haas"}) {
    const PostRun r = run_post(args + dialect, in, dir + "/" + dialect + ".nc", dir + "/" + dialect + ".log");
    INFO(dialect << ": " << r.log);
    REQUIRE(r.exit_code == 0);
    const Executor ex(source("machines/vmcl600.toml"), ExecJob{}, r.program);
    REQUIRE_FALSE(ex.blocks.empty());
    CHECK((ex.at(ex.blocks.back(), 1.0).tip_W - V3(20.0, 0.0, -1.5)).norm() < 1e-3);  // X20 = 20 mm
  }
  // fanuc names no rule: auto asks; the option answers
  CHECK(run_post(args + "fanuc", in, dir + "/f.nc", dir + "/f.log").exit_code == 2);
  const PostRun units = run_post(args + "fanuc --integer-words units", in, dir + "/u.nc", dir + "/u.log");
  CHECK(units.exit_code == 0);
  // a .ngc file is RS274NGC's (LinuxCNC's): auto reads units under any dialect
  const std::string ngc = write_text_file(dir + "/in.ngc", "G21 G90 G94\nG0 X0. Y0. Z50.\nG1 Z-1.5 F100\nX20\nM30\n");
  const PostRun from_ngc = run_post(args + "fanuc", ngc, dir + "/n.nc", dir + "/n.log");
  INFO(from_ngc.log);
  REQUIRE(from_ngc.exit_code == 0);
  const Executor ex(source("machines/vmcl600.toml"), ExecJob{}, from_ngc.program);
  REQUIRE_FALSE(ex.blocks.empty());
  CHECK((ex.at(ex.blocks.back(), 1.0).tip_W - V3(20.0, 0.0, -1.5)).norm() < 1e-3);  // X20 = 20 mm
}

TEST_CASE("integer words: increments posted and read back: X20 is 0.020 mm, under G20 0.0020 in") {
  const std::string dir = make_temp_dir("integer_words");
  // a Fanuc program (DPI = 0) whose integers are increments, one parameter (in units), a tape-format word
  const std::string program =
      "%\nO0001\nG21 G90 G94 G17\nG0 X20 Y12.5 Z5000\nG1 Z-1500 F100\nX-35.\n#1 = 2\nY#1\nG20\nX0019685\n"
      "G1 Y-0010 F10.\nM30\n%\n";
  const std::string in = write_text_file(dir + "/in.nc", program);
  const PostRun r = run_post(
      "--machine " + source("machines/vmcl600.toml") + " --tolerance none --dialect fanuc --integer-words increments",
      in, dir + "/out.nc", dir + "/log");
  INFO(r.log);
  REQUIRE(r.exit_code == 0);
  // the ends by the rule (mm): 0.001 mm per unit under G21, 0.0001 in = 0.00254 mm under G20
  const double in_mm = 25.4;
  const std::vector<V3> expected = {V3(0.020, 12.5, 5.0),          V3(0.020, 12.5, -1.5),
                                    V3(-35.0, 12.5, -1.5),         V3(-35.0, 2.0, -1.5),
                                    V3(1.9685 * in_mm, 2.0, -1.5), V3(1.9685 * in_mm, -0.001 * in_mm, -1.5)};
  const Executor ex(source("machines/vmcl600.toml"), ExecJob{}, r.program);
  std::vector<V3> ends;
  for (const ExecBlock& b : ex.blocks) ends.push_back(ex.at(b, 1.0).tip_W);
  REQUIRE(ends.size() >= expected.size());
  std::size_t next = 0;
  for (const V3& want : expected) {  // each expected end reached in order, within 1 µm
    while (next < ends.size() && (ends[next] - want).norm() > 1e-3) ++next;
    INFO("expected end " << want.transpose());
    REQUIRE(next < ends.size());
  }
  // as units, the same program is beyond the VMC's Z travel (Z5000 mm): refused, not posted
  CHECK(run_ncpost("post --machine " + source("machines/vmcl600.toml") + " --integer-words units -o " + dir +
                       "/units.nc " + in,
                   dir + "/units.log") == 3);
}

TEST_CASE("integer words: increments reach a cycle's Q and R but not a dwell's time; a parameter stays in units") {
  // G83 Q2000 = 2 mm pecks, R2000 = 2 mm, Z-5000 = -5 mm; G4 X1000 is a time (1 s as the ms reading gives it)
  const std::string text =
      "G21 G90 G94 G17\nG0 X10. Y10. Z10.\nG98 G83 Z-5000 R2000 Q2000 F100.\nG80\nG4 X1000\n#1 = 3\nG1 X#1 "
      "F100.\nM30\n";
  const auto records = read_all(text, rules({}, cl::IntegerWords::increments));
  const auto cycles = only<cl::Cycle>(records);  // the hole's and G80's (Kind::off)
  REQUIRE(cycles.size() == 2);
  CHECK(cycles[0].kind == cl::Cycle::Kind::deep);
  CHECK(cycles[1].kind == cl::Cycle::Kind::off);
  CHECK(cycles[0].peck_mm == Approx(2.0));
  CHECK(cycles[0].depth_mm == Approx(5.0 + 2.0));  // the bottom 7 mm below the hole's R plane at 2 mm
  const auto dwells = only<cl::Dwell>(records);
  REQUIRE(dwells.size() == 1);
  CHECK(dwells[0].seconds == Approx(1.0));  // X1000 read by --dwell-p auto: 1000 ms, not 1000 increments
  const auto ms = only<cl::Motion>(records);
  REQUIRE(!ms.empty());
  CHECK(ms.back().point.tip_mm.x() == Approx(3.0));  // #1 = 3: X3. (a parameter's value is in units)
}
