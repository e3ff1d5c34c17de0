// SPDX-License-Identifier: Apache-2.0
// Issue 27.5: text before the opening '%' is a leader (the program after it is read), and a
// program that moves nothing while its file has motion words is refused, never an empty output
// with exit 0 (gcode_framing.hpp).
#include <catch2/catch.hpp>

#include <stdlib.h>

#include <fstream>
#include <sstream>

#include "cl_records.hpp"
#include "cli_run.hpp"
#include "shipped_machines.hpp"
#include "temp_dir.hpp"
#include "test_paths.hpp"
#include "text_file.hpp"
#include "ncpost/postproc/read/gcode/gcode_cl_reader.hpp"

using namespace ncpost;
using namespace ncpost::gcode;

namespace {

std::vector<cl::Record> read_all(const std::string& text, std::vector<std::string>* notices = nullptr) {
  std::istringstream in(text);
  GcodeReaderOptions o;
  o.check_limits = false;
  GcodeClReader r(in, "t.ngc", test::ac_trunnion(), Setup{}, o);
  std::vector<cl::Record> out = test::all_records(r);
  if (notices) *notices = r.take_notices();
  return out;
}

InputError error_of(const std::string& text) {
  try {
    read_all(text);
  } catch (const InputError& e) {
    return e;
  }
  FAIL("no error for: " << text);
  throw;
}

}  // namespace

TEST_CASE("gcode leader: comment lines before the opening % are skipped and the program after it is read") {
  // the reproducer of issue 27.5 (a PowerMill program begins so), here with its M30
  std::vector<std::string> notices;
  const auto rs = read_all("(a)\n%\nG21 G90\nG0 X0 Y0 Z10\nG1 Z-1 F100\nX10\nM30\n", &notices);
  const auto ms = test::only<cl::Motion>(rs);
  // the program's own positions (no rotary words: A = C = 0, a machine-axis program on a machine
  // whose W is M at home: tip = X Y Z)
  REQUIRE(ms.size() == 3);
  CHECK(ms[0].point.tip_mm.isApprox(Vec3d(0, 0, 10)));
  CHECK(ms[1].point.tip_mm.isApprox(Vec3d(0, 0, -1)));
  CHECK(ms[2].point.tip_mm.isApprox(Vec3d(10, 0, -1)));
  CHECK(ms[0].rapid);
  CHECK_FALSE(ms[1].rapid);
  // the leader's comment is not a record of the program
  CHECK(test::only<cl::Comment>(rs).empty());
  REQUIRE_FALSE(notices.empty());
  CHECK_THAT(notices[0], Catch::Contains("1 line(s) before the opening '%' at line 2 are a leader"));
}

TEST_CASE("gcode leader: without its closing % or M2/M30 the program after the leader is refused as truncated") {
  const InputError e = error_of("(a)\n%\nG21 G90\nG0 X0 Y0 Z10\nG1 Z-1 F100\nX10\n");
  CHECK(e.where().line == 6);
  CHECK_THAT(e.detail(), Catch::Contains("starts with '%' but ends without the closing '%' or M2/M30"));
}

TEST_CASE("gcode leader: a '%' after a program that ended closes it; motions on both sides of it are refused") {
  // M30 before the first '%': that '%' closes the program, the text after it is not read
  const auto closed = test::only<cl::Motion>(read_all("G0 X1 Y0 Z5\nM30\n%\nG0 X7\n"));
  REQUIRE(closed.size() == 1);
  CHECK(closed[0].point.tip_mm.isApprox(Vec3d(1, 0, 5)));
  // motions before it and nothing moving after it: the '%' closes the program
  CHECK(test::only<cl::Motion>(read_all("G0 X1 Y0 Z5\n%\n(end)\n")).size() == 1);
  // motions before and after: a leader that moves, or a program that ends there: refused
  const InputError both = error_of("G0 X1 Y0 Z5\n%\nG0 X2 Y0 Z5\nM30\n%\n");
  CHECK(both.where().line == 2);
  CHECK_THAT(both.detail(), Catch::Contains("motions stand both before this '%' (line 1) and after it (line 3)"));
}

TEST_CASE("gcode leader: an NX Information listing is read from its '%', or refused saying what it is") {
  // the listing window of NX's post output (tests/data/real/nx_PostProcessed_*.txt): the program
  // after the '%' is the post's
  std::vector<std::string> notices;
  const auto ms = test::only<cl::Motion>(
      read_all("Information listing created by\tMArkos\nDate\t28-Nov-2021\n\n%\nG0 X4 Y0 Z5\nM30\n%\n", &notices));
  REQUIRE(ms.size() == 1);
  CHECK(ms[0].point.tip_mm.isApprox(Vec3d(4, 0, 5)));
  REQUIRE_FALSE(notices.empty());
  CHECK_THAT(notices[0], Catch::Contains("t.ngc:1: an NX 'Information listing' header (3 line(s) before the opening "
                                         "'%' at line 4) is skipped"));
  // a listing with no program framed by '%' after it
  const InputError e = error_of("Information listing created by\tMArkos\nDate\t28-Nov-2021\nG0 X4\nM30\n");
  CHECK(e.where().line == 1);
  CHECK(e.where().column == 1);
  CHECK_THAT(e.detail(), Catch::Contains("NX 'Information listing'"));
  CHECK_THAT(e.detail(), Catch::Contains("post the program file NX's post processor wrote"));
}

TEST_CASE("gcode leader: a program that moves nothing while the file has motion words is an input error") {
  // every motion in a deleted block (block skip on, the default)
  const InputError deleted = error_of("G21 G90\n/G0 X1 Y2 Z3\nM30\n");
  CHECK(deleted.where().line == 2);
  CHECK_THAT(deleted.detail(), Catch::Contains("moves nothing"));
  // motions after the program's end
  const InputError after = error_of("%\nG21\nM30\nG0 X1 Y2 Z3\n%\n");
  CHECK(after.where().line == 4);
  CHECK_THAT(after.detail(), Catch::Contains("after the program's end"));
  // a file with no motion words at all stays a (motionless) program
  CHECK(test::only<cl::Motion>(read_all("%\nG21 G90\n(nothing to cut)\nM30\n%\n")).empty());
}

TEST_CASE("gcode leader: the issue 27.5 reproducer through the executable is never exit 0 with 0 motions") {
  const std::string dir = ncpost::test::make_temp_dir("ncpost_gcode_leader");
  REQUIRE(dir != ".");
  const auto post = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir + "/" + name) << text;
    return test::run_ncpost("post --machine " + test::source("machines/vmcl600.toml") + " -o " + dir + "/" + name +
                                ".nc " + dir + "/" + name,
                            dir + "/" + name + ".log");
  };
  // as the issue gives it: no closing '%' and no M30 after the leader: refused (exit 2)
  CHECK(post("leader.ngc", "(a)\n%\nG21 G90\nG0 X0 Y0 Z10\nG1 Z-1 F100\nX10\n") == 2);
  CHECK_THAT(test::read_text_file(dir + "/leader.ngc.log"), Catch::Contains("leader.ngc:6"));
  // closed: posted, with its three motions
  REQUIRE(post("closed.ngc", "(a)\n%\nG21 G90\nG0 X0 Y0 Z10\nG1 Z-1 F100\nX10\nM30\n%\n") == 0);
  const std::string log = test::read_text_file(dir + "/closed.ngc.log");
  INFO(log);
  CHECK_THAT(log, Catch::Contains("3 CL motions"));
}
