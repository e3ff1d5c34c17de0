// SPDX-License-Identifier: Apache-2.0
// The three-axis laser loop on data it has not seen (issue 25 item 6): for each seed, a VMCL600
// truth whose 21 errors are not of the model's form (tests/support/laser_unseen_truth.hpp), the
// bundled laser plan (three lines per axis, 5 bidirectional runs) measured on it with noise, the
// identification, and two programs posted with the identified model and executed on the truth
// (tests/support/vmc_cut.hpp): the dome of vmc_compensated_cut_test (radius 120 mm, 5 deg) and
// samples/measurements/vmcl600/volume_test.cls. Printed per seed: the contour error (max over
// the executed path, µm) before (nominal program) and after (--tolerance 0.01 and 0.002), and per
// error function how far the identified model departs from the truth: at the laser targets,
// between them and beyond the outermost ones (straightness about its ISO 230-1 line).
// Usage: laser_unseen_bench [first seed=1] [sets=5] [noise µm=0.4] [work dir=.]
// (bench/run_laser_unseen.sh builds and runs it; figures in compensation/LASER.md)
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#define NCPOST_SOURCE_DIR NCPOST_BENCH_SOURCE_DIR
#include "laser_unseen_truth.hpp"
#include "ncpost/compensation/laser_identify.hpp"
#include "ncpost/compensation/machine_model.hpp"
#include "ncpost/machines/machine_file.hpp"
#include "test_paths.hpp"
#include "text_file.hpp"
#include "vmc_cut.hpp"

using namespace ncpost;

namespace {

/// Largest |model − truth| of one function at the targets, between them, and beyond them
/// (over the travel), in µm or µrad.
struct Departure {
  double at_targets = 0.0, between = 0.0, beyond = 0.0;
};

Departure departure(const comp::LaserFunction& f, const test::UnseenFunction& truth, double lo, double hi) {
  const bool straightness = f.component != f.axis && !f.is_angle();
  // the truth about its least-squares line over the targets, as the identification reports it
  const double s = straightness ? test::unseen_ls_slope(truth, f.nodes_mm) : 0.0;
  const double unit = f.is_angle() ? 1e6 : 1e3;
  Departure d;
  const double first = f.nodes_mm.front(), last = f.nodes_mm.back();
  for (double x = lo; x <= hi + 1e-9; x += 1.0) {
    const double e = unit * std::abs(f.at(x) - (truth(x) - s * x));
    const bool on_target =
        std::any_of(f.nodes_mm.begin(), f.nodes_mm.end(), [&](double n) { return std::abs(n - x) < 0.5; });
    double& slot = x < first || x > last ? d.beyond : on_target ? d.at_targets : d.between;
    slot = std::max(slot, e);
  }
  return d;
}

/// The identified functions with the curves between targets chosen up to Legendre degree
/// `max_degree` (< 0: the tables of the targets, linear between them, as before issue 25 item 6;
/// 0: linear or spline, the curves through the nodes).
comp::ErrorParameters with_curves(const comp::LaserIdentifyResult& r, int max_degree) {
  comp::ErrorParameters p;
  for (const auto& f : r.functions) {
    comp::LaserCurve c = max_degree >= 0 && f.fully_seen()
                             ? comp::choose_laser_curve(f.nodes_mm, f.values, 5.0, max_degree)
                             : comp::LaserCurve{};
    if (c.basis == comp::LaserBasis::linear) c.nodes_mm = f.nodes_mm, c.values = f.values;
    for (std::size_t i = 0; i < c.nodes_mm.size(); ++i)
      p.set(comp::table_parameter_name(f.component, f.axis, c.nodes_mm[i]), c.values[i]);
  }
  for (const comp::ErrorParameters* q : {&r.squareness, &r.reversal})
    for (std::size_t i = 0; i < q->size(); ++i) p.set(q->names()[i], q->values()[i]);
  return p;
}

struct Figures {
  double before_um = 0.0, after_um = 0.0, tight_um = 0.0;
};

Figures cut_figures(const Machine& m, const comp::MachineModel& model, const comp::MachineModel& truth,
                    const std::string& cl, const std::string& out) {
  const test::VmcCut before = test::vmc_cut_on(m, nullptr, truth, cl, -1, out);
  const test::VmcCut after = test::vmc_cut_on(m, &model, truth, cl, 0.01, out);
  const test::VmcCut tight = test::vmc_cut_on(m, &model, truth, cl, 0.002, out);
  for (const auto* c : {&before, &after, &tight})
    if (!c->failure.empty()) fmt::print("  post failed: {}\n", c->failure);
  return {1e3 * before.summary.verify.max_contour_mm, 1e3 * after.summary.verify.max_contour_mm,
          1e3 * tight.summary.verify.max_contour_mm};
}

}  // namespace

int main(int argc, char** argv) {
  const std::uint64_t first = argc > 1 ? std::stoull(argv[1]) : 1;
  const int sets = argc > 2 ? std::stoi(argv[2]) : 5;
  const double noise_um = argc > 3 ? std::stod(argv[3]) : 0.4;
  const std::string dir = argc > 4 ? argv[4] : ".";
  const Machine m = load_machine(test::source("machines/vmcl600.toml"));
  const comp::LaserPlanOptions plan;
  const std::string dome = test::vmc_dome_cl(5);
  const std::string volume = test::read_text_file(test::source("samples/measurements/vmcl600/volume_test.cls"));
  fmt::print(
      "seed | dome before / 0.01 / 0.002 µm (ratio) | volume before / 0.01 / 0.002 µm (ratio) | fit rms µm | s\n");
  for (std::uint64_t seed = first; seed < first + static_cast<std::uint64_t>(sets); ++seed) {
    const auto t0 = std::chrono::steady_clock::now();
    const test::UnseenTruth truth = test::unseen_truth(m, plan, seed);
    const auto data = test::unseen_laser_data(m, truth.parameters, plan, noise_um, seed);
    const comp::LaserIdentifyResult r = comp::identify_laser(m, data);
    if (!r.ok) {
      fmt::print("{}: identification failed: {}\n", seed, r.message);
      continue;
    }
    const comp::MachineModel on_truth(m, truth.parameters);
    // the identified model (curves through the nodes, the default) and the two alternatives
    const comp::MachineModel tables(m, with_curves(r, -1)), through(m, r.parameters),
        model(m, with_curves(r, comp::kMaxLegendreDegree));
    for (const auto* mm : {&tables, &through, &model}) {
      const Figures d = cut_figures(m, *mm, on_truth, dome, dir + "/laser_unseen_bench.nc");
      const Figures v = cut_figures(m, *mm, on_truth, volume, dir + "/laser_unseen_bench.nc");
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      fmt::print("{} {} | {:.2f} / {:.2f} / {:.2f} ({:.1f}x) | {:.2f} / {:.2f} / {:.2f} ({:.1f}x) | {:.2f} | {:.1f}\n",
                 seed,
                 mm == &tables    ? "linear tables "
                 : mm == &through ? "linear/spline "
                                  : "+ legendre    ",
                 d.before_um, d.after_um, d.tight_um, d.before_um / d.after_um, v.before_um, v.after_um, v.tight_um,
                 v.before_um / v.after_um, r.rms_fit_um, s);
    }
    for (std::size_t i = 0; i < truth.names.size(); ++i)
      for (const auto& f : r.functions)
        if (f.name() == truth.names[i]) {
          const Axis& axis = m.axes[static_cast<std::size_t>(f.axis - 'X')];
          comp::LaserFunction table = f;
          table.curve = {};  // LaserFunction::at then interpolates the target nodes
          const Departure l = departure(table, truth.functions[i], axis.limits->min, axis.limits->max);
          const Departure e = departure(f, truth.functions[i], axis.limits->min, axis.limits->max);
          fmt::print("    {} {:<16} {:<11} targets {:6.2f}  between {:6.2f} (linear {:6.2f})  beyond {:6.2f} {}\n",
                     f.name(), f.kind(), f.curve.label(), e.at_targets, e.between, l.between, e.beyond,
                     f.is_angle() ? "µrad" : "µm");
        }
    // squareness: the truth's, plus the slopes of EXY, EXZ, EYZ moved into it (ISO 230-1)
    auto slope = [&](const std::string& name) {
      for (std::size_t i = 0; i < truth.names.size(); ++i)
        if (truth.names[i] == name)
          return test::unseen_ls_slope(truth.functions[i], comp::laser_targets(m, name[2] - 'X', plan));
      return 0.0;
    };
    const double iso[3] = {truth.parameters.value_or("EC0Y", 0.0) - slope("EXY") - slope("EYX"),
                           truth.parameters.value_or("EB0Z", 0.0) + slope("EXZ") + slope("EZX"),
                           truth.parameters.value_or("EA0Z", 0.0) - slope("EYZ") - slope("EZY")};
    int k = 0;
    for (const char* q : {"EC0Y", "EB0Z", "EA0Z"})
      fmt::print("    {} identified {:.2f} µrad, ISO truth {:.2f}\n", q, 1e6 * r.squareness.value_or(q, 0.0),
                 1e6 * iso[k++]);
  }
  return 0;
}
