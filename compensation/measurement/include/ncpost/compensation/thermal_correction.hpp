// SPDX-License-Identifier: Apache-2.0
#pragma once
// Measured lengths corrected to 20 °C (ISO 1; issue 25 item 3; docs/formats.md "Measurement
// conditions"). A set whose file gives `# temperature:` T (°C) and `# material_expansion:` α (1/K)
// was measured on a machine whose structure and scales stood expanded by f = 1 + α (T − 20 °C):
// a length ℓ_T read by an instrument that does not expand with the machine is, at 20 °C,
//   ℓ_20 = ℓ_T / f.
// Which lengths:
//   ballbar  L (the measured bar length, mm):           L_20 = L_T / f
//   laser    positioning lines (component = the moving axis): the length the laser read from the
//            run's first row, D_T = (q − q_0) + (e − e_0)/1000 (mm; q the moving axis's command),
//            becomes D_20 = D_T / f, i.e. e_20 = e_0 + 1000 (D_20 − (q − q_0)) µm;
//            straightness lines are not changed (a uniform expansion moves a line's points by the
//            same amount across it, which the zeroing at each run's first row removes);
//   sphere   not changed: the probe reads the sphere through the machine's own scales, which
//            expand with the structure that carries the sphere (a uniform expansion cancels).
// The inverse (simulate: what the instrument reads at T) multiplies by f the same way.
#include <vector>

#include "ncpost/compensation/measurement.hpp"

namespace ncpost::comp {

/// Applies ℓ_20 = ℓ_T / f to the set's values where the file gives both T and α and the type has
/// lengths to correct; sets `corrected_to_20c` and `thermal_correction_max_um` (the largest change).
/// A set already corrected is left as it is.
void correct_to_20c(MeasurementSet& set);

/// The inverse: values of a machine at 20 °C as the instrument reads them at the file's T
/// (ℓ_T = f · ℓ_20), for `simulate`. No change where the file does not give both.
void expand_to_measuring_temperature(MeasurementSet& set);

/// True if the 20 °C correction changes this type of set (ballbar; laser positioning lines).
bool has_lengths_to_correct(const MeasurementSet& set);

/// The warnings of one identification's files: temperatures that differ by more than
/// kTemperatureAgreementK between files, each "text" without a prefix. Empty when they agree.
std::vector<std::string> temperature_warnings(const std::vector<MeasurementSet>& sets);

}  // namespace ncpost::comp
