// SPDX-License-Identifier: Apache-2.0
// The sweep of issue 27: every shipped serial machine, with and without RTCP, in each ISO dialect,
// posts a tilted drilled hole, a tilted cut with a rapid retract along its axis, two tools with CL
// lengths, and a G93 move; each written program is executed with the tests' own executor
// (nc_executor.hpp) and checked against what the CL data mean:
//  - every feed block within the header's tolerance (0.01 mm) of its CL segment (RTCP: the tip
//    runs straight), every G93 F = CL feed / executed tip path, every G94 F the CL feed;
//  - every rapid sample inside the hole's (retract's) cylinder on its axis line;
// or the run is refused with a message naming the input line (the three-axis machine for a tilted
// tool; a CL tool length other than the solved one on a head without RTCP). Nothing else.
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "cli_run.hpp"
#include "nc_executor.hpp"
#include "temp_dir.hpp"
#include "test_paths.hpp"
#include "text_file.hpp"

using namespace ncpost::test;

namespace {

std::string goto_of(const V3& tip, const V3& axis) {
  const V3 u = axis.normalized();
  return fmt::format("GOTO/{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f}\n", tip.x(), tip.y(), tip.z(), u.x(), u.y(),
                     u.z());
}

/// A CL feed segment and its feed.
struct Segment {
  V3 a, b;
  double feed = 0.0;
};

/// One case: the CL text, its feed segments, the line whose rapids must stay on (top, axis)
/// inside the cylinder from `depth` below to `clear` above, and whether it tilts the tool.
struct Case {
  std::string name, cl;
  std::vector<Segment> feeds;
  V3 top = V3::Zero(), axis = V3::UnitZ();
  double depth = 0.0, clear = 0.0;
  bool lengths_differ = false;
};

std::vector<Case> cases() {
  const double t = 20.0 * M_PI / 180.0;
  const V3 u(std::sin(t), 0, std::cos(t));
  std::vector<Case> out;
  {  // a drilled hole 20 deg off Z: R plane 3 above the top, 12 deep
    Case c{"tilted drill", "UNITS/MM\nMULTAX/ON\nLOADTL/2\nSPINDL/RPM,1500,CLW\nRAPID\n" +
                               goto_of(V3(10, 0, 0) + 50 * u, u) + "CYCLE/DRILL,RAPTO,3,FEDTO,-12,MMPM,120\n" +
                               goto_of(V3(10, 0, 0), u) + "CYCLE/OFF\nFINI\n"};
    c.feeds = {{V3(10, 0, 0) + 3 * u, V3(10, 0, 0) - 12 * u, 120}};
    c.top = V3(10, 0, 0), c.axis = u, c.depth = 12, c.clear = 3;
    out.push_back(c);
  }
  {  // a cut along X with the tool 20 deg off Z, then a rapid 50 mm out along the axis
    Case c{"tilted retract", "UNITS/MM\nMULTAX/ON\nLOADTL/1\nRAPID\n" + goto_of(V3(-20, 0, 0) + 60 * u, u) +
                                 "FEDRAT/MMPM,500\n" + goto_of(V3(-20, 0, 0), u) + goto_of(V3(0, 0, 0), u) + "RAPID\n" +
                                 goto_of(50 * u, u) + "FINI\n"};
    c.feeds = {{V3(-20, 0, 0) + 60 * u, V3(-20, 0, 0), 500}, {V3(-20, 0, 0), V3(0, 0, 0), 500}};
    c.axis = u, c.depth = 0, c.clear = 50;
    out.push_back(c);
  }
  {  // two tools with CL lengths 100 and 150 (the post solves for 100)
    const std::string cut = "RAPID\n" + goto_of(V3(0, 0, 0) + 40 * u, u) + "FEDRAT/MMPM,300\n" +
                            goto_of(V3(0, 0, 0), u) + "RAPID\n" + goto_of(40 * u, u);
    Case c{"tool lengths",
           "UNITS/MM\nMULTAX/ON\nLOADTL/1,LENGTH,100\n" + cut + "LOADTL/2,LENGTH,150\n" + cut + "FINI\n"};
    c.feeds = {{40 * u, V3(0, 0, 0), 300}};
    c.axis = u, c.depth = 0, c.clear = 40;
    c.lengths_differ = true;
    out.push_back(c);
  }
  {  // G93: the tip moves 10 mm along X while the tool turns 10 -> 40 deg in XZ
    const double a0 = 10 * M_PI / 180, a1 = 40 * M_PI / 180;
    const V3 u0(std::sin(a0), 0, std::cos(a0)), u1(std::sin(a1), 0, std::cos(a1));
    Case c{"G93 move", "UNITS/MM\nMULTAX/ON\nLOADTL/1\nRAPID\n" + goto_of(V3(0, 0, 30), u0) + "FEDRAT/MMPM,500\n" +
                           goto_of(V3(0, 0, 0), u0) + goto_of(V3(10, 0, 0), u1) + "FINI\n"};
    c.feeds = {{V3(0, 0, 30), V3(0, 0, 0), 500}, {V3(0, 0, 0), V3(10, 0, 0), 500}};
    c.axis = u0, c.depth = 0, c.clear = 0;
    out.push_back(c);
  }
  return out;
}

struct Machine {
  const char* name;
  V3 origin;
  bool head = false;  ///< rotary axes in the head (the axis positions depend on the tool length)
  bool tilts = true;  ///< reaches a tool axis tilted in XZ
};

const Machine kMachines[] = {{"ac-trunnion", V3(0, 0, 50)},
                             {"tsutsumi-zxfyac", V3(0, 0, 50)},
                             {"bv100", V3(0, 0, 50)},
                             {"linuxcnc-xyzac-trt", V3(0, 0, 50)},
                             {"haas-umc750", V3(0, 0, 50)},
                             {"hmc-b-table", V3(0, 0, 50)},
                             {"gantry-bc-head", V3(0, 0, -300), true},
                             {"vmcl600", V3(0, 0, 50), false, false}};

/// What the executed program does other than the CL data mean (empty: right).
std::string wrong_in(const Executor& ex, const Case& c, bool rtcp) {
  std::string out;
  for (const ExecBlock& b : ex.blocks) {
    if (!b.from_known) continue;
    if (b.kind == ExecBlock::Kind::rapid) {
      if (c.clear <= 0.0) continue;
      for (int i = 0; i <= 200; ++i) {
        const auto [off, along] = from_line(ex.at(b, i / 200.0).tip_W, c.top, c.axis);
        if (along >= -c.depth - 1e-6 && along <= c.clear - 1e-3 && off <= 10.0 && off > 2e-3)
          return fmt::format("line {} '{}': a rapid {:.3f} mm off the axis line inside the cut", b.line, b.text, off);
      }
      continue;
    }
    const V3 mid = ex.at(b, 0.5).tip_W;
    const Segment* on = &c.feeds.front();
    for (const Segment& s : c.feeds)
      if (from_segment(mid, s.a, s.b) < from_segment(mid, on->a, on->b)) on = &s;
    double worst = 0.0;
    for (int i = 0; i <= 50; ++i) worst = std::max(worst, from_segment(ex.at(b, i / 50.0).tip_W, on->a, on->b));
    if (worst > 0.01 + 1e-6) return fmt::format("line {} '{}': {:.4f} mm off the CL path", b.line, b.text, worst);
    const double path = ex.tip_path_mm(b);
    if (b.inverse_time && std::abs(b.feed * path - on->feed) > 2e-4 * on->feed)
      return fmt::format("line {} '{}': G93 F x path = {:.3f}, the CL feed is {}", b.line, b.text, b.feed * path,
                         on->feed);
    if (!b.inverse_time && std::abs(b.feed - on->feed) > 0.05)
      return fmt::format("line {} '{}': F{} where the CL feed is {}", b.line, b.text, b.feed, on->feed);
  }
  (void)rtcp;
  return out;
}

}  // namespace

TEST_CASE("sweep: every machine, RTCP or not, ISO dialects: right, or refused with the reason; never wrong",
          "[post][sweep]") {
  const std::string dir = make_temp_dir("wrong_move_sweep");
  int runs = 0, right = 0, refused = 0, wrong = 0;
  std::string table = "machine              case            rtcp dialect   outcome\n";
  for (const Machine& m : kMachines)
    for (const Case& c : cases())
      for (const bool rtcp : {false, true})
        for (const char* dialect : {"fanuc", "haas", "linuxcnc"}) {
          if (std::string(dialect) != "fanuc" && c.name != "G93 move" && c.name != "tilted drill") continue;
          ++runs;
          const std::string in = write_text_file(dir + "/c.apt", c.cl), out = dir + "/c.nc", log = dir + "/c.log";
          std::remove(out.c_str());
          const int rc = run_ncpost(fmt::format("post --machine {} --workpiece-origin {},{},{} --tool-length 100 "
                                                "--dialect {}{} -o {} {}",
                                                source(std::string("machines/") + m.name + ".toml"), m.origin.x(),
                                                m.origin.y(), m.origin.z(), dialect, rtcp ? " --rtcp" : "", out, in),
                                    log);
          const std::string program = read_text_file(out), messages = read_text_file(log);
          const bool expect_refusal = !m.tilts || (c.lengths_differ && m.head && !rtcp);
          std::string outcome;
          if (rc == 0) {
            const Executor ex(source(std::string("machines/") + m.name + ".toml"), ExecJob{m.origin, 100.0}, program);
            const std::string w = wrong_in(ex, c, rtcp);
            if (w.empty() && !expect_refusal) {
              ++right;
              outcome = "right";
            } else {
              ++wrong;
              outcome = w.empty() ? "posted, should be refused" : "WRONG: " + w;
            }
          } else {
            const bool names_line = messages.find("c.apt:") != std::string::npos;
            if (expect_refusal && names_line && program.empty() && (rc == 2 || rc == 3)) {
              ++refused;
              outcome = fmt::format("refused (exit {})", rc);
            } else {
              ++wrong;
              outcome = fmt::format("unexpected exit {}: {}", rc, messages.substr(0, 300));
            }
          }
          table += fmt::format("{:<20} {:<15} {:<4} {:<9} {}\n", m.name, c.name, rtcp ? "yes" : "no", dialect, outcome);
        }
  table += fmt::format("{} runs: {} right, {} refused with the reason, {} wrong\n", runs, right, refused, wrong);
  std::printf("%s", table.c_str());
  INFO(table);
  CHECK(wrong == 0);
  CHECK(right > 40);
}
