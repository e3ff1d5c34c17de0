// SPDX-License-Identifier: Apache-2.0
#pragma once
// Test support for residual analysis (tests/compensation/diagnose_*_test.cpp): data sets made the
// way `ncpost plan` + `ncpost simulate` make them, from a truth the analysis is not told about, and
// the compensated cut: the public dome path posted with an identified model and executed on the
// truth machine.
#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "ncpost/compensation/actual_ik.hpp"
#include "ncpost/compensation/adaptive_subdivision.hpp"
#include "ncpost/compensation/diagnose.hpp"
#include "ncpost/compensation/machine_model.hpp"
#include "ncpost/compensation/model_json.hpp"
#include "ncpost/compensation/nonlinear_compensation.hpp"
#include "ncpost/compensation/plans.hpp"
#include "ncpost/compensation/simulate.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "ncpost/postproc/read/apt/apt_reader.hpp"
#include "ncpost/postproc/write/atomic_file.hpp"
#include "ncpost/postproc/post.hpp"
#include "ncpost/postproc/solve/preview_model_solver.hpp"
#include "nonlinear_test_support.hpp"

namespace ncpost::test {

inline std::string public_scenario(const std::string& name) {
  return std::string(NCPOST_SOURCE_DIR) + "/tests/data/scenarios/" + name + "/";
}
inline Machine public_machine() { return load_machine(public_scenario("public-clean") + "machine.toml"); }

/// The location errors of public-clean's truth.json plus `extra` (the undeclared effect).
inline comp::ErrorParameters truth_with(const Machine& m, const comp::ErrorParameters& extra) {
  comp::ErrorParameters t = comp::read_model_json(public_scenario("public-clean") + "truth.json", &m).parameters;
  for (std::size_t i = 0; i < extra.size(); ++i) t.set(extra.names()[i], extra.values()[i]);
  return t;
}

/// The public scenarios' plan: ballbar-4axis at 250 and 300 mm, then the sphere (t0 619 s).
inline std::vector<comp::MeasurementSet> simulated_sets(const Machine& m, const comp::ErrorParameters& truth,
                                                        double noise_um, std::uint64_t seed) {
  comp::BallbarPlanOptions b;
  b.heights_mm = {250.0, 300.0};
  comp::SpherePlanOptions s;
  s.t0_s = 619.0;
  std::vector<comp::NamedPlan> plans = comp::plan_ballbar_4axis(m, b);
  for (auto& p : comp::plan_sphere(m, s)) plans.push_back(p);
  std::vector<comp::MeasurementSet> sets;
  for (std::size_t i = 0; i < plans.size(); ++i) {
    comp::SimulationOptions o;
    o.noise_um = noise_um;
    o.seed = seed + 7919 * i;
    sets.push_back(comp::simulate(m, plans[i].set, truth, o));
    sets.back().file = plans[i].name;
  }
  return sets;
}

inline comp::DiagnoseResult run_diagnose(const char* title, const Machine& m,
                                         const std::vector<comp::MeasurementSet>& sets) {
  const auto t0 = std::chrono::steady_clock::now();
  comp::DiagnoseResult d = comp::diagnose(m, sets, comp::basic_parameters(m));
  const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("%s: basic rms %.3f max %.3f um -> final rms %.3f max %.3f um (noise from data %.3f um), %.1f s\n", title,
              d.basic.rms_after_um, d.basic.max_after_um, d.final_fit.rms_after_um, d.final_fit.max_after_um,
              d.noise_um, sec);
  for (const auto& e : d.added) {
    std::printf("  + %-16s size %.4g +- %.2g (rms %.3f -> %.3f um, F %.4g, p %.3g)\n", e.candidate.effect.c_str(),
                e.size, e.size_sigma, e.rms_before_um, e.rms_after_um, e.f_statistic, e.p_value);
    for (const auto& q : e.equivalent) std::printf("      (equivalent on these data: %s)\n", q.c_str());
    for (std::size_t i = 0; i < e.values.size(); ++i)
      std::printf("      %-18s %.6g +- %.2g\n", e.values.names()[i].c_str(), e.values.values()[i],
                  e.uncertainty.value_or(e.values.names()[i], 0.0));
  }
  for (const auto& r : d.last_rejected)
    std::printf("  - %-16s rms %.3f um, p %.3g: %s\n", r.effect.c_str(), r.rms_after_um, r.p_value, r.reason.c_str());
  std::printf("  stop: %s\n", d.stop_reason.c_str());
  for (std::size_t i = 0; i < d.final_fit.files.size(); ++i)
    std::printf("  %-20s rms %.3f -> %.3f um, max %.3f -> %.3f um\n", d.final_fit.files[i].file.c_str(),
                d.basic.files[i].rms_after_um, d.final_fit.files[i].rms_after_um, d.basic.files[i].max_after_um,
                d.final_fit.files[i].max_after_um);
  return d;
}

/// Largest tool-tip deviation (um, in W) between two machines (measurement-only effects left
/// out) over the working space of identify_clean_test.cpp (X, Y +-250, Z -150..350 mm, A
/// -10..100 deg, C any; 2000 poses, workpiece origin of job.json); `truth_error_um` gets the
/// largest deviation of the first machine from the nominal.
inline double worst_prediction_um(const Machine& m, const comp::ErrorParameters& truth,
                                  const comp::ErrorParameters& model, double* truth_error_um) {
  const comp::MachineModel actual(m, truth), identified(m, model);
  const Setup setup = dome_setup();
  unsigned state = 12345u;
  auto uniform = [&state](double lo, double hi) {
    state = state * 1664525u + 1013904223u;
    return lo + (hi - lo) * double(state >> 8) / double(1u << 24);
  };
  double worst = 0.0, largest = 0.0;
  for (int k = 0; k < 2000; ++k) {
    AxisPosition q = home_of(m);
    q.linear_mm = Vec3d(uniform(-250, 250), uniform(-250, 250), uniform(-150, 350));
    q.rotary_rad = Eigen::Vector2d(deg_to_rad(uniform(-10, 100)), deg_to_rad(uniform(-360, 360)));
    const auto pt = actual.tool_pose(q, setup);
    worst = std::max(worst, 1e3 * (pt.tip_mm - identified.tool_pose(q, setup).tip_mm).norm());
    largest = std::max(largest, 1e3 * (pt.tip_mm - forward(m, q, setup).tip_mm).norm());
  }
  if (truth_error_um) *truth_error_um = largest;
  return worst;
}

/// Largest tool-tip deviation (um, in W) between two machines at the poses a job uses: every CL
/// point of the APT file `cl_path` solved by the nominal IK (continuity from the previous point),
/// with the set-up `setup`.
inline double worst_prediction_on_path_um(const Machine& m, const comp::ErrorParameters& truth,
                                          const comp::ErrorParameters& model, const std::string& cl_path,
                                          const Setup& setup, std::size_t* poses = nullptr) {
  const comp::MachineModel actual(m, truth), identified(m, model);
  std::ifstream in(cl_path);
  cl::AptReader reader(in, cl_path);
  AxisPosition previous = home_of(m);
  double worst = 0.0;
  std::size_t n = 0;
  while (auto r = reader.next()) {
    const auto* motion = std::get_if<cl::Motion>(&*r);
    if (!motion) continue;
    const IkOutcome ik = solve(m, motion->point, setup, previous);
    if (!ik.ok()) continue;
    previous = *ik.position;
    worst = std::max(
        worst, 1e3 * (actual.tool_pose(previous, setup).tip_mm - identified.tool_pose(previous, setup).tip_mm).norm());
    ++n;
  }
  if (poses) *poses = n;
  return worst;
}

/// Commands from the compensated IK of the identified model, execution on the truth: the post's
/// verification then measures the cut the truth machine makes.
class CompensatedOnTruth final : public KinematicModel {
 public:
  CompensatedOnTruth(const comp::MachineModel& identified, const comp::MachineModel& truth, const Setup& setup)
      : compensated_(identified, setup), truth_(truth), setup_(setup) {}
  IkOutcome solve_quiet(const ClPoint& cl, const AxisPosition& previous, SolverData& data,
                        SolveFigures* figures) const override {
    return compensated_.solve_quiet(cl, previous, data, figures);
  }
  AxisPosition with_rotary(const ClPoint& cl, const RotaryAngles& r, SolverData& data) const override {
    return compensated_.with_rotary(cl, r, data);
  }
  ToolPoseT<double> execute(const AxisPosition& q, const SolverData&) const override {
    return truth_.tool_pose(q, setup_);
  }
  const Machine& machine() const override { return truth_.machine(); }

 private:
  preview::ModelMotionSolver compensated_;
  const comp::MachineModel& truth_;
  Setup setup_;
};

/// `post` of the dome path (public-clean path.cls, job.json set-up) with the identified model:
/// compensated IK and adaptive subdivision to `tolerance_mm` (5 µm unless given) on the identified
/// machine, 4-decimal words;
/// returns the largest contour error of the written program executed on the truth (mm);
/// `endpoint_mm` gets the largest error at block ends (model mismatch and 4-decimal rounding).
inline double compensated_cut_mm(const Machine& m, const comp::ErrorParameters& identified_parameters,
                                 const comp::ErrorParameters& truth_parameters, const std::string& out_path,
                                 double* endpoint_mm = nullptr, double tolerance_mm = 0.005) {
  const comp::MachineModel identified(m, identified_parameters), truth(m, truth_parameters);
  const Setup setup = dome_setup();
  const CompensatedOnTruth solver(identified, truth, setup);
  const preview::ModelMotionSolver on_model(identified, setup);
  const auto errors = identified.errors();
  nonlinear::CompensationOptions comp;
  comp.method = nonlinear::Method::adaptive;
  comp.tolerance_mm = tolerance_mm;
  comp.rounding_allowance_mm = nonlinear::rounding_allowance_mm(4, 4, 200.0);
  PostOptions options;
  options.verify = true;
  options.subdivide = [&](const SolvedPoint& a, const SolvedPoint& b, SolverData& data) {
    auto ik = [&](const ClPoint& cl, const AxisPosition& previous) {
      return on_model.solve_quiet(cl, previous, data, nullptr);
    };
    const nonlinear::SplitBlock split = nonlinear::compensate_block(m, setup, {a.cl, b.cl, a.q, b.q}, errors, ik, comp);
    if (!split.ok()) throw std::runtime_error(split.failure);
    std::vector<SolvedPoint> points;
    for (const auto& node : split.nodes) points.push_back({node.cl, node.q});
    return points;
  };
  std::ifstream in(dome_path());
  cl::AptReader reader(in, "path.cls");
  AtomicFile out(out_path);
  NcWriter writer(out, dialect_named("fanuc"), "XYZAC");
  const PostSummary s = post_program(reader, "path.cls", solver, writer, options);
  out.commit();
  std::printf(
      "  compensated cut on the truth: %zu motions -> %zu blocks, contour error %.4f mm (line %d), block ends "
      "%.4f mm\n",
      s.motions_in, s.blocks_out, s.verify.max_contour_mm, s.verify.worst_line, s.verify.max_endpoint_mm);
  if (endpoint_mm) *endpoint_mm = s.verify.max_endpoint_mm;
  return s.verify.max_contour_mm;
}

/// The same cut with reversal: the commands of each CL point come from the compensated IK with
/// the dead band of the identified model (where the axes actually stand after the previous
/// point), inserted points likewise, and each output block is executed on the truth with its
/// dead band (the actual angle of each axis from where it actually stood). The dome path turns
/// each rotary axis one way only, so the dead-band offset is constant along each block.
inline double compensated_cut_with_reversal_mm(const Machine& m, const comp::ErrorParameters& identified_parameters,
                                               const comp::ErrorParameters& truth_parameters,
                                               double* endpoint_mm = nullptr) {
  const comp::MachineModel identified(m, identified_parameters), truth(m, truth_parameters);
  const Setup s = dome_setup();
  const auto path = read_gotos(dome_path());
  AxisPosition previous = home_of(m);
  std::optional<AxisPosition> actual_identified, actual_truth;
  if (endpoint_mm) *endpoint_mm = 0.0;
  nonlinear::AdaptiveOptions o;
  o.tolerance_mm = 0.005;
  double worst = 0.0;
  auto offsets = [](const comp::RowState<double>& st, AxisPosition q) {
    for (int i = 0; i < 5; ++i) q[i] += st.reversal[static_cast<std::size_t>(i)];
    return q;
  };
  for (std::size_t i = 0; i < path.size(); ++i) {
    auto ik = [&](const ClPoint& cl, const AxisPosition& prev) {
      IkOutcome n = solve(m, cl, s, prev);
      if (!n.ok()) return n;
      comp::ActualIkOptions ao;
      ao.previous_actual = actual_identified;
      const comp::ActualIkOutcome a = comp::solve_actual(identified, cl, s, *n.position, ao);
      if (!a.ok())
        n.position.reset();
      else
        n.position = a.position;
      return n;
    };
    const IkOutcome end = ik(path[i].point, previous);
    if (!end.ok()) throw std::runtime_error("compensated IK failed on line " + std::to_string(path[i].line));
    const AxisPosition q = *end.position;
    const comp::RowState<double> st_id = comp::reversal_state(identified, q, actual_identified);
    const comp::RowState<double> st_truth = comp::reversal_state(truth, q, actual_truth);
    if (i > 0 && !path[i].rapid) {
      const nonlinear::ClBlock b{path[i - 1].point, path[i].point, previous, q};
      const nonlinear::SplitBlock split = nonlinear::subdivide_adaptive(m, s, b, identified.errors(st_id), ik, o);
      if (!split.ok()) throw std::runtime_error(split.failure);
      nonlinear::SplitBlock check = split;
      nonlinear::verify_split(m, s, b, check, truth.errors(st_truth));
      worst = std::max(worst, check.max_error_mm);
      if (endpoint_mm)
        *endpoint_mm = std::max(*endpoint_mm, (truth.tool_pose(q, s, st_truth).tip_mm - path[i].point.tip_mm).norm());
    }
    actual_identified = offsets(st_id, q);
    actual_truth = offsets(st_truth, q);
    previous = q;
  }
  std::printf("  compensated cut on the truth with reversal: contour error %.4f mm, block ends %.4f mm\n", worst,
              endpoint_mm ? *endpoint_mm : 0.0);
  return worst;
}

/// Error of the tool tip at the CL points of the dome path (mm, largest): commands from the
/// compensated IK of `model` (with its dead band, if any), executed on the truth (with its dead
/// band) — the block ends of a compensated post, without subdivision or rounding.
inline double compensated_ends_mm(const Machine& m, const comp::ErrorParameters& model_parameters,
                                  const comp::ErrorParameters& truth_parameters) {
  const comp::MachineModel model(m, model_parameters), truth(m, truth_parameters);
  const Setup s = dome_setup();
  AxisPosition previous = home_of(m);
  std::optional<AxisPosition> actual_model, actual_truth;
  double worst = 0.0;
  auto with_offsets = [](const comp::RowState<double>& st, AxisPosition q) {
    for (int i = 0; i < 5; ++i) q[i] += st.reversal[static_cast<std::size_t>(i)];
    return q;
  };
  for (const ClLine& p : read_gotos(dome_path())) {
    const IkOutcome n = solve(m, p.point, s, previous);
    if (!n.ok()) throw std::runtime_error("IK failed on line " + std::to_string(p.line));
    comp::ActualIkOptions o;
    o.previous_actual = actual_model;
    const comp::ActualIkOutcome a = comp::solve_actual(model, p.point, s, *n.position, o);
    if (!a.ok()) throw std::runtime_error("compensated IK failed on line " + std::to_string(p.line));
    const AxisPosition q = *a.position;
    const comp::RowState<double> st_truth = comp::reversal_state(truth, q, actual_truth);
    worst = std::max(worst, (truth.tool_pose(q, s, st_truth).tip_mm - p.point.tip_mm).norm());
    actual_model = with_offsets(comp::reversal_state(model, q, actual_model), q);
    actual_truth = with_offsets(st_truth, q);
    previous = q;
  }
  return worst;
}

}  // namespace ncpost::test
