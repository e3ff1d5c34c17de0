// SPDX-License-Identifier: Apache-2.0
// `post --verify` reads the program it wrote (issue 27.7): a dialect file that writes the wrong
// arc word, or another feed word, gives a program that does not do what the input means; --verify
// must see it in the written text (exit 5, no program), where it used to re-run its own values.
#include <catch2/catch.hpp>

#include <string>

#include "cli_run.hpp"
#include "nc_executor.hpp"
#include "temp_dir.hpp"
#include "test_paths.hpp"
#include "text_file.hpp"

using namespace ncpost::test;

namespace {

/// `text` with every `from` replaced by `to` (REQUIREs at least one).
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  std::size_t n = 0;
  for (std::size_t at = 0; (at = text.find(from, at)) != std::string::npos; at += to.size(), ++n)
    text.replace(at, from.size(), to);
  REQUIRE(n > 0);
  return text;
}

struct Run {
  int exit_code = -1;
  std::string program, log;
};

Run post_golden_sample(const std::string& dialect_path, const std::string& extra, const std::string& name) {
  const std::string dir = make_temp_dir("verify_read_back");
  Run r;
  const std::string out = dir + "/" + name + ".nc", log = dir + "/" + name + ".log";
  r.exit_code = run_ncpost("post --machine " + source("machines/ac-trunnion.toml") +
                               " --workpiece-origin 0,0,80 --verify --dialect " + dialect_path + " " + extra + " -o " +
                               out + " " + data("golden/sample.apt"),
                           log);
  r.program = read_text_file(out);
  r.log = read_text_file(log);
  return r;
}

}  // namespace

TEST_CASE("--verify passes the shipped dialect's program and reads its arcs back", "[verify]") {
  const Run r = post_golden_sample(source("postproc/dialects/fanuc.toml"), "", "fanuc");
  INFO(r.log);
  REQUIRE(r.exit_code == 0);
  // the program has a counter-clockwise arc about the CL circle (checked independently here):
  // the executor runs the written G3 and every point stays on the circle of radius 20 about Z
  const Executor ex(source("machines/ac-trunnion.toml"), ExecJob{V3(0, 0, 80), 0.0}, r.program);
  int arcs = 0;
  for (const ExecBlock& b : ex.blocks) {
    if (b.kind != ExecBlock::Kind::arc_ccw && b.kind != ExecBlock::Kind::arc_cw) continue;
    ++arcs;
    for (int i = 0; i <= 20; ++i) {
      const V3 p = ex.at(b, i / 20.0).tip_W;
      CHECK(std::hypot(p.x(), p.y()) == Approx(20.0).margin(1e-3));
    }
    // a quarter turn from (20, 0) to (0, 20): counter-clockwise, the midpoint at 45 deg
    const V3 mid = ex.at(b, 0.5).tip_W;
    CHECK(mid.x() == Approx(20.0 / std::sqrt(2.0)).margin(1e-3));
    CHECK(mid.y() == Approx(20.0 / std::sqrt(2.0)).margin(1e-3));
  }
  CHECK(arcs >= 1);
}

TEST_CASE("--verify refuses a program whose dialect writes the arcs the wrong way round", "[verify]") {
  const std::string dir = make_temp_dir("verify_read_back_dialect");
  std::string fanuc = read_text_file(source("postproc/dialects/fanuc.toml"));
  fanuc = replaced(fanuc, "counter_clockwise = \"G3\"", "counter_clockwise = \"G2_\"");
  fanuc = replaced(fanuc, "\nclockwise = \"G2\"", "\nclockwise = \"G3\"");
  fanuc = replaced(fanuc, "counter_clockwise = \"G2_\"", "counter_clockwise = \"G2\"");
  const std::string swapped = write_text_file(dir + "/fanuc_swapped.toml", fanuc);
  const Run r = post_golden_sample(swapped, "", "swapped");
  INFO(r.log);
  CHECK(r.exit_code == 5);
  CHECK(r.program.empty());  // no program written
  CHECK(r.log.find("turns the arc clockwise: the CL circle runs counter-clockwise") != std::string::npos);
  // without --verify the program is written as the dialect says (the user asked for no check)
}

TEST_CASE("--verify refuses a feed word written per minute by a dialect whose inverse-time word is wrong", "[verify]") {
  // a dialect whose inverse-time mode word is the per-minute word: every G93 number would run as mm/min
  const std::string dir = make_temp_dir("verify_read_back_feed");
  std::string fanuc = read_text_file(source("postproc/dialects/fanuc.toml"));
  fanuc = replaced(fanuc, "inverse_time = \"G93\"", "inverse_time = \"G94\"");
  const std::string wrong = write_text_file(dir + "/fanuc_g94.toml", fanuc);
  const Run r = post_golden_sample(wrong, "", "g94");
  INFO(r.log);
  CHECK(r.exit_code == 5);
  CHECK(r.program.empty());
  CHECK(r.log.find("runs per minute, the block needs inverse time") != std::string::npos);
}
