// SPDX-License-Identifier: Apache-2.0
// An arc that would expand into more points than kMaxArcSegments is bad input (a fuzzer timeout:
// tests/fuzz/findings/gcode_reader_huge_arc_timeout.ngc), reported with file and line.
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/read/gcode/gcode_cl_reader.hpp"
#include "test_paths.hpp"

using namespace ncpost;

namespace {
std::size_t read_all(std::istream& in, const std::string& name, const Machine& m) {
  gcode::GcodeReaderOptions counting;  // the arcs' point counts, not whether they fit the machine
  counting.check_limits = false;
  gcode::GcodeClReader reader(in, name, m, Setup{}, counting);
  std::size_t n = 0;
  while (auto r = reader.next()) n += std::holds_alternative<cl::Motion>(*r) ? 1 : 0;
  return n;
}
}  // namespace

TEST_CASE("an arc of 33 km radius is refused with its line, not expanded for seconds") {
  const Machine m = load_machine(test::source("machines/ac-trunnion.toml"));
  std::istringstream in("G90 G21 G17\nG0 X0 Y0 Z10 A0 C0\nG1 Z0 F100\nG2 X20 Y5 I5 J33333330\n");
  try {
    read_all(in, "huge.ngc", m);
    FAIL("expected an InputError");
  } catch (const InputError& e) {
    CHECK_THAT(e.what(), Catch::Contains("huge.ngc:4") && Catch::Contains("points"));
  }
  // the fuzzer's reproducer is refused as bad input too, quickly
  std::ifstream finding(test::source("tests/fuzz/findings/gcode_reader_huge_arc_timeout.ngc"), std::ios::binary);
  REQUIRE(finding);
  CHECK_THROWS_AS(read_all(finding, "finding.ngc", m), InputError);
  // an ordinary full circle of radius 1 m still expands
  std::istringstream ok("G90 G21 G17\nG0 X0 Y0 Z10 A0 C0\nG1 Z0 F100\nG2 X0 Y0 I1000 J0\n");
  CHECK(read_all(ok, "ok.ngc", m) > 1000);
}
