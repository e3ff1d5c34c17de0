// SPDX-License-Identifier: Apache-2.0
// The tool length of G-code input: `G43 H<n>` names the register whose length the program cuts
// with. It was rewritten to the tool's number (`T3 ... G43 H23` posted as `G43 H3`: Z off by the
// difference of two lengths) or dropped (a program without a tool change posted under the
// header's G49). G49 cancels the length: a cut after it in the work's coordinates is refused.
#include <catch2/catch.hpp>

#include <algorithm>
#include <sstream>

#include "shipped_machines.hpp"
#include "cl_records.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/read/gcode/gcode_cl_reader.hpp"
#include "ncpost/postproc/post.hpp"
#include "text_file.hpp"

using namespace ncpost;

namespace {

std::vector<cl::Record> read_all(const std::string& text) {
  std::istringstream in(text);
  gcode::GcodeClReader r(in, "t.nc", test::ac_trunnion(), Setup{});
  std::vector<cl::Record> out;
  while (auto x = r.next()) out.push_back(std::move(*x));
  return out;
}

/// The blocks of the program posted from `text` in `dialect` (no header comments, no numbers).
std::vector<std::string> post_blocks(const std::string& text, const std::string& dialect, bool rtcp = false) {
  std::istringstream in(text);
  gcode::GcodeClReader reader(in, "t.nc", test::ac_trunnion(), Setup{});
  const std::string out_path = "gcode_tool_length_test_" + dialect + ".nc";
  {
    AtomicFile out(out_path);
    NcWriter writer(out, dialect_named(dialect), "XYZAC");
    PostOptions o;
    o.rtcp = rtcp;
    post_program(reader, "t.nc", NominalSolver(test::ac_trunnion(), Setup{}), writer, o);
    out.commit();
  }
  std::istringstream lines(test::read_text_file(out_path));
  std::vector<std::string> blocks;
  for (std::string line; std::getline(lines, line);)
    if (!line.empty() && line[0] != '(' && line[0] != ';') blocks.push_back(line);
  return blocks;
}

/// The blocks of `blocks` that start with `prefix`, in order.
std::vector<std::string> starting_with(const std::vector<std::string>& blocks, const std::string& prefix) {
  std::vector<std::string> out;
  for (const auto& b : blocks)
    if (b.rfind(prefix, 0) == 0) out.push_back(b);
  return out;
}

std::string input_error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  FAIL("no input error");
  return {};
}

const std::string kTwoTools =
    "G21 G90 G94\nT3 M6\nS1000 M3\nG0 G43 H23 Z50.\nG0 X10. Y10. A0 C0\nG1 Z-1. F100.\n"
    "T4 M6\nG0 G43 H4 Z50.\nG1 X20.\nM30\n";

}  // namespace

TEST_CASE("G-code: G43 H is a length record after the tool change; H0 and G49 cancel") {
  const auto rs = read_all(kTwoTools);
  const auto tools = test::only<cl::ToolChange>(rs);
  const auto lengths = test::only<cl::LengthOffset>(rs);
  REQUIRE(tools.size() == 2);
  REQUIRE(lengths.size() == 2);
  CHECK(lengths[0].register_number == 23);
  CHECK(lengths[0].where.line == 4);
  CHECK(lengths[1].register_number == 4);
  // the record follows its tool change and precedes the motion of its block
  std::size_t change = 0, length = 0, motion = 0;
  for (std::size_t i = 0; i < rs.size(); ++i) {
    if (std::holds_alternative<cl::ToolChange>(rs[i]) && !change) change = i + 1;
    if (std::holds_alternative<cl::LengthOffset>(rs[i]) && !length) length = i + 1;
    if (std::holds_alternative<cl::Motion>(rs[i]) && !motion) motion = i + 1;
  }
  CHECK(change < length);
  CHECK(length < motion);
  // G49 in the safety line before any G43 leaves the motions as they were
  CHECK(test::only<cl::Motion>(read_all("G21 G90 G40 G49 G80\nG0 X10. Y10. Z50. A0 C0\nM30\n")).size() == 1);
  // after a G43, G49 (or G43 H0) cancels the length: a cut is refused
  const std::string head = "G21 G90\nT1 M6\nG0 G43 H1 Z50. X0 Y0 A0 C0\nG1 Z-1. F100.\nG0 Z50.\nG49\n";
  CHECK_THAT(input_error_of([&] { read_all(head + "G1 X10. Z-1.\nM30\n"); }),
             Catch::Contains("t.nc:7:4: a cutting motion with the tool length cancelled (G49 or H0 at line 6)"));
  // a rapid in Z is posted as the rapids before the first G43 are (the tip at Z), with a notice
  std::vector<std::string> notices;
  {
    std::istringstream in(head + "G0 Z60.\nM30\n");
    gcode::GcodeClReader r(in, "t.nc", test::ac_trunnion(), Setup{});
    std::vector<cl::Record> rs;
    while (auto x = r.next()) rs.push_back(std::move(*x));
    notices = r.take_notices();
    CHECK(test::only<cl::Motion>(rs).back().point.tip_mm.z() == Approx(60.0));
  }
  CHECK(std::any_of(notices.begin(), notices.end(), [](const std::string& n) {
    return n.find("t.nc:7:4: a rapid in Z with the tool length cancelled (G49 or H0 at line 6) is posted") !=
           std::string::npos;
  }));
  CHECK_THAT(input_error_of([&] { read_all(head + "G81 X5. Y5. Z-3. R2. F50.\nM30\n"); }),
             Catch::Contains("t.nc:7:5: a cutting motion with the tool length cancelled"));
  CHECK_THAT(input_error_of([&] { read_all("G21 G90\nG0 G43 H1 Z50. X0 Y0 A0 C0\nG43 H0\nG1 Z10. F100.\nM30\n"); }),
             Catch::Contains("(G49 or H0 at line 3)"));
  // ... but a return to the reference point is a machine move; rapids in X Y and the rotary axes
  // position the next tool (the safety line of the next operation), and G43 restores the length
  const auto next_op = read_all(head +
                                "G91 G28 Z0\nG90\nT2 M6\nG0 G90 G40 G49 G80\nG0 X20. Y5.\n"
                                "G43 H2 Z30.\nG1 Z-1.\nM30\n");
  const auto m = test::only<cl::Motion>(next_op);
  REQUIRE(m.size() >= 3);
  CHECK(m.back().point.tip_mm.z() == Approx(-1.0).margin(1e-9));
}

TEST_CASE("post: the length register of G43 H is written as programmed (fanuc, haas, RTCP)") {
  const auto fanuc = post_blocks(kTwoTools, "fanuc");
  // T3's own register with its change, then the program's H23 before the first motion
  CHECK(starting_with(fanuc, "G43") == std::vector<std::string>{"G43 H3", "G43 H23", "G43 H4"});
  CHECK(starting_with(fanuc, "T") == std::vector<std::string>{"T3 M6", "T4 M6"});
  std::size_t h23 = 0, first_motion = 0;
  for (std::size_t i = 0; i < fanuc.size(); ++i) {
    if (fanuc[i] == "G43 H23") h23 = i;
    if (fanuc[i].rfind("G0 X", 0) == 0 && !first_motion) first_motion = i;
  }
  CHECK(h23 > 0);
  CHECK(h23 < first_motion);
  CHECK(starting_with(post_blocks(kTwoTools, "haas"), "G43") ==
        std::vector<std::string>{"G43 H3", "G43 H23", "G43 H4"});
  // with RTCP the length comes with TCP on: the program's register
  const auto rtcp = post_blocks(kTwoTools, "fanuc", true);
  CHECK(starting_with(rtcp, "G43.4") == std::vector<std::string>{"G43.4 H3", "G43.4 H23", "G43.4 H4"});
  // a program without a tool change: its G43 H1 is written (it was left under the header's G49)
  const auto no_change = post_blocks("G21 G90\nG0 G43 H1 Z50.\nG0 X10. Y10. A0 C0\nG1 Z-1. F100.\nM30\n", "fanuc");
  CHECK(starting_with(no_change, "G43") == std::vector<std::string>{"G43 H1"});
  // the tool's own register: nothing more than the change writes
  const auto own = post_blocks("G21 G90\nT2 M6\nG0 G43 H2 Z50.\nG0 X10. Y10. A0 C0\nM30\n", "fanuc");
  CHECK(starting_with(own, "G43") == std::vector<std::string>{"G43 H2"});
}

TEST_CASE("post: a length register the dialect cannot write is refused (heidenhain, sinumerik)") {
  for (const char* d : {"heidenhain", "sinumerik"}) {
    CAPTURE(d);
    const std::string e = input_error_of([&] { post_blocks(kTwoTools, d); });
    CHECK_THAT(e, Catch::Contains("t.nc:4:8: H23: the tool length of register 23 (the tool in the spindle is T3) "
                                  "cannot be written in the " +
                                  std::string(d) + " dialect"));
    // the tool's own register is what its call activates: posted
    CHECK_NOTHROW(post_blocks("G21 G90\nT2 M6\nS1000 M3\nG0 G43 H2 Z50.\nG0 X10. Y10. A0 C0\nM30\n", d));
  }
}
