// SPDX-License-Identifier: Apache-2.0
// Issue 24.3: work offsets the input program sets itself (G10 L2, Fanuc G10 L20) re-posted. The posted
// program has one frame, the base offset's at the first motion (docs/formats.md "Work offsets"): every
// later change of an offset's value is in the words, and no G10 is written again (the control would
// shift a second time). The INPUT is executed with the tests' own control interpreter, the OUTPUT with
// nc_executor.hpp (1 µm at every input block end); two ends are also computed here from the rule.
#include <catch2/catch.hpp>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "cli_run.hpp"
#include "input_output_tips.hpp"
#include "nc_executor.hpp"
#include "temp_dir.hpp"
#include "test_paths.hpp"

using namespace ncpost;
using namespace ncpost::test;

namespace {

/// The lines of `program` that hold `word` outside comments.
std::vector<std::string> blocks_with(const std::string& program, const std::string& word) {
  std::vector<std::string> found;
  std::istringstream in(program);
  for (std::string line; std::getline(in, line);) {
    std::string words;
    int depth = 0;
    for (char c : line) {
      depth += c == '(' ? 1 : c == ')' ? -1 : 0;
      if (depth == 0 && c != ')') words += c;
    }
    if (words.find(word) != std::string::npos) found.push_back(line);
  }
  return found;
}

}  // namespace

TEST_CASE("work offsets set by G10 L2 / L20 re-posted: one frame, the shifts in the words, no G10 written again") {
  // G55 set by G10 L2, then moved 40 mm in Y while in force (a second copy of the part, as
  // camotics_botomata_bottom.nc does), then a Fanuc G10 L20 P1 (G54.1 P1) for a third operation
  const std::string input =
      "%\nO0200\nG21 G90 G17 G94\nG10 L2 P1 X-200. Y-100. Z-300.\nG10 L2 P2 X-200. Y-100. Z-300.\nT1 M6\n"
      "G55 G0 X10. Y10. Z20.\nG1 Z-1. F200\nX50.\nG0 Z20.\nG10 L2 P2 Y-60.\nG0 X10. Y10.\nG1 Z-1.\nX50.\n"
      "G0 Z20.\nG10 L20 P1 X-150. Y-100. Z-300.\nG54.1 P1 G0 X0. Y0.\nG1 Z-1.\nX5.\nG0 Z20.\nM30\n%\n";
  const std::string dir = make_temp_dir("g10_repost");
  const PostRun r = run_post("--machine " + source("machines/vmcl600.toml") + " --tolerance none --dialect fanuc",
                             write_text_file(dir + "/in.nc", input), dir + "/out.nc", dir + "/log");
  INFO(r.log);
  REQUIRE(r.exit_code == 0);
  // the output's words are in G55's frame as it stood at the first motion: a G10 written again would
  // shift the control's offset a second time (the executor, like the control's own words, ignores it)
  INFO(r.program);
  CHECK(blocks_with(r.program, "G10").empty());
  CHECK(blocks_with(r.program, "G54.1").empty());
  ControlSpec spec;  // no offset values but the program's own
  CHECK(compare_tips(input, spec, "G55", "vmcl600.toml", r.program) == 12);
  // the second copy is 40 mm further in +Y than the first in the output's frame: its first cut ends
  // at W (50, 10 + 40, -1), the third operation's at G54.1 P1's zero + (5, 0, -1) - G55's = (55, 0, -1)
  const Executor ex(source("machines/vmcl600.toml"), ExecJob{}, r.program);
  const auto reached = [&](const V3& w) {
    return std::any_of(ex.blocks.begin(), ex.blocks.end(),
                       [&](const ExecBlock& b) { return (ex.at(b, 1.0).tip_W - w).norm() < 1e-3; });
  };
  CHECK(reached(V3(50.0, 50.0, -1.0)));
  CHECK(reached(V3(55.0, 0.0, -1.0)));
}
