// SPDX-License-Identifier: Apache-2.0
// ncpost plan: measurement plans and the NC programs that run them (README "Worked example").
#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "commands.hpp"
#include "dialect_option.hpp"
#include "file_checks.hpp"
#include "number_checks.hpp"
#include "machine_kind.hpp"
#include "ncpost/postproc/write/atomic_file.hpp"
#include "ncpost/compensation/laser_plan.hpp"
#include "ncpost/compensation/measurement_csv.hpp"
#include "ncpost/compensation/plans.hpp"
#include "ncpost/machines/load.hpp"
#include "ncpost/postproc/write/plan_nc.hpp"

namespace ncpost::cli {

namespace {

Vec3d parse_vec(const std::string& s, const char* option) {
  std::stringstream in(s);
  Vec3d v;
  char c1 = 0, c2 = 0;
  if (!(in >> v.x() >> c1 >> v.y() >> c2 >> v.z()) || c1 != ',' || c2 != ',' || !(in >> std::ws).eof() ||
      !v.allFinite() || v.cwiseAbs().maxCoeff() > 100000.0)
    throw UsageError(fmt::format("{}: expected X,Y,Z in mm, each finite and within +-100000, got '{}'", option, s));
  return v;
}

/// The plan's commands rounded as the dialect writes them: the CSV holds what the control reads.
comp::CommandRounding rounding_of(const Dialect& d) {
  return {std::pow(10.0, -d.linear_decimals), std::pow(10.0, -d.angle_decimals)};
}

/// The plan sets of the test (`program`: how its NC program runs them). Throws
/// std::invalid_argument if the machine does not fit the test.
std::vector<comp::NamedPlan> make_plans(PlanArgs& a, const Machine& m, const comp::CommandRounding& rounding,
                                        comp::PlanProgramOptions& program) {
  if (a.test == "ballbar-4axis") {
    comp::BallbarPlanOptions o;
    if (!a.heights.empty()) o.heights_mm = a.heights;
    if (a.bar_length) o.bar_length_mm = *a.bar_length;
    if (a.dt) o.dt_s = *a.dt;
    if (a.t0) o.t0_s = *a.t0;
    o.points = a.points;
    o.rounding = rounding;
    program.continuous = true;
    return comp::plan_ballbar_4axis(m, o);
  } else if (a.test == "sphere") {
    comp::SpherePlanOptions o;
    if (!a.sphere.empty()) o.sphere_mm = parse_vec(a.sphere, "--sphere");
    if (!a.levels.empty()) o.levels_deg = a.levels;
    if (a.step) o.step_deg = *a.step;
    if (a.dt) o.dt_s = *a.dt;
    if (a.t0) o.t0_s = *a.t0;
    o.rounding = rounding;
    program.clearance_mm = a.clearance_mm;
    return comp::plan_sphere(m, o);
  } else if (a.test == "laser") {
    comp::LaserPlanOptions o = a.laser;
    if (a.dt) o.dt_s = *a.dt;
    if (a.t0) o.t0_s = *a.t0;
    if (!a.tool_lengths.empty()) o.tool_length_mm = a.tool_lengths.front();
    o.rounding = rounding;
    a.laser = o;
    if (const std::string why = o.validate(); !why.empty()) throw UsageError("plan laser: " + why);
    return comp::plan_laser(m, o);
  } else {
    comp::BcHeadPlanOptions o;
    if (!a.tool_lengths.empty()) o.tool_lengths_mm = a.tool_lengths;
    if (a.bar_length) o.bar_length_mm = *a.bar_length;
    if (a.dt) o.dt_s = *a.dt;
    if (a.t0) o.t0_s = *a.t0;
    o.b_test_along_y = !a.seed_directions;
    o.rounding = rounding;
    return comp::plan_bc_head(m, o);
  }
}

}  // namespace

/// The serial machines' plans (plans.hpp, laser_plan.hpp), the program in the chosen dialect.
PlanOutput plan_serial(const PlanArgs& given) {
  PlanArgs a = given;
  const Machine m = machines::load_as<Machine>(a.machine);
  std::vector<comp::NamedPlan> plans;
  comp::PlanProgramOptions program;
  const Dialect dialect = dialect_named(a.dialect);
  try {
    plans = make_plans(a, m, rounding_of(dialect), program);
  } catch (const std::invalid_argument& e) {
    throw Infeasible(fmt::format("plan {} on machine '{}': {}", a.test, m.name, e.what()));
  }
  std::string program_text;  // made before anything is written: a plan that cannot be run writes nothing
  try {
    const comp::PlanProgram records = a.test == "laser"
                                          ? comp::laser_program(m, plans, a.laser)
                                          : comp::plan_program(m, plans, "ncpost plan " + a.test, program);
    program_text = plan_program_text(m, records, dialect);
  } catch (const std::invalid_argument& e) {
    throw Infeasible(fmt::format("plan {} on machine '{}': {}", a.test, m.name, e.what()));
  }
  PlanOutput out;
  for (const auto& p : plans) out.sets.push_back({p.name, comp::format_measurement_csv(p.set, m), p.set.rows.size()});
  out.program = std::move(program_text);
  return out;
}

namespace {

/// The options of `plan` into `a`.
void add_plan_options(CLI::App* sub, const std::shared_ptr<PlanArgs>& a) {
  sub->add_option("--machine", a->machine, "machine definition (TOML)")->required();
  sub->add_option("test", a->test, "ballbar-4axis | sphere | bc-head | laser")
      ->required()
      ->check(CLI::IsMember({"ballbar-4axis", "sphere", "bc-head", "laser"}));
  sub->add_option("-o,--output", a->output, "output: PLAN.csv (one set) or PLAN_<set>.csv (several), and PLAN.nc")
      ->required();
  sub->add_option("--height", a->heights, "ballbar-4axis: height of the balls above the tilt axis (mm), repeatable")
      ->take_all()
      ->check(finite_in(-5000.0, 5000.0, "mm"));
  sub->add_option("--bar-length", a->bar_length, "ballbar length (mm, default 100)")
      ->check(finite_in(0.0, 2000.0, "mm", Bound::open));
  sub->add_option("--points", a->points, "ballbar-4axis: rows per height (default 500)")->check(CLI::Range(2, 1000000));
  sub->add_option("--dt", a->dt, "time between rows (s)")->check(finite_in(0.0, 86400.0, "s", Bound::open));
  sub->add_option("--t0", a->t0, "time stamp of the first row (s, default 0)")->check(finite_in(0.0, 1e9, "s"));
  sub->add_option("--sphere", a->sphere, "sphere: centre X,Y,Z at home (mm, default 120,40,80)");
  sub->add_option("--levels", a->levels, "sphere: levels of the tilt axis (deg)")
      ->delimiter(',')
      ->check(finite_in(-360.0, 360.0, "deg"));
  sub->add_option("--clearance", a->clearance_mm,
                  "sphere: distance of the stylus from the sphere centre while it turns between probing poses "
                  "(mm, default 30)")
      ->check(finite_in(0.0, 1000.0, "mm", Bound::open));
  sub->add_option("--step", a->step, "sphere: step of the swept axis (deg, default 30)")
      ->check(finite_in(0.0, 360.0, "deg", Bound::open));
  sub->add_option(
         "--tool-length", a->tool_lengths,
         "bc-head: tool lengths (mm), repeatable (default 100 and 250); laser: reflector holder length (default 100)")
      ->take_all()
      ->check(finite_in(0.0, 2000.0, "mm"));
  sub->add_flag("--seed-directions", a->seed_directions,
                "bc-head: read the B test along X and Z only, as the published BC-head test (the B-line tilts are then "
                "not seen)");
  sub->add_option("--axes", a->laser.axes, "laser: axes to measure (default XYZ)");
  sub->add_option("--target-step", a->laser.step_mm, "laser: target spacing (mm, default 50)")
      ->check(finite_in(0.0, 10000.0, "mm", Bound::open));
  sub->add_option("--runs", a->laser.runs, "laser: bidirectional runs per line (default 5, ISO 230-2)")
      ->check(CLI::Range(1, 100));
  sub->add_option("--lines", a->laser.lines, "laser: parallel lines per axis, 1..3 (default 3)")
      ->check(CLI::Range(1, 3));
  sub->add_flag(
      "--positioning-only", [a](std::int64_t) { a->laser.straightness = false; },
      "laser: positioning only, no straightness sets");
  sub->add_option(
         "--reflector-offset", a->laser.reflector_offset_mm,
         "laser: reflector offset from the spindle where a line cannot be reached by an axis (mm, default 100)")
      ->check(finite_in(-5000.0, 5000.0, "mm"));
  sub->add_option("--margin", a->laser.margin_mm, "laser: kept clear of each travel end (mm, default 0)")
      ->check(finite_in(0.0, 5000.0, "mm"));
  sub->add_option("--overshoot", a->laser.overshoot_mm, "laser: overshoot before each pass (mm, default 5)")
      ->check(finite_in(0.0, 1000.0, "mm"));
  sub->add_option("--dialect", a->dialect,
                  "The NC program's dialect: fanuc (default), haas, linuxcnc, sinumerik, heidenhain, or the path of a "
                  "dialect file (docs/usage.md \"Dialect files\"); the plan's commands are rounded to its decimals")
      ->type_name("NAME|PATH")
      ->check(dialect_name_or_path());
}

}  // namespace

void add_plan(CLI::App& app, Action& action) {
  auto a = std::make_shared<PlanArgs>();
  CLI::App* sub = app.add_subcommand("plan", "Write measurement plans and the NC programs that run them");
  add_plan_options(sub, a);
  sub->callback([&action, a] {
    action = [a] {
      {  // before anything is computed; the per-set CSV names are checked again once known
        std::string stem = a->output;
        if (stem.size() > 4 && stem.substr(stem.size() - 4) == ".csv") stem.resize(stem.size() - 4);
        check_files({{"-o (program)", stem + ".nc"}, {"-o (plan)", stem + ".csv"}}, {{"--machine", a->machine}});
      }
      const PlanOutput plan = machine_kind(a->machine).plan(*a);
      std::string stem = a->output;
      if (stem.size() > 4 && stem.substr(stem.size() - 4) == ".csv") stem.resize(stem.size() - 4);
      const auto csv_name = [&](const PlanOutput::Set& p) {
        return plan.sets.size() == 1 ? stem + ".csv" : fmt::format("{}_{}.csv", stem, p.name);
      };
      std::vector<NamedPath> outputs{{"-o (program)", stem + ".nc"}};
      for (const auto& p : plan.sets) outputs.push_back({"-o (plan)", csv_name(p)});
      check_files(outputs, {{"--machine", a->machine}});
      for (const auto& p : plan.sets) {
        const std::string file = csv_name(p);
        write_file_atomically(file, p.csv);
        fmt::print("plan {}: {} rows -> {}\n", p.name, p.rows, file);
      }
      write_file_atomically(stem + ".nc", plan.program);
      fmt::print("NC program -> {}.nc\n", stem);
      return 0;
    };
  });
}

}  // namespace ncpost::cli
