// SPDX-License-Identifier: Apache-2.0
// A Klartext program re-posted (post_request.hpp, the input detected by its BEGIN PGM): on the
// same machine and set-up, a machine-axis Klartext program must come out as the same machine
// positions in the output dialect. Expected positions are the Klartext words themselves, worked
// out by hand from the TNC's rules (FMAX only for its block, incremental IY, the held first rapid
// taking the first X Y, the arc about CC as G3 with I J from the start to the centre).
#include <catch2/catch.hpp>

#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "shipped_machines.hpp"
#include "vmcl600_setup.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/read/cl_input.hpp"
#include "ncpost/postproc/write/dialect.hpp"
#include "ncpost/postproc/machine/serial_post_machine.hpp"
#include "ncpost/postproc/post_request.hpp"
#include "test_paths.hpp"

using namespace ncpost;

namespace {

using Position = std::array<double, 5>;  ///< X Y Z A C (mm, deg)

struct Written {
  std::vector<Position> positions;  ///< after each block with an axis word
  std::vector<std::string> blocks;  ///< those blocks
};

/// The modal machine positions a Fanuc-style program reaches, block by block.
Written positions_of(const std::string& program) {
  Written w;
  Position p{};
  std::istringstream in(program);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '(' || line[0] == '%' || line[0] == 'O') continue;
    if (line.find("G91") != std::string::npos) break;  // the dialect's closing retract (G91 G28 Z0)
    bool moved = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
      const char c = line[i];
      const std::string letters = "XYZAC";
      const std::size_t slot = letters.find(c);
      if (slot == std::string::npos || (i > 0 && std::isalpha(static_cast<unsigned char>(line[i - 1])))) continue;
      p[slot] = std::strtod(line.c_str() + i + 1, nullptr);
      moved = true;
    }
    if (moved) {
      w.positions.push_back(p);
      w.blocks.push_back(line);
    }
  }
  return w;
}

bool same(const Position& a, const Position& b) {
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::abs(a[i] - b[i]) > 1.5e-4) return false;
  return true;
}

std::vector<Position> deduplicated(const std::vector<Position>& ps) {
  std::vector<Position> out;
  for (const auto& p : ps)
    if (out.empty() || !same(out.back(), p)) out.push_back(p);
  return out;
}

std::string post_klartext(const std::string& text, const Machine& machine, const Setup& setup) {
  PostRequest r;
  r.machine = serial_post_machine(machine);
  r.setup = setup;
  r.dialect = dialect_named("fanuc");
  r.threads = 1;
  r.input_name = "repost.h";
  std::istringstream in(text);
  std::ostringstream out;
  post(in, out, r);
  return out.str();
}

}  // namespace

TEST_CASE("klartext re-post: a three-axis program on the VMCL600 keeps its machine positions and its arc") {
  const std::string text =
      "0 BEGIN PGM REPOST MM\n"
      "1 TOOL CALL 3 Z S6000\n"
      "2 L Z+20 R0 FMAX M3\n"
      "3 L X-20 Y-10 FMAX\n"
      "4 L Z-5 F300 M8\n"
      "5 L X+40 F600\n"
      "6 L IY+30\n"
      "7 CC X+40 Y+40\n"
      "8 C X+60 Y+40 DR+\n"
      "9 L Z+20 FMAX M9\n"
      "10 L X+0 Y+0 FMAX M5\n"
      "11 M30\n"
      "12 END PGM REPOST MM\n";
  const std::string nc =
      post_klartext(text, load_machine(test::source("machines/vmcl600.toml")), test::vmcl600_setup());
  INFO(nc);
  const Written w = positions_of(nc);
  const std::vector<Position> expected = {
      {-20, -10, 20, 0, 0},  // block 2, held: X Y from block 3
      {-20, -10, -5, 0, 0}, {40, -10, -5, 0, 0},
      {40, 20, -5, 0, 0},   {60, 40, -5, 0, 0},  // the quarter circle about (40, 40)
      {60, 40, 20, 0, 0},   {0, 0, 20, 0, 0},
  };
  const auto got = deduplicated(w.positions);
  REQUIRE(got.size() == expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    INFO("position " << i);
    CHECK(same(got[i], expected[i]));
  }
  // the arc: counter-clockwise (G3), the centre 20 mm along +Y from its start (40, 20)
  bool arc = false;
  for (const auto& b : w.blocks)
    if (b.find("G3") != std::string::npos) {
      arc = true;
      CHECK(b.find("I0.0000") != std::string::npos);
      CHECK(b.find("J20.0000") != std::string::npos);
    }
  CHECK(arc);
  CHECK(nc.find("T3 M6") != std::string::npos);
  CHECK(nc.find("S6000 M3") != std::string::npos);
}

TEST_CASE("klartext re-post: a five-axis machine-axis program on the AC trunnion ends every block where it did") {
  const std::string text =
      "0 BEGIN PGM TRUN MM\n"
      "1 TOOL CALL 1 Z S2000\n"
      "2 L X+0 Y+0 Z+100 A+0 C+0 R0 FMAX M3\n"
      "3 L X+10 Y+20 Z+50 FMAX\n"
      "4 L Z+30 F200\n"
      "5 L X+20 A+10 C+15 F400\n"
      "6 L Y+0 A+5\n"
      "7 L Z+100 FMAX M5\n"
      "8 END PGM TRUN MM\n";
  Setup setup;
  setup.workpiece_origin_mm = Vec3d(0, 0, 80);
  const std::string nc = post_klartext(text, test::ac_trunnion(), setup);
  INFO(nc);
  const auto got = deduplicated(positions_of(nc).positions);
  const std::vector<Position> ends = {{0, 0, 100, 0, 0},    {10, 20, 50, 0, 0}, {10, 20, 30, 0, 0},
                                      {20, 20, 30, 10, 15}, {20, 0, 30, 5, 15}, {20, 0, 100, 5, 15}};
  // every block end, in order (the tolerance may add points between them)
  std::size_t at = 0;
  for (const auto& p : got)
    if (at < ends.size() && same(p, ends[at])) ++at;
  CHECK(at == ends.size());
  CHECK(same(got.back(), ends.back()));
  CHECK(same(got.front(), ends.front()));
}

TEST_CASE("klartext re-post: CYCL DEF 200 becomes G83 with the planes of its Q parameters") {
  const std::string text =
      "0 BEGIN PGM DRILL MM\n"
      "1 TOOL CALL 4 Z S2000\n"
      "2 L X+0 Y+0 Z+50 R0 FMAX M3\n"
      "3 CYCL DEF 200 DRILLING ~\n"
      "  Q200=+2 ;SET-UP CLEARANCE ~\n"
      "  Q201=-15 ;DEPTH ~\n"
      "  Q206=+150 ;FEED RATE FOR PLNGNG ~\n"
      "  Q202=+5 ;PLUNGING DEPTH ~\n"
      "  Q210=+0 ;DWELL TIME AT TOP ~\n"
      "  Q203=+1 ;SURFACE COORDINATE ~\n"
      "  Q204=+20 ;2ND SET-UP CLEARANCE\n"
      "4 L X+30 Y+20 R0 FMAX M99\n"
      "5 L Z+50 FMAX M5\n"
      "6 END PGM DRILL MM\n";
  const std::string nc =
      post_klartext(text, load_machine(test::source("machines/vmcl600.toml")), test::vmcl600_setup());
  INFO(nc);
  // the surface Z1: the R plane 2 above it (R3), the bottom 15 below it (Z-14), pecks of 5
  const Written w = positions_of(nc);
  int holes = 0;
  for (const auto& b : w.blocks)
    if (b.find("G83") != std::string::npos) {
      ++holes;
      for (const char* word : {"X30.0000", "Y20.0000", "Z-14.0000", "R3.0000", "Q5.0000", "F150.0"}) {
        INFO(word);
        CHECK(b.find(word) != std::string::npos);
      }
    }
  CHECK(holes == 1);
  REQUIRE_FALSE(w.positions.empty());
  CHECK(same(w.positions.back(), Position{30, 20, 50, 0, 0}));
}

TEST_CASE("klartext input: detected by its BEGIN PGM, or named with --input-kind klartext") {
  CHECK(input_kind_named("klartext") == InputKind::klartext);
  const std::string text = "0 BEGIN PGM D MM\n1 L X+1 Y+2 Z+3 A+0 C+0 R0 FMAX\n2 END PGM D MM\n";
  for (InputKind kind : {InputKind::automatic, InputKind::klartext}) {
    std::istringstream in(text);
    auto reader = open_cl_reader(in, "d.h", kind, cl::ReaderOptions{}, test::ac_trunnion(), Setup{});
    std::optional<cl::Record> r = reader->next();
    while (r && !std::holds_alternative<cl::Motion>(*r)) r = reader->next();
    REQUIRE(r);
    CHECK((std::get<cl::Motion>(*r).point.tip_mm - Vec3d(1, 2, 3)).norm() < 1e-12);
  }
  // forced to G-code: refused, naming the kind that reads it
  std::istringstream in(text);
  try {
    open_cl_reader(in, "d.h", InputKind::machine, cl::ReaderOptions{}, test::ac_trunnion(), Setup{});
    FAIL("a Klartext program read as G-code");
  } catch (const InputError& e) {
    CHECK_THAT(e.what(),
               Catch::Contains("d.h:1: a Heidenhain Klartext program") && Catch::Contains("--input-kind klartext"));
  }
}
