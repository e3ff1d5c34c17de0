// SPDX-License-Identifier: Apache-2.0
#pragma once
// Simulated measurements: a plan run on a machine described by error parameters (the truth),
// with Gaussian noise (docs/formats.md, docs/cli.md `simulate`). Values in the file's units (mm; laser µm);
// the noise standard deviation is given in µm for every type. A plan whose file gives
// `# temperature:` and `# material_expansion:` is simulated as read at that temperature (the
// lengths expanded, thermal_correction.hpp), which `identify` corrects back to 20 °C.
#include <cstdint>

#include "ncpost/compensation/error_parameters.hpp"
#include "ncpost/compensation/measurement.hpp"

namespace ncpost::comp {

struct SimulationOptions {
  double noise_um = 0.0;   ///< standard deviation of the added noise (µm)
  std::uint64_t seed = 1;  ///< random seed (std::mt19937_64)
};

/// The plan with its values filled in. Throws std::invalid_argument for a parameter name the
/// machine cannot have.
MeasurementSet simulate(const Machine& machine, const MeasurementSet& plan, const ErrorParameters& truth,
                        const SimulationOptions& options = {});

}  // namespace ncpost::comp
