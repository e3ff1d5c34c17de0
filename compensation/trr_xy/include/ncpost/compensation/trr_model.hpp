// SPDX-License-Identifier: Apache-2.0
#pragma once
// TRR-XY error parameters in the model JSON (docs/formats.md "Error model"; names of docs/trr-xy.md:
// `<param>_<chain>`, e.g. `dl_a`, in mm and rad). Parameters not in the file are zero.
#include <string>
#include <vector>

#include "ncpost/compensation/model_json.hpp"
#include "ncpost/kinematics/trr_xy_geometry.hpp"

namespace ncpost::trr {

/// What a model must agree with before it is applied (issue 14 item 10, compensation/README.md
/// "Model checks"): it names this machine, and every value is plausible for its kind (lengths
/// within `length_mm`, angles within `angle_rad`). With `force`, each failed check is a warning
/// (appended to `warnings`) instead of an InputError.
struct ModelChecks {
  std::string machine_name;  ///< empty: not checked (a model written for no machine in particular)
  bool force = false;
  double length_mm = 1.0;
  double angle_rad = 0.01;
  std::vector<std::string>* warnings = nullptr;
};

/// Reads a model file; a parameter name that is not one of the 30 is an InputError naming the
/// file and the line of the name; then the checks above.
Errors read_errors_json(const std::string& path, const ModelChecks& checks = {});

/// The parameters of a model file as Errors (validated as above; `text` is the file's text for
/// line numbers).
Errors errors_from_model(const comp::ModelFile& model, const std::string& text, const std::string& path);

/// A model file holding these errors (all 30, in the spec's order).
comp::ModelFile model_from_errors(const Errors& e, const std::string& machine_name);

}  // namespace ncpost::trr
