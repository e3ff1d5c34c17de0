// SPDX-License-Identifier: Apache-2.0
#pragma once
// `ncpost post` and `ncpost preview` on the TRR-XY machine (docs/trr-xy.md): the serial
// subcommands call these first; they run the TRR-XY path when --machine is a kind = "trr-xy" file.
#include <cstdint>
#include <optional>
#include <vector>
#include <string>

#include "input_options.hpp"
#include "ncpost/postproc/post_request.hpp"

namespace ncpost::cli {

/// The TRR-XY job of `ncpost post` (the common post, post_request.hpp): the machine file and the
/// models of --model and --verify-on ("": none). UsageError for the options this machine has not
/// (--rtcp, --tool-length, G-code --input-kind).
TrrJob load_trr_post_job(const JobOptions& job, const std::string& model, const std::string& verify_on, bool rtcp);

struct TrrPreviewRequest {
  const JobOptions& job;
  const std::string& model;
  const std::string& csv;
  const std::string& html;
  const std::string& input;       ///< name in messages
  const std::string& input_path;  ///< the file read
};

/// The exit code if the machine is a TRR-XY machine (then the preview has run), else nullopt.
std::optional<int> preview_if_trr_xy(const TrrPreviewRequest& r);

}  // namespace ncpost::cli

namespace ncpost::cli {

/// `plan sphere` on the TRR-XY machine: the probing poses of trr_identify.hpp with two stylus
/// lengths (0 and 100 mm) → PLAN.csv (trr_probing_csv.hpp) and PLAN.nc. Exit code, or nullopt
/// when the machine is not a TRR-XY machine.
std::optional<int> plan_if_trr_xy(const std::string& machine, const std::string& test, const std::string& output);

/// `simulate` on the TRR-XY machine: a probing plan on the machine of the model JSON.
std::optional<int> simulate_if_trr_xy(const std::string& machine, const std::string& model, const std::string& plan,
                                      const std::string& output, double noise_um, std::uint64_t seed);

/// `identify` on the TRR-XY machine: the 30 parameters from probing data, with the
/// identifiability report; `other_options` names serial-only options that were given.
std::optional<int> identify_if_trr_xy(const std::string& machine, const std::vector<std::string>& data,
                                      const std::string& output, const std::string& other_options);

}  // namespace ncpost::cli
