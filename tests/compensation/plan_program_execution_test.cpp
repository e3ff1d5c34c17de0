// SPDX-License-Identifier: Apache-2.0
// The programs `plan` writes, executed (issue 14 item 14): each block of the written program is
// parsed and its straight line in axis space followed through the nominal forward kinematics.
// With the instrument mounted (between "M0 (mount" and "M0 (... remove") every move is a
// measuring move: the ballbar keeps its length (±0.011 mm: the guide tolerance and rounding), the
// probe stylus never comes nearer the sphere centre than the clearance except along the probe axis
// with the rotary axes still, and every row of the plan is read at its planned pose. The programs
// are written by the NC writer (postproc/plan_nc.hpp) in the Fanuc dialect, with 5 decimals (the
// plans' default rounding, 1e-5) and with the stock 4 (the rows rounded to 1e-4 as `ncpost plan`
// does); motion words and axis words are modal in its output.
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>
#include <string>

#include "ncpost/compensation/plans.hpp"
#include "ncpost/kinematics/forward.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/write/plan_nc.hpp"

using namespace ncpost;
using namespace ncpost::comp;

namespace {

const std::string kMachines = std::string(NCPOST_SOURCE_DIR) + "/machines/";

/// Fanuc words with `decimals` for mm and degrees, and the plan rounding that goes with them.
struct Words {
  Dialect dialect;
  CommandRounding rounding;
};
Words fanuc_with(int decimals) {
  Words w{dialect_named("fanuc"), {}};
  w.dialect.linear_decimals = w.dialect.angle_decimals = decimals;
  w.rounding.linear_mm = w.rounding.angle_deg = std::pow(10.0, -decimals);
  return w;
}

std::string text_of(const Machine& m, const PlanProgram& program, const Words& w) {
  return plan_program_text(m, program, w.dialect);
}

struct Execution {
  int sets_mounted = 0;
  int reads = 0;                   ///< G4 (static) or G1 (continuous) blocks with the instrument on
  int reads_off_plan = 0;          ///< G4 reads not at their row's pose
  int violations = 0;              ///< samples breaking the instrument's rule
  double worst_bar_mm = 0.0;       ///< largest change of the ballbar length
  double nearest_turn_mm = 1e9;    ///< nearest the stylus came to the sphere centre while a rotary axis moved
  double worst_off_line_mm = 0.0;  ///< farthest off the probe axis line while moving with the rotary axes still
  bool moved_after_last_stop = false;
};

/// Executes `program` for `plans` on `m`: sets in order, one per mount.
/// `quantum_mm`: what the program's mm words are rounded to. The program ends where the
/// dialect's program end starts (`end_block`: Fanuc M5 M9 G91 G28 Z0 G90 M30, as every posted
/// program; Z goes to its reference with the instrument removed).
Execution execute(const Machine& m, const std::vector<NamedPlan>& plans, const std::string& program, bool continuous,
                  double clearance_mm, double quantum_mm, const std::string& end_block) {
  Execution ex;
  std::istringstream in(program);
  std::string line;
  AxisPosition q = home_of(m);
  bool mounted = false, stopped_once = false;
  bool g1 = false;  // the motion word is modal
  std::size_t read_in_set = 0;
  const NamedPlan* plan = nullptr;
  while (std::getline(in, line) && line != end_block) {
    const auto paren = line.find('(');
    const std::string comment = paren == std::string::npos ? "" : line.substr(paren);
    const std::string code = line.substr(0, paren);
    std::istringstream words(code);
    std::string w;
    AxisPosition next = q;
    bool motion = false, dwell = false, m0 = false;
    while (words >> w) {
      const char c = w[0];
      const double v = w.size() > 1 ? std::atof(w.c_str() + 1) : 0.0;
      if (c == 'G' && (v == 0.0 || v == 1.0)) g1 = v == 1.0;
      if (c == 'G' && v == 4.0) dwell = true;
      if (c == 'M' && v == 0.0) m0 = true;
      const int a = m.index_of(c);
      if (a >= 0 && !dwell) {
        next[a] = m.axes[static_cast<std::size_t>(a)].is_rotary() ? deg_to_rad(v) : v;
        motion = true;
      }
    }
    if (m0) {
      mounted = comment.find("mount the instrument") != std::string::npos;
      if (mounted) {
        plan = &plans[static_cast<std::size_t>(ex.sets_mounted++)];
        read_in_set = 0;
      } else {
        stopped_once = true;
      }
      continue;
    }
    if (motion && stopped_once && !mounted && plan == &plans.back()) ex.moved_after_last_stop = true;
    if (mounted && dwell) {
      ++ex.reads;
      const auto& row = plan->set.rows[read_in_set++];
      for (int a = 0; a < static_cast<int>(m.axes.size()); ++a)
        if (std::abs(row.command[a] - q[a]) > 1e-5) ++ex.reads_off_plan;
    }
    if (mounted && motion) {
      const MeasurementSet& s = plan->set;
      Setup setup;
      setup.tool_length_mm = s.tool_length_mm;
      const bool turning = (next.rotary_rad - q.rotary_rad).norm() > 1e-12;
      for (int k = 0; k <= 20; ++k) {
        AxisPosition p = home_of(m);
        const double f = k / 20.0;
        p.linear_mm = q.linear_mm + f * (next.linear_mm - q.linear_mm);
        p.rotary_rad = q.rotary_rad + f * (next.rotary_rad - q.rotary_rad);
        const ToolPoseT<double> tool = forward(m, p, setup);
        if (s.type == MeasurementType::ballbar) {
          const double change = std::abs((tool.tip_mm - s.table_ball_mm).norm() - s.bar_length_mm);
          ex.worst_bar_mm = std::max(ex.worst_bar_mm, change);
          ex.violations += change > 0.011;
        } else {
          const Vec3d d = tool.tip_mm - s.sphere_mm;
          if (turning) {
            ex.nearest_turn_mm = std::min(ex.nearest_turn_mm, d.norm());
            ex.violations += d.norm() < clearance_mm;
          } else {
            const double along = d.dot(tool.axis);
            const double off = (d - along * tool.axis).norm();
            ex.worst_off_line_mm = std::max(ex.worst_off_line_mm, off);
            // ten times the program's rounding (1e-4 mm for words written to 1e-5)
            ex.violations += off > 10.0 * quantum_mm || along < -10.0 * quantum_mm;
          }
        }
      }
      if (continuous && g1) ++ex.reads;
    }
    if (motion) q = next;
  }
  return ex;
}

std::size_t rows_of(const std::vector<NamedPlan>& plans) {
  std::size_t n = 0;
  for (const auto& p : plans) n += p.set.rows.size();
  return n;
}

}  // namespace

TEST_CASE("ballbar-4axis program: the bar keeps its length while mounted; set-up moves only after the stop") {
  const Machine m = load_machine(kMachines + "ac-trunnion.toml");
  const int decimals = GENERATE(5, 4);
  INFO(decimals << " decimals");
  const Words w = fanuc_with(decimals);
  BallbarPlanOptions o;
  o.heights_mm = {250.0, 300.0};
  o.rounding = w.rounding;
  const auto plans = plan_ballbar_4axis(m, o);
  const std::string program = text_of(m, plan_program(m, plans, "test", true), w);
  const Execution ex = execute(m, plans, program, true, 0.0, w.rounding.linear_mm, w.dialect.program_end.front());
  CHECK(ex.sets_mounted == 2);
  CHECK(ex.reads == static_cast<int>(rows_of(plans) - plans.size()));  // the first row is the start
  CHECK(ex.violations == 0);
  CHECK(ex.worst_bar_mm < 0.002);
  // the Z300 set-up move of the second set (the first one is at Z250) comes after the stop of the first
  const auto stop = program.find("M0 (stop recording, remove the instrument)");
  const auto setup_move = program.find(decimals == 5 ? "G0 Z300.00000" : "G0 Z300.0000");
  REQUIRE(stop != std::string::npos);
  REQUIRE(setup_move != std::string::npos);
  CHECK(stop < setup_move);
}

TEST_CASE("bc-head program: turns between readings hold the tool ball") {
  const Machine m = load_machine(kMachines + "gantry-bc-head.toml");
  const int decimals = GENERATE(5, 4);
  INFO(decimals << " decimals");
  const Words w = fanuc_with(decimals);
  BcHeadPlanOptions po;
  po.rounding = w.rounding;
  const auto plans = plan_bc_head(m, po);
  const std::string program = text_of(m, plan_program(m, plans, "test", false), w);
  const Execution ex = execute(m, plans, program, false, 0.0, w.rounding.linear_mm, w.dialect.program_end.front());
  CHECK(ex.sets_mounted == static_cast<int>(plans.size()));
  CHECK(ex.reads == static_cast<int>(rows_of(plans)));
  CHECK(ex.reads_off_plan == 0);
  CHECK(ex.violations == 0);
  CHECK(ex.worst_bar_mm <= 0.011);
  CHECK(ex.worst_bar_mm > 0.0);  // the guided turns do deviate, within the tolerance
}

TEST_CASE("sphere program: retract along the probe axis, turn at the clearance, approach along the axis") {
  const int decimals = GENERATE(5, 4);
  const Words w = fanuc_with(decimals);
  for (const char* name : {"ac-trunnion", "haas-umc750", "gantry-bc-head"}) {
    INFO(name << ", " << decimals << " decimals");
    const Machine m = load_machine(kMachines + name + ".toml");
    SpherePlanOptions po;
    po.rounding = w.rounding;
    const auto plans = plan_sphere(m, po);
    PlanProgramOptions o;
    o.clearance_mm = 30.0;
    const std::string program = text_of(m, plan_program(m, plans, "test", o), w);
    const Execution ex =
        execute(m, plans, program, false, o.clearance_mm, w.rounding.linear_mm, w.dialect.program_end.front());
    CHECK(ex.sets_mounted == 1);
    CHECK(ex.reads == static_cast<int>(rows_of(plans)));
    CHECK(ex.reads_off_plan == 0);
    CHECK(ex.violations == 0);
    CHECK(ex.nearest_turn_mm >= 30.0);
    CHECK(ex.nearest_turn_mm < 30.5 + 1e-9);  // retracted to clearance + turn tolerance
    CHECK(ex.worst_off_line_mm < 10.0 * w.rounding.linear_mm);
    CHECK_FALSE(ex.moved_after_last_stop);
  }
}
