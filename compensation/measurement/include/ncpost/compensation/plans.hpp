// SPDX-License-Identifier: Apache-2.0
#pragma once
// Measurement plans (the tests users run), as measurement sets without values. Commands are the
// nominal ones that put the tool ball / probe on the target (kinematics/inverse.hpp linear_for),
// rounded as the CSV writes them (mm to 1e-5, degrees to 1e-5) so that a plan read back is the
// plan simulated.
//
// ballbar-4axis (seed 000, Tsutsumi & Saito 2003): table-table machine, tilt axis = the rotary
//   axis nearer the bed (A), rotary axis = the one carrying the workpiece (C). Tool ball on the C
//   line at height h (the point of the C line at z = h at home), table ball at bar length from it
//   along −Y at the same height; first half tilt 0→90° with rotary 0→180°, second half tilt 90→0°
//   with rotary 180→360°, `points` rows in all (half each, end points included), dt apart.
// sphere (as Heidenhain KinematicsOpt): probe a table sphere at a grid of rotary positions: the
//   axis parallel to Z at home is swept 0→360°−step and back to 0 (both approach directions) at
//   each level of the other axis (levels outside the limits are skipped).
// bc-head (seed 002, Gao et al.): ballbar with the tool ball at the TCP held at `point`; C test:
//   B = 0, C at 0/90/180°, bar along X and Y; B test: C = 0, B at 0/+90/−90°, bar along X, Y and
//   Z (the seed reads X and Z only: `b_test_along_y = false`; the tilts of the B line then act
//   only at second order); one set per test, direction and tool length. Two tool lengths by
//   default: at one, the offset and the tilt of the C line act alike at the ball.
#include <string>
#include <vector>

#include "ncpost/compensation/measurement.hpp"
#include "ncpost/compensation/plan_program.hpp"

namespace ncpost::comp {

/// The quanta the commands of a plan are rounded to: those of the NC program's words (10^-decimals
/// of its dialect), so that the CSV rows are the values the control reads.
struct CommandRounding {
  double linear_mm = 1e-5;
  double angle_deg = 1e-5;
};

struct BallbarPlanOptions {
  CommandRounding rounding;
  std::vector<double> heights_mm{250.0};
  double bar_length_mm = 100.0;
  int points = 500;     ///< rows per height (both halves)
  double dt_s = 0.5;    ///< time between rows
  double gap_s = 60.0;  ///< time between sets (remounting)
  double t0_s = 0.0;
};

struct SpherePlanOptions {
  CommandRounding rounding;
  Vec3d sphere_mm{120.0, 40.0, 80.0};
  std::vector<double> levels_deg{0, 30, 60, 90, 75, 45, 15};
  double step_deg = 30.0;
  double dt_s = 6.0;
  double t0_s = 0.0;
};

struct BcHeadPlanOptions {
  CommandRounding rounding;
  std::vector<double> tool_lengths_mm{100.0, 250.0};
  double bar_length_mm = 100.0;
  Vec3d point_mm = Vec3d::Zero();  ///< where the tool ball is held (M)
  bool b_test_along_y = true;      ///< false: the seed's directions (B test along X and Z)
  double dt_s = 10.0;
  double gap_s = 60.0;
  double t0_s = 0.0;
};

/// One plan set with a name (used for file names: PREFIX_name.csv).
struct NamedPlan {
  std::string name;
  MeasurementSet set;
};

/// Throws std::invalid_argument if the machine does not fit the test.
std::vector<NamedPlan> plan_ballbar_4axis(const Machine& machine, const BallbarPlanOptions& options);
std::vector<NamedPlan> plan_sphere(const Machine& machine, const SpherePlanOptions& options);
std::vector<NamedPlan> plan_bc_head(const Machine& machine, const BcHeadPlanOptions& options);

struct PlanProgramOptions {
  bool continuous = false;           ///< ballbar-4axis: the rows are one measuring move (G93 G1 through them)
  double clearance_mm = 30.0;        ///< sphere: the stylus stays this far from the centre between probing points
  double guide_tolerance_mm = 0.01;  ///< ballbar: how far a guided turn may change the bar length (plan_moves.hpp)
  double turn_tolerance_mm = 0.5;    ///< sphere: how far a turn at the clearance may leave its target
};

/// The NC program (records for the NC writer, plan_program.hpp) that runs the sets in order. Each
/// set: a set-up rapid to its start (instrument off), a stop to mount the instrument, the
/// measuring moves, a stop to remove it; set-up moves only after that stop. With the instrument on every move is guided
/// (plan_moves.hpp):
///  - continuous sets (ballbar 4-axis): inverse-time moves (G93 G1) through the rows, timed;
///  - static ballbar sets (bc-head): a dwell to read each row, guided turns holding the tool ball
///    (the bar keeps its length within guide_tolerance_mm);
///  - sphere sets: the stylus comes to each probing pose along the probe axis (G1 with the rotary
///    axes still), dwells, retracts along the probe axis to clearance_mm + turn_tolerance_mm from
///    the centre, then turns guided on that distance (never nearer than clearance_mm).
PlanProgram plan_program(const Machine& machine, const std::vector<NamedPlan>& plans, const std::string& title,
                         const PlanProgramOptions& options);
inline PlanProgram plan_program(const Machine& machine, const std::vector<NamedPlan>& plans, const std::string& title,
                                bool continuous) {
  PlanProgramOptions o;
  o.continuous = continuous;
  return plan_program(machine, plans, title, o);
}

}  // namespace ncpost::comp
