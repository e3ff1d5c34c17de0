// SPDX-License-Identifier: Apache-2.0
// ncpost sensitivity: the TRR-XY sensitivity maps (docs/trr-xy.md).
#include <fmt/format.h>

#include <cmath>

#include "commands.hpp"
#include "file_checks.hpp"
#include "machine_kind.hpp"
#include "number_checks.hpp"
#include "ncpost/compensation/trr_sensitivity.hpp"
#include "ncpost/machines/trr_xy_file.hpp"
#include "ncpost/postproc/write/atomic_file.hpp"
#include "ncpost/postproc/verify/trr_sensitivity_report.hpp"

namespace ncpost::cli {
namespace {

struct SensitivityArgs {
  std::string machine;
  std::string json;
  std::string html;
  double polar_step_deg = 1.0;
  double azimuth_step_deg = 1.0;
};

int run_sensitivity(const SensitivityArgs& a) {
  check_files({{"--json", a.json}, {"--html", a.html}}, {{"--machine", a.machine}});
  if (const std::string kind = machine_kind(a.machine).name; kind != "trr-xy")
    throw UsageError(
        fmt::format("--machine {}: sensitivity maps are defined for the TRR-XY machine (kind \"trr-xy\"), "
                    "this file's kind is \"{}\"",
                    a.machine, kind));
  const trr::Machine m = load_trr_xy_machine(a.machine);
  trr::SensitivityOptions o;
  const auto divides = [](double step, double whole) {
    const double n = whole / step;
    return step > 0 && n >= 1 && std::abs(n - std::round(n)) < 1e-9;
  };
  if (!divides(a.polar_step_deg, o.max_polar_deg) || !divides(a.azimuth_step_deg, 360.0) || a.azimuth_step_deg > 120.0)
    throw UsageError("--polar-step/--azimuth-step: expected steps (deg) that divide 30 and 360 (azimuth at most 120)");
  o.polar_step_deg = a.polar_step_deg;
  o.azimuth_step_deg = a.azimuth_step_deg;
  trr::SensitivityResult r;
  try {
    r = trr::sensitivity(m, o);
  } catch (const std::runtime_error& e) {
    throw Infeasible(e.what());
  }
  if (!a.json.empty()) write_file_atomically(a.json, trr::sensitivity_json(r, o));
  if (!a.html.empty()) write_file_atomically(a.html, trr::sensitivity_html(r, o, m.name, a.machine));
  fmt::print("Tool-tip deviation along the surface normal, hemisphere R {} mm, polar 0-{} deg, {} CL points:\n{}",
             o.sphere_radius_mm, o.max_polar_deg, r.points.size(), trr::sensitivity_table(r));
  return 0;
}

}  // namespace

void add_sensitivity(CLI::App& app, Action& action) {
  auto a = std::make_shared<SensitivityArgs>();
  CLI::App* sub = app.add_subcommand("sensitivity", "Sensitivity maps of the TRR-XY machine's 30 error parameters");
  sub->add_option("--machine", a->machine, "TRR-XY machine definition (TOML)")->required()->check(CLI::ExistingFile);
  sub->add_option("--json", a->json, "Write {\"dr_a\": {\"max_um\", \"min_um\", \"range_um\", ...}, ...}");
  sub->add_option("--html", a->html, "Write a self-contained HTML page with each parameter's map (inline SVG)");
  sub->add_option("--polar-step", a->polar_step_deg, "Grid step in polar angle (deg, default 1)")
      ->check(finite_in(0.0, 30.0, "deg", Bound::open));
  sub->add_option("--azimuth-step", a->azimuth_step_deg, "Grid step in azimuth (deg, default 1)")
      ->check(finite_in(0.0, 120.0, "deg", Bound::open));
  sub->callback([a, &action] { action = [a] { return run_sensitivity(*a); }; });
}

}  // namespace ncpost::cli
