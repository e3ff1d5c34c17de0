// SPDX-License-Identifier: Apache-2.0
// The TRR-XY step of `export` (kind_steps.hpp): the model's 30 parameters folded into the machine
// file as its calibration (export_trr_machine.hpp). A TRR-XY model has no per-axis tables, so the
// one-axis formats (linuxcnc, siemens, isg) are refused naming what it supports.
#include <fmt/format.h>

#include <stdexcept>

#include "file_checks.hpp"
#include "kind_steps.hpp"
#include "ncpost/compensation/export_trr_machine.hpp"
#include "ncpost/kinematics/trr_xy_geometry.hpp"
#include "ncpost/machines/load.hpp"
#include "ncpost/postproc/write/atomic_file.hpp"
#include "ncpost/version.hpp"
#include "trr_model_input.hpp"

namespace ncpost::cli {

int export_trr_xy(const ExportArgs& args) {
  std::vector<NamedPath> inputs{{"MODEL", args.model}};
  if (!args.machine.empty()) inputs.push_back({"--machine", args.machine});
  check_files({{"-o", args.output}}, inputs);
  if (args.format == "linuxcnc" || args.format == "siemens" || args.format == "isg")
    throw UsageError(fmt::format(
        "--format {}: a TRR-XY model holds the 30 geometric parameters of the parallel head (docs/trr-xy.md), no "
        "per-axis error table for a {} file; it supports --format machine (with --machine, the TRR-XY machine file "
        "to correct)",
        args.format, args.format));
  if (args.format != "machine")
    throw UsageError(
        fmt::format("--format: expected machine for a TRR-XY model (the machine file with the model as "
                    "its calibration), got '{}'",
                    args.format));
  if (!args.axis.empty())
    throw UsageError("--axis: a TRR-XY machine file takes the whole model, not one axis (leave out --axis)");
  if (args.machine.empty())
    throw UsageError("--format machine needs --machine M.toml: the TRR-XY machine file to correct");
  const trr::Machine machine = machines::load_as<trr::Machine>(args.machine);
  const trr::Errors model = read_trr_model(args.model, machine.name, args.force);
  comp::TrrMachineExport out;
  try {
    out = comp::corrected_trr_machine(machine, model);
  } catch (const std::invalid_argument& e) {
    throw InputError({args.model, 0, 0}, fmt::format("{}; the machine file would be the original one", e.what()));
  }
  const std::vector<std::string> notes{
      fmt::format("ncpost {} export --format machine: '{}' with the model '{}' applied", ncpost::version(),
                  machine.name, args.model),
      fmt::format("(from '{}') as its calibration ([trr_xy.calibration], the machine's own plus the model's",
                  args.machine),
      "parameters): read it NOMINALLY (post without --model); the name differs from the original's so that this",
      "model is not applied a second time.",
      fmt::format("Applied: {}", fmt::join(out.applied, ", ")),
      "Left out: nothing"};
  write_file_atomically(args.output, comp::format_trr_machine_toml(out.corrected, notes));
  fmt::print("exported {} parameter(s) of the model into the machine file '{}' ({})\n", out.applied.size(), args.output,
             out.corrected.name);
  return 0;
}

bool holds_trr_xy_parameters(const std::vector<std::string>& names) {
  for (const std::string& n : names)
    if (trr::Errors::index_of(n) < 0) return false;
  return true;
}

}  // namespace ncpost::cli
