// SPDX-License-Identifier: Apache-2.0
// The TRR-XY steps of `plan`, `simulate` and `identify` (sphere probing, trr_identify.hpp;
// kind_steps.hpp).
#include <fmt/format.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <sstream>

#include "kind_steps.hpp"
#include "ncpost/compensation/trr_model.hpp"
#include "ncpost/compensation/trr_probing_csv.hpp"
#include "ncpost/compensation/trr_summary.hpp"
#include "ncpost/machines/load.hpp"
#include "ncpost/postproc/write/plan_nc.hpp"
#include "ncpost/postproc/solve/trr_solver.hpp"
#include "trr_model_input.hpp"

namespace ncpost::cli {

namespace {

/// Stylus lengths of the sphere plan (mm beyond the tool): two, so that identify sees the tool axis.
constexpr double kStylusLengthsMm[] = {0.0, 100.0};
/// Time stamp step between the plan's rows (s).
constexpr double kRowTimeStepS = 10.0;

/// `c` as the control reads it: each word rounded to the dialect's decimals (the CSV holds what the
/// program moves to).
trr::Command as_written(const trr::Command& c, const Dialect& d) {
  const double quantum_mm = std::pow(10.0, -d.linear_decimals);
  Eigen::Matrix<double, 5, 1> w = c.words();
  for (int k = 0; k < 5; ++k) w[k] = std::round(w[k] / quantum_mm) * quantum_mm;
  return trr::Command::from_words(w);
}

/// The program of the sphere plan: per row a rapid to its pose and a program stop (probe the
/// sphere, then resume), the stylus change between the two lengths as a comment.
comp::PlanProgram sphere_program(const trr::Machine& m, const trr::ProbingData& plan, std::size_t poses) {
  comp::PlanProgram p;
  p.name = "TRRPROBE";
  p.header = {"ncpost plan sphere on " + m.name + ": probe the sphere at each pose (stylus 0, then 100 mm)"};
  for (std::size_t i = 0; i < plan.rows.size(); ++i) {
    if (i == poses) p.comment(fmt::format("change the stylus: {:g} mm", plan.rows[i].stylus_mm));
    p.rapid(trr_slots(plan.rows[i].command));
    p.stop("probe the sphere");
  }
  return p;
}

}  // namespace

PlanOutput plan_trr_xy(const PlanArgs& a) {
  if (a.test != "sphere")
    throw UsageError(fmt::format("plan {}: the TRR-XY machine has the sphere-probing plan only", a.test));
  const trr::Machine m = machines::load_as<trr::Machine>(a.machine);
  const Dialect dialect = dialect_named(a.dialect);
  trr::ProbingData plan;
  plan.metadata["machine"] = m.name;
  plan.metadata["probe"] = "sphere centre deviation; stylus = extra length beyond the tool (mm)";
  const std::vector<trr::Command> poses = trr::probing_commands(m);
  double t = 0.0;
  for (double stylus : kStylusLengthsMm)
    for (const trr::Command& c : poses) {
      plan.rows.push_back({t, as_written(c, dialect), stylus, Vec3d::Zero()});
      t += kRowTimeStepS;
    }
  const trr::Kinematics nominal(m);
  const TrrSolver axes(nominal, nominal, Vec3d::Zero());  // the words X Y U V W, all linear
  std::string program;
  try {
    program = plan_program_text(axes.machine(), sphere_program(m, plan, poses.size()), dialect);
  } catch (const std::invalid_argument& e) {
    throw Infeasible(fmt::format("plan {} on machine '{}': {}", a.test, m.name, e.what()));
  }
  return {{{"sphere", trr::format_probing_csv(plan, true), plan.rows.size()}}, std::move(program)};
}

SimulateOutput simulate_trr_xy(const SimulateArgs& a) {
  const trr::Machine m = machines::load_as<trr::Machine>(a.machine);
  const trr::Errors e = read_trr_model(a.model, m.name, a.force_model);
  std::optional<trr::Kinematics> truth;
  try {
    truth.emplace(m, e);
  } catch (const std::runtime_error& ex) {
    throw Infeasible(ex.what());
  }
  const trr::Kinematics nominal(m);
  trr::ProbingData data = trr::read_probing_csv(a.plan, true);
  std::mt19937_64 rng(a.seed);
  std::normal_distribution<double> noise(0.0, a.noise_um / 1000.0);
  for (trr::ProbingRow& r : data.rows) {
    const auto d = trr::predicted_deviation(*truth, nominal, r.command.slider_mm, r.stylus_mm);
    if (!d) throw Infeasible(fmt::format("{}: a pose cannot be solved on the simulated machine", a.plan));
    r.deviation_mm = *d;
    if (a.noise_um > 0)
      for (int c = 0; c < 3; ++c) r.deviation_mm[c] += noise(rng);
  }
  return {trr::format_probing_csv(data, false), fmt::format("simulated {} rows of sphere probing on '{}' (noise {} µm)",
                                                            data.rows.size(), m.name, a.noise_um)};
}

IdentifyOutput identify_trr_xy(const IdentifyArgs& a) {
  const std::string serial_only = !a.params.empty() ? "--params" : !a.fixed.empty() ? "--fixed" : "";
  if (!serial_only.empty())
    throw UsageError(
        fmt::format("{}: not available for the TRR-XY machine (its 30 parameters are always fitted)", serial_only));
  const trr::Machine m = machines::load_as<trr::Machine>(a.machine);
  std::vector<trr::ProbeMeasurement> data;
  trr::TrrReportInputs report{a.machine, a.output, a.report, a.data, {}};
  for (const auto& f : a.data) {
    report.data.push_back(trr::read_probing_csv(f, false));
    for (const auto& pm : trr::measurements(report.data.back())) data.push_back(pm);
  }
  trr::IdentifyResult id;
  try {
    id = trr::identify(m, data);
  } catch (const std::runtime_error& e) {
    throw Infeasible(e.what());
  }
  comp::ModelFile file = trr::model_from_errors(id.errors, m.name);
  file.identifiability = id.identifiability;
  for (int k = 0; k < trr::kParameterCount; ++k)
    if (id.uncertainty[static_cast<std::size_t>(k)] >= 0.0)
      file.uncertainty.set(trr::Errors::name(k), id.uncertainty[static_cast<std::size_t>(k)]);
  comp::FitSummary fit;
  fit.rms_before_um = id.rms_before_um;
  fit.max_before_um = id.max_before_um;
  fit.rms_after_um = id.rms_after_um;
  fit.max_after_um = id.max_after_um;
  file.fit = fit;

  fmt::print("TRR-XY identification from {} probed points: rank {} of {} ({} iterations)\n", data.size(),
             id.identifiability.rank, id.identifiability.parameters, id.iterations);
  fmt::print("residual rms {:.3f} -> {:.3f} µm, max {:.3f} -> {:.3f} µm\n", id.rms_before_um, id.rms_after_um,
             id.max_before_um, id.max_after_um);
  for (int k = 0; k < trr::kParameterCount; ++k) {
    const double sd = id.uncertainty[static_cast<std::size_t>(k)];
    const bool angle = trr::Errors::is_angle(k);
    const double scale = angle ? 1e6 : 1e3;  // µrad, µm
    if (sd < 0.0)
      fmt::print("  {:<6} not determined (null space)\n", trr::Errors::name(k));
    else
      fmt::print("  {:<6} {:>10.3f} ± {:.3f} {}\n", trr::Errors::name(k), id.errors[k] * scale, sd * scale,
                 angle ? "µrad" : "µm");
  }
  fmt::print("directions the data cannot see (weights per unit of effect):\n");
  for (const auto& dir : id.identifiability.null_space) {
    std::string s;
    for (const auto& [name, w] : dir) s += fmt::format(" {}{:+.3f}", name, w);
    fmt::print("  {}\n", s);
  }
  const bool reported = !a.report.empty();
  return {.model_json = comp::format_model_json(file),
          .report_html = reported ? trr::trr_identify_report_html(m, id, report) : std::string(),
          .summary_html =
              reported ? comp::summary_page_html(trr::trr_identification_summary(m, id, report)) : std::string(),
          .closing = fmt::format("model -> {}\n", a.output)};
}

}  // namespace ncpost::cli
