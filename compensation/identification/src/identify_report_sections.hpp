// SPDX-License-Identifier: Apache-2.0
#pragma once
// Sections of the identification report (identify_report.cpp), internal to the compensation
// library: the ballbar tests as a ballbar report draws them (polar plots labelled with angles and
// the axes moved, the residual on its own magnified scale, ISO 230-4 figures, feed and
// direction), the sphere-probing positions with their dispersion per axis before and after, the
// pass/fail verdict against a tolerance, and the compensation values as entered in the control.
#include <optional>
#include <string>
#include <vector>

#include "ncpost/compensation/control_entries.hpp"
#include "ncpost/compensation/identify.hpp"
#include "ncpost/report/circularity.hpp"

namespace ncpost::comp::sections {

/// `tolerance_um`: of G (ISO 14253-1 verdicts); `repeat_G_um`: G of every file of the same test
/// (uncertainty_budget.hpp), empty when not repeated.
/// `opposite`: the run of the same test in the other direction in another file (opposite_run), or
/// nullptr; with it the hysteresis H of the two runs is shown.
std::string ballbar_section(const Machine& machine, const MeasurementSet& set, const std::vector<double>& fitted_mm,
                            const std::vector<double>& nominal_mm, std::optional<double> tolerance_um,
                            const std::vector<double>& repeat_G_um, const MeasurementSet* opposite = nullptr);

/// ISO 230-4 figures of a ballbar file's measured ΔL: both directions together, and where the
/// file runs both, each direction alone (ccw: the test angle rising).
struct BallbarFigures {
  report::CircularityFigures both, ccw, cw;
};
BallbarFigures ballbar_figures(const Machine& machine, const MeasurementSet& set);

/// ISO 230-4 circular hysteresis H (µm) of two ballbar files that run one test in opposite
/// directions (the same bar, balls and axes moved, each file one way): report::circular_hysteresis_um
/// of their measured ΔL against the test angle; nullopt when they are not such a pair.
std::optional<double> two_file_hysteresis_um(const Machine& machine, const MeasurementSet& a, const MeasurementSet& b);

/// The first other set that runs sets[s]'s test in the opposite direction (two_file_hysteresis_um),
/// or nullptr.
const MeasurementSet* opposite_run(const Machine& machine, const std::vector<MeasurementSet>& sets, std::size_t s);

std::string sphere_section(const Machine& machine, const MeasurementSet& set, const std::vector<double>& fitted_mm,
                           const std::vector<double>& nominal_mm);

std::string control_values_section(const Machine& machine, const IdentifyResult& result, ControlFormat format);

/// The largest deviation of each file against `tolerance_um` (ISO 14253-1, the file's reading budget).
std::string verdict_section(const IdentifyResult& result, const std::vector<MeasurementSet>& sets,
                            std::optional<double> tolerance_um);

}  // namespace ncpost::comp::sections
