// SPDX-License-Identifier: Apache-2.0
// Issue 13 item 1: with --rtcp every tool change activates that tool's length, in each dialect's
// words (Dialect::tool_call / rtcp_on / rtcp_off with "{tool}"): RTCP off before the change, the
// tool call, RTCP on with the new tool's length after it; without RTCP the tool's length offset.
#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/read/apt/apt_reader.hpp"
#include "ncpost/postproc/write/atomic_file.hpp"
#include "ncpost/postproc/post.hpp"
#include "test_paths.hpp"

using namespace ncpost;

namespace {

const char* const kTwoTools =
    "UNITS/MM\nLOADTL/1\nFEDRAT/500\nGOTO/0,0,10\nGOTO/10,0,10\nLOADTL/6\nGOTO/10,0,0\nGOTO/20,0,0\nFINI\n";

/// The blocks of the program posted from `cl` in `dialect` that are not motions, comments or framing.
std::vector<std::string> tool_blocks(const std::string& dialect, bool rtcp) {
  const Machine m = load_machine(test::source("machines/ac-trunnion.toml"));
  Setup setup;
  setup.workpiece_origin_mm = Vec3d(0, 0, 80);
  std::istringstream in(kTwoTools);
  cl::AptReader reader(in, "two_tools.apt");
  PostOptions options;
  options.rtcp = rtcp;
  const std::string path = "rtcp_tool_length_" + dialect + (rtcp ? "_rtcp" : "") + ".nc";
  {
    AtomicFile out(path);
    NcWriter writer(out, dialect_named(dialect), "XYZAC");
    post_program(reader, "two_tools.apt", NominalSolver(m, setup), writer, options);
    out.commit();
  }
  std::ifstream text(path);
  std::vector<std::string> blocks;
  const std::vector<std::string>& end = dialect_named(dialect).program_end;  // M5 ... M30: not tool words
  for (std::string line; std::getline(text, line);) {
    if (dialect == "heidenhain") line = line.substr(line.find(' ') + 1);  // block number
    static const std::regex axis_word(R"([XYZAC][-+]?[0-9])");
    if (line.empty() || line[0] == '%' || line[0] == '(' || line[0] == ';' || line[0] == 'O' ||
        line.rfind("G90", 0) == 0 || line.rfind("BEGIN", 0) == 0 || line.rfind("END", 0) == 0 ||
        std::regex_search(line, axis_word) || std::find(end.begin(), end.end(), line) != end.end())
      continue;
    blocks.push_back(line);
  }
  return blocks;
}

}  // namespace

TEST_CASE("RTCP: each tool change activates that tool's length in every dialect", "[post][rtcp]") {
  using V = std::vector<std::string>;
  CHECK(tool_blocks("fanuc", true) == V{"T1 M6", "G43.4 H1", "G49", "T6 M6", "G43.4 H6", "G49"});
  CHECK(tool_blocks("haas", true) == V{"T1 M6", "G234 H1", "G49", "T6 M6", "G234 H6", "G49"});
  CHECK(tool_blocks("linuxcnc", true) ==
        V{"T1 M6", "G43 H1", "M428", "M429", "G49", "T6 M6", "G43 H6", "M428", "M429", "G49"});
  CHECK(tool_blocks("sinumerik", true) == V{"T1 M6 D1", "TRAORI", "TRAFOOF", "T6 M6 D1", "TRAORI", "TRAFOOF"});
  CHECK(tool_blocks("heidenhain", true) == V{"TOOL CALL 1 Z", "M128", "M129", "TOOL CALL 6 Z", "M128", "M129"});
}

TEST_CASE("without RTCP each tool change writes the tool's length offset", "[post][rtcp]") {
  using V = std::vector<std::string>;
  CHECK(tool_blocks("fanuc", false) == V{"T1 M6", "G43 H1", "T6 M6", "G43 H6"});
  CHECK(tool_blocks("haas", false) == V{"T1 M6", "G43 H1", "T6 M6", "G43 H6"});
  CHECK(tool_blocks("linuxcnc", false) == V{"T1 M6", "G43", "T6 M6", "G43"});
  CHECK(tool_blocks("sinumerik", false) == V{"T1 M6 D1", "T6 M6 D1"});
  CHECK(tool_blocks("heidenhain", false) == V{"TOOL CALL 1 Z", "TOOL CALL 6 Z"});
}

TEST_CASE("dialect tool words: {tool} stands for the tool number", "[post][rtcp]") {
  CHECK(with_tool("G43.4 H{tool}", 12) == "G43.4 H12");
  CHECK(with_tool("T{tool} M6 D1", 6) == "T6 M6 D1");
  CHECK(with_tool("M128", 3) == "M128");
  CHECK(with_tool("{tool}{tool}", 7) == "77");
}
