// SPDX-License-Identifier: Apache-2.0
#pragma once
// The steps of each subcommand that differ between machine kinds (machine_kind.hpp): what the
// command gives them (its arguments, checked), what they give back (the contents of the files the
// command then writes, all or none), and each kind's steps. Each section ends with the step of the
// serial machines (machine.hpp), defined in the command's file (cmd_*.cpp); the TRR-XY steps are
// at the end (trr_commands.cpp, trr_measure_commands.cpp, trr_export.cpp).
#include <cstdint>
#include <istream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "input_options.hpp"
#include "ncpost/compensation/laser_plan.hpp"
#include "ncpost/postproc/post_request.hpp"
#include "ncpost/postproc/verify/preview_blocks.hpp"

namespace ncpost::cli {

// ---- preview ------------------------------------------------------------------------------

struct PreviewArgs {
  JobOptions job;
  std::string model;
  bool force_model = false;  ///< --force: model checks as warnings
  std::string csv;
  std::string html;
  std::string input;       ///< the INPUT argument; in a run, the name in messages
  std::string input_path;  ///< in a run: the file read (the spool of standard input or a pipe)
};

/// The machine a preview runs on (the nominal one, or that of --model): the solver of its commands,
/// the evaluator of its blocks and the reader of its input (APT, or G-code in its words).
class PreviewMachine {
 public:
  virtual ~PreviewMachine() = default;
  virtual const std::string& name() const = 0;
  virtual const MotionSolver& solver() const = 0;
  virtual const preview::BlockEvaluator& evaluator() const = 0;
  /// The reader of `in`, named `name` in messages.
  virtual std::unique_ptr<cl::Reader> open_reader(std::istream& in, const std::string& name) const = 0;
};

std::unique_ptr<PreviewMachine> load_serial_preview(const PreviewArgs& args);

// ---- plan ---------------------------------------------------------------------------------

struct PlanArgs {
  std::string machine, test, output;
  std::vector<double> heights, tool_lengths, levels;
  std::optional<double> bar_length, dt, t0, step;
  int points = 500;
  double clearance_mm = 30.0;
  std::string sphere;
  bool seed_directions = false;
  comp::LaserPlanOptions laser;
  std::string dialect = "fanuc";  ///< the NC program's dialect (name or dialect file)
};

/// The files of a plan: its measurement sets and the NC program that runs them.
struct PlanOutput {
  struct Set {
    std::string name;  ///< PLAN.csv for a single set, else PLAN_<name>.csv
    std::string csv;
    std::size_t rows = 0;
  };
  std::vector<Set> sets;
  std::string program;  ///< PLAN.nc
};

PlanOutput plan_serial(const PlanArgs& args);

// ---- simulate -----------------------------------------------------------------------------

struct SimulateArgs {
  std::string machine, model, output, plan;
  bool force_model = false;  ///< --force: model checks as warnings
  double noise_um = 0.0;
  std::uint64_t seed = 1;
};

struct SimulateOutput {
  std::string csv;      ///< the measurement CSV
  std::string summary;  ///< "simulated N rows of ... on 'machine' (...)"
};

SimulateOutput simulate_serial(const SimulateArgs& args);

// ---- identify -----------------------------------------------------------------------------

struct IdentifyArgs {
  std::string machine, output, report, params, fixed, loss = "squared";
  std::string control;  ///< --control: the report's control entries ("" = the machine's default)
  double loss_scale_um = 3.0;
  std::optional<double> pass_tolerance_um;
  std::string tolerance;  ///< --tolerance KIND=µm,...: per figure kind, over the machine file's [tolerances]
  bool no_diagnose = false, no_basic = false;
  std::vector<std::string> data;
};

struct IdentifyOutput {
  std::string model_json;
  std::string report_html;   ///< written to --report when given
  std::string summary_html;  ///< its one-page summary, written beside it (summary_page.hpp)
  std::string closing;       ///< printed once the files are written
};

IdentifyOutput identify_serial(const IdentifyArgs& args);

// ---- post ---------------------------------------------------------------------------------

struct PostJobArgs {
  const JobOptions& job;
  const std::string& model;      ///< --model ("": none)
  const std::string& verify_on;  ///< --verify-on ("": none)
  bool force_model = false;      ///< --force
};

void load_serial_post(const PostJobArgs& args, PostRequest& r);

// ---- export -------------------------------------------------------------------------------

struct ExportArgs {
  std::string format, axis, machine, output, model;
  bool force = false;
};

int export_serial(const ExportArgs& args);

// ---- the TRR-XY steps (docs/trr-xy.md) -----------------------------------------------------

std::unique_ptr<PreviewMachine> load_trr_xy_preview(const PreviewArgs& args);
/// `plan sphere`: the probing poses of trr_identify.hpp with two stylus lengths (0 and 100 mm).
PlanOutput plan_trr_xy(const PlanArgs& args);
/// A probing plan on the machine of the model JSON.
SimulateOutput simulate_trr_xy(const SimulateArgs& args);
/// The 30 parameters from probing data, with the identifiability report.
IdentifyOutput identify_trr_xy(const IdentifyArgs& args);
void load_trr_xy_post(const PostJobArgs& args, PostRequest& r);
/// `export --format machine`: the model folded into the machine file ([trr_xy.calibration]).
int export_trr_xy(const ExportArgs& args);
/// A model whose parameters (`names`, not empty) are all TRR-XY names is a TRR-XY model.
bool holds_trr_xy_parameters(const std::vector<std::string>& names);

}  // namespace ncpost::cli
