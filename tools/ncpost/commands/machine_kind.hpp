// SPDX-License-Identifier: Apache-2.0
#pragma once
// The registry of machine kinds: how every subcommand does what differs between kinds for the
// machine of --machine. The machine file's kind ([machine] kind, machine_file_kind in
// ncpost/machines/trr_xy_file.hpp) names one entry, which holds that kind's steps (kind_steps.hpp):
// load the machine and its model for a post or a preview, make a plan, simulate, fit, export.
// Everything else — option checks, file safety, atomic outputs, reports, messages — is the
// command's own code, the same for every kind. A new kind is a row of the registry
// (machine_kind.cpp) and the files of its steps; no command changes.
#include <string>
#include <vector>

#include "kind_steps.hpp"

namespace ncpost::cli {

/// One machine kind and its steps.
struct MachineKind {
  const char* name;  ///< as in the machine file's [machine] kind ("serial", "trr-xy")
  /// Whether a model with these parameter names (not empty) is of this kind (`export` without
  /// --machine); nullptr: the default kind, which takes every model no other kind holds.
  bool (*holds_parameters)(const std::vector<std::string>& names);
  std::unique_ptr<PreviewMachine> (*preview)(const PreviewArgs& args);
  /// Infeasible when the plan cannot be run on the machine; UsageError for a test it has not.
  PlanOutput (*plan)(const PlanArgs& args);
  SimulateOutput (*simulate)(const SimulateArgs& args);
  /// Prints the fit's text report on stdout; throws Infeasible when the fit fails (after the report).
  IdentifyOutput (*identify)(const IdentifyArgs& args);
  /// Loads the machine of the job, with the models of --model and --verify-on, into `r`, whose
  /// program options (rtcp, tilted_plane, nonlinear, tolerance) are already set: UsageError for
  /// an option the machine cannot take.
  void (*load_post)(const PostJobArgs& args, PostRequest& r);
  /// Writes the export; returns the exit code. UsageError for a format the model's kind cannot hold.
  int (*export_model)(const ExportArgs& args);
};

/// The kind of the machine file at `path`; a file without a kind, or of a kind the registry has
/// not, is the default kind's (serial), whose loader refuses an unknown kind naming the line.
/// InputError when the file cannot be read or parsed.
const MachineKind& machine_kind(const std::string& path);

/// The kind of an export: the machine file's (--machine), else the model's own (the kind that
/// holds its parameter names; the default kind says what is wrong with a file it cannot read).
const MachineKind& export_kind(const ExportArgs& args);

}  // namespace ncpost::cli
