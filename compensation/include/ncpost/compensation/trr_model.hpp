// SPDX-License-Identifier: Apache-2.0
#pragma once
// TRR-XY error parameters in the model JSON (docs/formats.md "Error model"; names of docs/trr-xy.md:
// `<param>_<chain>`, e.g. `dl_a`, in mm and rad). Parameters not in the file are zero.
#include <string>

#include "ncpost/compensation/model_json.hpp"
#include "ncpost/kinematics/trr_xy_geometry.hpp"

namespace ncpost::trr {

/// Reads a model file; a parameter name that is not one of the 30 is an InputError naming the
/// file and the line of the name.
Errors read_errors_json(const std::string& path);

/// The parameters of a model file as Errors (validated as above; `text` is the file's text for
/// line numbers).
Errors errors_from_model(const comp::ModelFile& model, const std::string& text, const std::string& path);

/// A model file holding these errors (all 30, in the spec's order).
comp::ModelFile model_from_errors(const Errors& e, const std::string& machine_name);

}  // namespace ncpost::trr
