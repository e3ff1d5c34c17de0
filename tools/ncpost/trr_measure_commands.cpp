// SPDX-License-Identifier: Apache-2.0
// `plan`, `simulate` and `identify` on the TRR-XY machine (sphere probing, trr_identify.hpp).
#include <fmt/format.h>

#include <random>

#include "ncpost/compensation/trr_model.hpp"
#include "ncpost/compensation/trr_probing_csv.hpp"
#include "ncpost/machines/trr_xy_file.hpp"
#include "ncpost/postproc/atomic_file.hpp"
#include "ncpost/postproc/nc_writer.hpp"
#include "trr_commands.hpp"

namespace ncpost::cli {

std::optional<int> plan_if_trr_xy(const std::string& machine, const std::string& test, const std::string& output) {
  if (machine_file_kind(machine) != "trr-xy") return std::nullopt;
  if (test != "sphere") throw UsageError(fmt::format("plan {}: the TRR-XY machine has the sphere-probing plan only", test));
  const trr::Machine m = load_trr_xy_machine(machine);
  trr::ProbingData plan;
  plan.metadata["machine"] = m.name;
  plan.metadata["probe"] = "sphere centre deviation; stylus = extra length beyond the tool (mm)";
  const std::vector<trr::Command> poses = trr::probing_commands(m);
  double t = 0.0;
  for (double stylus : {0.0, 100.0})
    for (const trr::Command& c : poses) {
      plan.rows.push_back({t, c, stylus, Vec3d::Zero()});
      t += 10.0;
    }
  std::string stem = output;
  if (stem.size() > 4 && stem.substr(stem.size() - 4) == ".csv") stem.resize(stem.size() - 4);
  write_file_atomically(stem + ".csv", trr::format_probing_csv(plan, true));
  AtomicFile nc(stem + ".nc");
  NcWriter w(nc, dialect_named("fanuc"), "XYUVW");
  w.begin_program("TRRPROBE", {"ncpost plan sphere on " + m.name + ": probe the sphere at each pose (stylus 0, then 100 mm)"});
  for (std::size_t i = 0; i < plan.rows.size(); ++i) {
    if (i == poses.size()) w.comment("change the stylus: 100 mm");
    NcMotion mo;
    mo.rapid = true;
    const auto v = plan.rows[i].command.words();
    for (int k = 0; k < 5; ++k) mo.values[static_cast<std::size_t>(k)] = v[k];
    w.motion(mo);
    w.block("M0");
  }
  w.end_program();
  nc.commit();
  fmt::print("plan sphere: {} rows -> {}.csv\nNC program -> {}.nc\n", plan.rows.size(), stem, stem);
  return 0;
}

std::optional<int> simulate_if_trr_xy(const std::string& machine, const std::string& model, const std::string& plan_path,
                                      const std::string& output, double noise_um, std::uint64_t seed,
                                      bool force_model) {
  if (machine_file_kind(machine) != "trr-xy") return std::nullopt;
  const trr::Machine m = load_trr_xy_machine(machine);
  const trr::Errors e = read_trr_model(model, m.name, force_model);
  std::optional<trr::Kinematics> truth;
  try {
    truth.emplace(m, e);
  } catch (const std::runtime_error& ex) {
    throw Infeasible(ex.what());
  }
  const trr::Kinematics nominal(m);
  trr::ProbingData data = trr::read_probing_csv(plan_path, true);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, noise_um / 1000.0);
  for (trr::ProbingRow& r : data.rows) {
    const auto d = trr::predicted_deviation(*truth, nominal, r.command.slider_mm, r.stylus_mm);
    if (!d) throw Infeasible(fmt::format("{}: a pose cannot be solved on the simulated machine", plan_path));
    r.deviation_mm = *d;
    if (noise_um > 0)
      for (int c = 0; c < 3; ++c) r.deviation_mm[c] += noise(rng);
  }
  write_file_atomically(output, trr::format_probing_csv(data, false));
  fmt::print("simulated {} rows of sphere probing on '{}' (noise {} µm) -> {}\n", data.rows.size(), m.name, noise_um,
             output);
  return 0;
}

std::optional<int> identify_if_trr_xy(const std::string& machine, const std::vector<std::string>& data_files,
                                      const std::string& output, const std::string& other_options) {
  if (machine_file_kind(machine) != "trr-xy") return std::nullopt;
  if (!other_options.empty())
    throw UsageError(fmt::format("{}: not available for the TRR-XY machine (its 30 parameters are always fitted)",
                                 other_options));
  const trr::Machine m = load_trr_xy_machine(machine);
  std::vector<trr::ProbeMeasurement> data;
  for (const auto& f : data_files)
    for (const auto& pm : trr::measurements(trr::read_probing_csv(f, false))) data.push_back(pm);
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
  write_file_atomically(output, comp::format_model_json(file));

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
  fmt::print("model -> {}\n", output);
  return 0;
}

}  // namespace ncpost::cli
