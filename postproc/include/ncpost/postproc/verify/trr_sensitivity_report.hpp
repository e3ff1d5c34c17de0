// SPDX-License-Identifier: Apache-2.0
#pragma once
// Reports of `ncpost sensitivity` (docs/trr-xy.md "Sensitivity map"): the JSON
// {"dr_a": {"max_um": .., "min_um": .., "range_um": ..}, ...} for all 30 parameters in the order
// of the spec's table (chain a, b, c), the human table, and a self-contained HTML page (inline SVG,
// no scripts) with each parameter's deviation map over the hemisphere seen from above (+Z up the
// page is +Y; the screw lines of chains a, b, c marked at 0°, 120°, 240°).
#include <string>

#include "ncpost/compensation/trr_sensitivity.hpp"

namespace ncpost::trr {

/// JSON text. Besides max_um, min_um and range_um each entry has `step` (the error set: mm, or
/// deg for ar, at, gp), `unit`, and where the extremes are (`max_at_deg`, `min_at_deg`: polar,
/// azimuth in degrees).
std::string sensitivity_json(const SensitivityResult& r, const SensitivityOptions& o);

/// Fixed-width table, one line per parameter, and a summary by kind of error.
std::string sensitivity_table(const SensitivityResult& r);

/// The maps with a diverging colour bar each (a map without effect drawn as zero), and the
/// provenance (the machine file with its SHA-256, date, version).
std::string sensitivity_html(const SensitivityResult& r, const SensitivityOptions& o, const std::string& machine_name,
                             const std::string& machine_file = {});

}  // namespace ncpost::trr
