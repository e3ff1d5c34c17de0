// SPDX-License-Identifier: Apache-2.0
#pragma once
// Loading the TRR-XY machine file (docs/trr-xy.md "Machine file"): [machine] with
// kind = "trr-xy" and no chain, [trr_xy] with the five dimensions (mm), and [axes.X], [axes.Y]
// (table) and [axes.U], [axes.V], [axes.W] (sliders of chains a, b, c), all type = "linear" with
// optional limits (mm). Optional extra key of ncpost: [trr_xy] max_link_angle (deg, default 45).
// Optional [trr_xy.calibration]: the machine's deviations from the symmetric design in the 30
// parameters of a model (names `<param>_<chain>`, mm and rad, absent = 0; written by
// `ncpost export --format machine`), part of the machine's nominal kinematics (trr::Machine).
// Every error is an InputError naming the file, the line and what was expected.
#include <string>

#include "ncpost/kinematics/trr_xy_geometry.hpp"
#include "ncpost/machines/input_error.hpp"

namespace ncpost {

/// The `kind` of a machine file's [machine] table: "serial" (also when absent) or "trr-xy".
/// Throws InputError if the file cannot be read or parsed.
std::string machine_file_kind(const std::string& path);

trr::Machine parse_trr_xy_machine(const std::string& text, const std::string& file_name);
trr::Machine load_trr_xy_machine(const std::string& path);

}  // namespace ncpost
