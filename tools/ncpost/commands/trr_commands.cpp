// SPDX-License-Identifier: Apache-2.0
// The TRR-XY steps of `ncpost post` and `ncpost preview` (kind_steps.hpp).
#include <fmt/format.h>

#include "kind_steps.hpp"
#include "ncpost/compensation/trr_model.hpp"
#include "ncpost/machines/load.hpp"
#include "ncpost/postproc/machine/trr_xy_post_machine.hpp"
#include "ncpost/postproc/solve/trr_preview_evaluator.hpp"
#include "ncpost/postproc/solve/trr_solver.hpp"
#include "trr_model_input.hpp"

namespace ncpost::cli {
namespace {

/// The options the TRR-XY machine has not (UsageError naming why).
void refuse_serial_options(const JobOptions& o) {
  if (o.tool_length_mm != 0.0)
    throw UsageError("--tool-length: the TRR-XY machine takes its tool offset from the machine file (tool_offset)");
  if (o.input_kind == "rtcp")
    throw UsageError("--input-kind rtcp: the TRR-XY machine has no RTCP programs (its G-code input is X Y U V W)");
}

trr::Kinematics kinematics_of(const trr::Machine& m, const trr::Errors& e) {
  try {
    return trr::Kinematics(m, e);
  } catch (const std::runtime_error& ex) {
    throw Infeasible(ex.what());
  }
}

class TrrPreviewMachine final : public PreviewMachine {
 public:
  TrrPreviewMachine(trr::Machine machine, const trr::Errors& errors, const Vec3d& origin_mm, const JobOptions& job)
      : machine_(std::move(machine)),
        nominal_(kinematics_of(machine_, {})),
        actual_(kinematics_of(machine_, errors)),
        reading_(nominal_, nominal_, origin_mm),
        solver_(actual_, actual_, origin_mm),
        evaluator_(actual_, origin_mm),
        kind_(input_kind_named(job.input_kind)),
        reader_(reader_options(job)) {}

  const std::string& name() const override { return machine_.name; }
  const MotionSolver& solver() const override { return solver_; }
  const preview::BlockEvaluator& evaluator() const override { return evaluator_; }
  /// APT CL data, or a program of the words X Y U V W read back through the nominal machine.
  std::unique_ptr<cl::Reader> open_reader(std::istream& in, const std::string& name) const override {
    const TrrSolver& reading = reading_;
    return open_cl_reader(in, name, kind_, reader_, reading.machine(), Setup{},
                          [&reading](const AxisPosition& q, std::string* why) { return reading.pose(q, why); });
  }

 private:
  trr::Machine machine_;
  trr::Kinematics nominal_, actual_;
  TrrSolver reading_, solver_;
  preview::TrrEvaluator evaluator_;
  InputKind kind_;
  cl::ReaderOptions reader_;
};

}  // namespace

trr::Errors read_trr_model(const std::string& path, const std::string& machine_name, bool force_model) {
  std::vector<std::string> warnings;
  trr::ModelChecks checks;
  checks.machine_name = machine_name;
  checks.force = force_model;
  checks.warnings = &warnings;
  const trr::Errors e = trr::read_errors_json(path, checks);
  for (const auto& w : warnings) fmt::print(stderr, "ncpost: warning: {} (applied: --force)\n", w);
  return e;
}

std::unique_ptr<PreviewMachine> load_trr_xy_preview(const PreviewArgs& a) {
  trr::Machine m = machines::load_as<trr::Machine>(a.job.machine);
  const Vec3d origin_mm = workpiece_origin_mm(a.job);
  refuse_serial_options(a.job);
  trr::Errors e;
  if (!a.model.empty()) e = read_trr_model(a.model, m.name, a.force_model);
  return std::make_unique<TrrPreviewMachine>(std::move(m), e, origin_mm, a.job);
}

void load_trr_xy_post(const PostJobArgs& a, PostRequest& r) {
  if (r.rtcp) throw UsageError("--rtcp: the TRR-XY machine has no RTCP dialect; it is posted in X Y U V W");
  if (r.tilted_plane)
    throw UsageError(
        "--tilted-plane: the TRR-XY machine has no tilted work plane (its control has no rotary axes to "
        "turn a plane with, only the table X Y and the sliders U V W); post without --tilted-plane");
  refuse_serial_options(a.job);
  trr::Machine machine = machines::load_as<trr::Machine>(a.job.machine);
  std::optional<trr::Errors> model, verify_on;
  if (!a.model.empty()) model = read_trr_model(a.model, machine.name, a.force_model);
  if (!a.verify_on.empty()) verify_on = read_trr_model(a.verify_on, machine.name, a.force_model);
  r.machine = trr_xy_post_machine(std::move(machine), std::move(model), std::move(verify_on));
  r.setup.workpiece_origin_mm = workpiece_origin_mm(a.job);
  r.model_source = a.model;
  r.verify_on_source = a.verify_on;
}

}  // namespace ncpost::cli
