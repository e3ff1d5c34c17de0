// SPDX-License-Identifier: Apache-2.0
#pragma once
// The error model file (docs/formats.md "Error model (JSON)"): written by `identify`, read by
// `post --model` and `simulate`. Parameters in mm / rad (names: parameter_name.hpp; component
// errors of linear axes either as polynomial terms `EXX:p1` or as table nodes `EXX:t:-250`, the
// value at that axis position, interpolated linearly — issue 7, compensation/LASER.md).
//
// Reading validates every parameter name against the machine (when given): an unknown or
// impossible name is an InputError naming the file, the line of the name and the reason. Keys
// this page does not know are kept (`extra`, as their JSON text) and written back.
//
// With a machine, the model must also be made for it (issue 14 item 10): `"machine"` its name,
// `"axes"` (when given; written by identify) its axis letters, and every parameter plausible for
// its kind (model_plausibility.hpp). Otherwise an InputError, unless `force`: then each problem is
// kept in `warnings` (FILE:LINE:COL: text) for the caller to print. Numbers beyond double range
// (1e400) and keys of a wrong type are InputErrors too, never a library exception.
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ncpost/compensation/error_parameters.hpp"
#include "ncpost/kinematics/machine.hpp"
#include "ncpost/machines/input_error.hpp"

namespace ncpost::comp {

/// A direction of parameter space the data cannot see: name → weight (unit vector).
using NullDirection = std::vector<std::pair<std::string, double>>;

struct Identifiability {
  int rank = 0;
  int parameters = 0;
  std::vector<NullDirection> null_space;  ///< weights under 0.05 left out when written
  /// Parameters held at their prior value (not fitted) because the data cannot separate them.
  std::vector<std::string> pinned;
  /// For each pinned parameter, what the fitted values represent (human text).
  std::vector<std::string> combinations;
};

struct FitSummary {
  double rms_before_um = 0.0;
  double max_before_um = 0.0;
  double rms_after_um = 0.0;
  double max_after_um = 0.0;
  double rms_nominal_um = 0.0;  ///< extra: residual of the nominal machine (no errors)
  double max_nominal_um = 0.0;
};

struct ModelFile {
  std::string machine;
  std::string axes;  ///< the machine's axis letters in order, e.g. "XYZAC" ("" if not given)
  ErrorParameters parameters;
  ErrorParameters uncertainty;
  std::vector<std::string> effects_added;
  std::optional<Identifiability> identifiability;
  std::optional<FitSummary> fit;
  /// Other top-level keys, kept as they are: key → the value's JSON text (written back in key order).
  std::map<std::string, std::string> extra;
  std::vector<std::string> warnings;  ///< checks overridden by ModelReadOptions::force (not written)
};

struct ModelReadOptions {
  bool force = false;  ///< accept a model of another machine or with implausible values (as warnings)
};

/// The axis letters of a machine in order ("XYZAC"), as the model file's "axes".
std::string model_axes(const Machine& machine);

/// Parses a model file; with `machine`, every parameter name is checked against it.
ModelFile parse_model_json(const std::string& text, const std::string& file_name, const Machine* machine,
                           const ModelReadOptions& options = {});
ModelFile read_model_json(const std::string& path, const Machine* machine, const ModelReadOptions& options = {});
/// The JSON text (1-space indent as the shared files, parameters in their order).
std::string format_model_json(const ModelFile& model);

}  // namespace ncpost::comp
