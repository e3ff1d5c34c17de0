// SPDX-License-Identifier: Apache-2.0
#pragma once
// Options shared by the subcommands that read a job (machine, set-up, input kind and units).
#include <memory>
#include <optional>
#include <string>

#include "commands.hpp"
#include "ncpost/kinematics/machine.hpp"
#include "ncpost/postproc/read/cl_input.hpp"
#include "ncpost/postproc/read/cl_record.hpp"

namespace ncpost::cli {

struct JobOptions {
  std::string machine;
  std::string workpiece_origin;  ///< "X,Y,Z" mm
  double tool_length_mm = 0.0;
  std::string units;  ///< "", "mm" or "inch": units of a CL file that does not say
  std::string input_kind = "auto";
  bool allow_unterminated = false;         ///< accept a CL file that ends without FINI / END / END-OF-PATH
  std::string msys = "ignore";             ///< NX MSYS: "ignore" (GOTOs as written) or "apply"
  std::string dwell_p = "auto";            ///< G-code dwell time without a decimal point: "auto", "ms" or "s"
  std::string arc_centre = "incremental";  ///< G-code I J K: "incremental", "centre-to-start" or "absolute"
  std::string tool_words = "one";          ///< G-code two T words in a block: "one" (refused) or "load-next"
  std::string integer_words = "auto";  ///< G-code coordinates without a decimal point: "auto", "units", "increments"
  std::string work_offsets;            ///< G-code: the work offsets' values (TOML or a LinuxCNC var file), "" none
  std::string subprogram_dir;          ///< G-code: where subprograms in other files are looked for first, "" none
};

struct LoadedJob {
  Machine machine;
  Setup setup;
};

void add_job_options(CLI::App& sub, JobOptions& o);
/// `--workpiece-origin X,Y,Z` (mm; zero when not given); UsageError when malformed.
Vec3d workpiece_origin_mm(const JobOptions& o);
LoadedJob load_job(const JobOptions& o);
/// The CL reader's options from the command line.
cl::ReaderOptions reader_options(const JobOptions& o);
/// Opens the reader for the input's kind (detected from the content unless forced).
std::unique_ptr<cl::Reader> open_cl_reader(std::istream& in, const std::string& name, const JobOptions& o,
                                           const LoadedJob& job);
// NC axis words of the machine: ncpost::axis_letters (ncpost/postproc/read/cl_input.hpp)

}  // namespace ncpost::cli
