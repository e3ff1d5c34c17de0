// SPDX-License-Identifier: Apache-2.0
// ncpost simulate: run a measurement plan on a machine described by a model JSON (README "Worked example").
#include <fmt/format.h>

#include <stdexcept>

#include "commands.hpp"
#include "file_checks.hpp"
#include "number_checks.hpp"
#include "model_input.hpp"
#include "machine_kind.hpp"
#include "ncpost/postproc/write/atomic_file.hpp"
#include "ncpost/compensation/measurement_csv.hpp"
#include "ncpost/compensation/model_json.hpp"
#include "ncpost/compensation/simulate.hpp"
#include "ncpost/machines/load.hpp"

namespace ncpost::cli {

/// A measurement plan on the serial machine of the model JSON (simulate.hpp).
SimulateOutput simulate_serial(const SimulateArgs& a) {
  const Machine m = machines::load_as<Machine>(a.machine);
  const comp::ModelFile model = read_model_for(a.model, m, a.force_model);
  const comp::MeasurementSet plan = comp::read_measurement_csv(a.plan, m, {true});
  const comp::MeasurementSet data = comp::simulate(m, plan, model.parameters, {a.noise_um, a.seed});
  return {comp::format_measurement_csv(data, m),
          fmt::format("simulated {} rows of {} on '{}' ({} parameters, noise {} µm)", data.rows.size(),
                      comp::to_string(data.type), m.name, model.parameters.size(), a.noise_um)};
}

void add_simulate(CLI::App& app, Action& action) {
  auto args = std::make_shared<SimulateArgs>();
  CLI::App* sub = app.add_subcommand("simulate", "Simulate a measurement plan on a machine with errors");
  sub->add_option("--machine", args->machine, "machine definition (TOML)")->required();
  sub->add_option("--model", args->model, "error model JSON (written by identify): the simulated machine")->required();
  add_model_force_option(*sub, args->force_model);
  sub->add_option("--noise-um", args->noise_um, "standard deviation of Gaussian noise on every value (µm, 0 to 1000)")
      ->check(finite_in(0.0, 1000.0, "µm"));
  sub->add_option("--seed", args->seed, "random seed of the noise");
  sub->add_option("-o,--output", args->output, "measurement CSV to write")->required();
  sub->add_option("plan", args->plan, "plan CSV (a measurement CSV; value columns absent or ignored)")->required();
  sub->callback([&action, args] {
    action = [args] {
      check_files({{"-o", args->output}},
                  {{"--machine", args->machine}, {"--model", args->model}, {"plan", args->plan}});
      const SimulateOutput out = machine_kind(args->machine).simulate(*args);
      write_file_atomically(args->output, out.csv);
      fmt::print("{} -> {}\n", out.summary, args->output);
      return 0;
    };
  });
}

}  // namespace ncpost::cli
