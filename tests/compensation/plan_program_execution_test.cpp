// SPDX-License-Identifier: Apache-2.0
// The programs `plan` writes, executed (issue 14 item 14): each block of the written program is
// parsed and its straight line in axis space followed through the nominal forward kinematics.
// With the instrument mounted (between "M0 (mount" and "M0 (... remove") every move is a
// measuring move: the ballbar keeps its length (±0.011 mm: the guide tolerance and rounding), the
// probe stylus never comes nearer the sphere centre than the clearance except along the probe axis
// with the rotary axes still, and every row of the plan is read at its planned pose.
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>
#include <string>

#include "ncpost/compensation/plans.hpp"
#include "ncpost/kinematics/forward.hpp"
#include "ncpost/machines/machine_file.hpp"

using namespace ncpost;
using namespace ncpost::comp;

namespace {

const std::string kMachines = std::string(NCPOST_SOURCE_DIR) + "/machines/";

struct Execution {
  int sets_mounted = 0;
  int reads = 0;              ///< G4 (static) or G1 (continuous) blocks with the instrument on
  int reads_off_plan = 0;     ///< G4 reads not at their row's pose
  int violations = 0;         ///< samples breaking the instrument's rule
  double worst_bar_mm = 0.0;  ///< largest change of the ballbar length
  double nearest_turn_mm = 1e9;  ///< nearest the stylus came to the sphere centre while a rotary axis moved
  double worst_off_line_mm = 0.0;  ///< farthest off the probe axis line while moving with the rotary axes still
  bool moved_after_last_stop = false;
};

/// Executes `program` for `plans` on `m`: sets in order, one per mount.
Execution execute(const Machine& m, const std::vector<NamedPlan>& plans, const std::string& program, bool continuous,
                  double clearance_mm) {
  Execution ex;
  std::istringstream in(program);
  std::string line;
  AxisPosition q;
  bool mounted = false, stopped_once = false;
  std::size_t read_in_set = 0;
  const NamedPlan* plan = nullptr;
  while (std::getline(in, line)) {
    const auto paren = line.find('(');
    const std::string comment = paren == std::string::npos ? "" : line.substr(paren);
    const std::string code = line.substr(0, paren);
    std::istringstream words(code);
    std::string w;
    AxisPosition next = q;
    bool motion = false, dwell = false, m0 = false, g1 = false;
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
        AxisPosition p;
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
            ex.violations += off > 1e-4 || along < -1e-4;  // 1e-4: the program rounds to 1e-5
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
  BallbarPlanOptions o;
  o.heights_mm = {250.0, 300.0};
  const auto plans = plan_ballbar_4axis(m, o);
  const std::string program = plan_program(m, plans, "test", true);
  const Execution ex = execute(m, plans, program, true, 0.0);
  CHECK(ex.sets_mounted == 2);
  CHECK(ex.reads == static_cast<int>(rows_of(plans) - plans.size()));  // the first row is the start
  CHECK(ex.violations == 0);
  CHECK(ex.worst_bar_mm < 0.002);
  // the Z300 C0 set-up move of the second set comes after the stop of the first
  const auto stop = program.find("M0 (stop recording, remove the instrument)");
  const auto setup_move = program.find("G94 G0 X0.00000 Y0.00000 Z300.00000 A0.00000 C0.00000");
  REQUIRE(stop != std::string::npos);
  REQUIRE(setup_move != std::string::npos);
  CHECK(stop < setup_move);
}

TEST_CASE("bc-head program: turns between readings hold the tool ball") {
  const Machine m = load_machine(kMachines + "gantry-bc-head.toml");
  const auto plans = plan_bc_head(m, {});
  const std::string program = plan_program(m, plans, "test", false);
  const Execution ex = execute(m, plans, program, false, 0.0);
  CHECK(ex.sets_mounted == static_cast<int>(plans.size()));
  CHECK(ex.reads == static_cast<int>(rows_of(plans)));
  CHECK(ex.reads_off_plan == 0);
  CHECK(ex.violations == 0);
  CHECK(ex.worst_bar_mm <= 0.011);
  CHECK(ex.worst_bar_mm > 0.0);  // the guided turns do deviate, within the tolerance
}

TEST_CASE("sphere program: retract along the probe axis, turn at the clearance, approach along the axis") {
  for (const char* name : {"ac-trunnion", "haas-umc750", "gantry-bc-head"}) {
    INFO(name);
    const Machine m = load_machine(kMachines + name + ".toml");
    const auto plans = plan_sphere(m, {});
    PlanProgramOptions o;
    o.clearance_mm = 30.0;
    const std::string program = plan_program(m, plans, "test", o);
    const Execution ex = execute(m, plans, program, false, o.clearance_mm);
    CHECK(ex.sets_mounted == 1);
    CHECK(ex.reads == static_cast<int>(rows_of(plans)));
    CHECK(ex.reads_off_plan == 0);
    CHECK(ex.violations == 0);
    CHECK(ex.nearest_turn_mm >= 30.0);
    CHECK(ex.nearest_turn_mm < 30.5 + 1e-9);  // retracted to clearance + turn tolerance
    CHECK(ex.worst_off_line_mm < 1e-4);
    CHECK_FALSE(ex.moved_after_last_stop);
  }
}
