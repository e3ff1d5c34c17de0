// SPDX-License-Identifier: Apache-2.0
// ncpost preview: the nonlinear error of every block of a CL program (README "Nonlinear error").
#include <fmt/format.h>
#include <unistd.h>

#include <fstream>
#include <memory>
#include <optional>

#include "commands.hpp"
#include "file_checks.hpp"
#include "input_file.hpp"
#include "model_input.hpp"
#include "input_options.hpp"
#include "machine_kind.hpp"
#include "ncpost/compensation/machine_model.hpp"
#include "ncpost/compensation/model_json.hpp"
#include "ncpost/postproc/write/atomic_file.hpp"
#include "ncpost/postproc/verify/preview_csv.hpp"
#include "ncpost/postproc/verify/preview_html.hpp"
#include "ncpost/postproc/solve/preview_model_solver.hpp"

namespace ncpost::cli {
namespace {

/// The serial machine (nominal, or that of --model) with its solver and block evaluator.
class SerialPreviewMachine final : public PreviewMachine {
 public:
  explicit SerialPreviewMachine(const PreviewArgs& a) : options_(a.job), job_(load_job(a.job)) {
    if (!a.model.empty()) {
      const comp::ModelFile file = read_model_for(a.model, job_.machine, a.force_model);
      model_ = std::make_unique<comp::MachineModel>(job_.machine, file.parameters);
      solver_ = std::make_unique<preview::ModelMotionSolver>(*model_, job_.setup);
      evaluator_ = std::make_unique<preview::ModelEvaluator<comp::ErrorFunctor<double>>>(model_->machine(), job_.setup,
                                                                                         model_->errors());
    } else {
      solver_ = std::make_unique<NominalSolver>(job_.machine, job_.setup);
      evaluator_ = std::make_unique<preview::ModelEvaluator<NominalErrors>>(job_.machine, job_.setup);
    }
  }

  const std::string& name() const override { return job_.machine.name; }
  const MotionSolver& solver() const override { return *solver_; }
  const preview::BlockEvaluator& evaluator() const override { return *evaluator_; }
  std::unique_ptr<cl::Reader> open_reader(std::istream& in, const std::string& name) const override {
    return open_cl_reader(in, name, options_, job_);
  }

 private:
  JobOptions options_;
  LoadedJob job_;
  std::unique_ptr<comp::MachineModel> model_;
  std::unique_ptr<MotionSolver> solver_;
  std::unique_ptr<preview::BlockEvaluator> evaluator_;
};

}  // namespace

std::unique_ptr<PreviewMachine> load_serial_preview(const PreviewArgs& a) {
  return std::make_unique<SerialPreviewMachine>(a);
}

namespace {

int run_preview(const PreviewArgs& given) {
  check_files({{"--csv", given.csv}, {"--html", given.html}},
              {{"INPUT", given.input}, {"--machine", given.job.machine}, {"--model", given.model}});
  const InputFile input(given.input);
  PreviewArgs a = given;
  a.input = input.name();
  a.input_path = input.path();
  const std::unique_ptr<PreviewMachine> machine = machine_kind(a.job.machine).preview(a);
  const MotionSolver& solver = machine->solver();
  const preview::BlockEvaluator& evaluator = machine->evaluator();
  std::ifstream in(a.input_path, std::ios::binary);
  if (!in) throw InputError({a.input, 0, 0}, "cannot open the input file");
  auto reader = machine->open_reader(in, a.input);

  std::optional<AtomicFile> csv_file;
  std::optional<preview::CsvWriter> csv;
  if (!a.csv.empty()) {
    csv_file.emplace(a.csv);
    csv.emplace(*csv_file);
  }
  preview::PreviewSummary summary;
  const bool tty = ::isatty(STDERR_FILENO) != 0;
  std::function<void(std::size_t)> progress;
  if (tty) progress = [](std::size_t n) { fmt::print(stderr, "\rpreview: {} motions", n); };
  preview::PreviewStats stats;
  try {
    stats = preview::run_preview(
        *reader, a.input, solver, evaluator,
        [&](const preview::BlockRow& row) {
          if (csv) csv->add(row);
          summary.add(row);
        },
        progress);
  } catch (const preview::PreviewInfeasible& e) {
    throw Infeasible(e.what());
  }
  if (tty) fmt::print(stderr, "\r\033[K");

  if (!a.html.empty()) {
    preview::HtmlReport report;
    report.input_name = a.input;
    report.machine_name = fmt::format("{} ({})", machine->name(), a.job.machine);
    report.model_name = a.model;
    report.inputs.push_back({"CL input", a.input_path, a.input});
    report.inputs.push_back({"machine file", a.job.machine});
    if (!a.model.empty()) report.inputs.push_back({"error model", a.model});
    report.summary = &summary;
    report.stats = stats;
    std::vector<int> lines;
    for (const auto& w : summary.worst()) lines.push_back(w.line);
    report.worst_source_lines = preview::source_lines(a.input_path, lines);
    if (!summary.worst().empty()) report.worst_curve_mm = evaluator.error_curve(summary.worst().front().cl, 200);
    write_file_atomically(a.html, preview::render_html(report));
  }
  if (csv_file) csv_file->commit();

  for (const auto& n : stats.notices) fmt::print(stderr, "notice: {}\n", n);
  std::string worst;
  if (!summary.worst().empty())
    worst = fmt::format(" (block {}, CL line {})", summary.worst().front().block, summary.worst().front().line);
  fmt::print(
      "{} CL motions, {} blocks previewed; largest nonlinear error {:.4f} mm{}, mean {:.4f} mm, largest "
      "orientation error {:.4f} deg; blocks over 5 µm: {}\n",
      stats.motions, summary.blocks(), summary.max_error_mm(), worst, summary.mean_error_mm(),
      rad_to_deg(summary.max_orientation_rad()), summary.blocks_over(0.005));
  return 0;
}

}  // namespace

void add_preview(CLI::App& app, Action& action) {
  auto a = std::make_shared<PreviewArgs>();
  CLI::App* sub =
      app.add_subcommand("preview", "Preview the nonlinear error of every block (exact and harmonic model)");
  add_job_options(*sub, a->job);
  sub->add_option("--model", a->model, "Error model JSON: preview on the actual machine");
  add_model_force_option(*sub, a->force_model);
  sub->add_option("--csv", a->csv, "Write one row per block: block,line,max_error_mm,at_t,harmonic_mm,...");
  sub->add_option("--html", a->html, "Write a self-contained HTML report (inline SVG)");
  sub->add_option("INPUT", a->input, "APT CL data or G-code; - reads standard input")
      ->required()
      ->check(existing_input());
  sub->callback([a, &action] { action = [a] { return run_preview(*a); }; });
}

}  // namespace ncpost::cli
