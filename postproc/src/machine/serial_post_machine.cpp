// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/machine/serial_post_machine.hpp"

#include <fmt/format.h>

#include "ncpost/compensation/machine_model.hpp"
#include "ncpost/postproc/post_request.hpp"
#include "ncpost/postproc/read/cl_input.hpp"
#include "ncpost/postproc/solve/actual_solver.hpp"
#include "ncpost/postproc/solve/executed_on.hpp"
#include "ncpost/postproc/solve/tolerance_subdivider.hpp"

namespace ncpost {
namespace {

/// One run on a serial machine: the nominal chain, the actual machine of the model (if any) and
/// the machine the program is re-executed on (if not the model's).
class SerialModels final : public PostModels {
 public:
  SerialModels(const Machine& machine, const std::optional<comp::ErrorParameters>& model,
               const std::optional<comp::ErrorParameters>& verify_on, const PostRequest& r, bool account)
      : machine_(machine), r_(r), nominal_(machine, r.setup) {
    if (model) {
      model_ = std::make_unique<comp::MachineModel>(machine, *model);
      auto s = std::make_unique<ActualSolver>(*model_, r.setup);
      s->set_measure_uncompensated(account);  // the uncompensated error of each CL point, when reported
      actual_ = s.get();
      actual_solver_ = std::move(s);
    }
    if (verify_on) {
      executing_ = std::make_unique<comp::MachineModel>(machine, *verify_on);
      executed_on_.emplace(solver(), *executing_, r.setup);
    }
  }

  const KinematicModel& posted() const override {
    return executed_on_ ? static_cast<const KinematicModel&>(*executed_on_) : solver();
  }
  /// The program's G93 times on the nominal kinematics: the machine's errors change a block's path
  /// length by far less than the F word's resolution, the nominal chain is several times cheaper to
  /// evaluate than the error model, and the times never depend on a verifying machine.
  const KinematicModel* feeds() const override { return &nominal_; }
  std::unique_ptr<cl::Reader> open_reader(std::istream& in) const override {
    return open_cl_reader(in, r_.input_name, r_.input_kind, r_.reader, machine_, r_.setup);
  }
  PostOptions options(const std::optional<double>& tolerance_mm) const override {
    PostOptions o;
    o.rtcp = r_.rtcp;
    o.tool_length_mm = r_.setup.tool_length_mm;
    o.native_arcs = !model_;  // the actual machine would not follow the control's circle
    o.native_cycles = !model_;
    o.tilted_plane = r_.tilted_plane;
    if (tolerance_mm) {
      const nonlinear::CompensationOptions comp = compensation(r_, *tolerance_mm);
      o.take_up_reversal = true;
      o.subdivide = actual_ ? make_tolerance_subdivider(*actual_, comp, r_.dialect)
                            : make_tolerance_subdivider(nominal_, comp, r_.dialect);
    }
    return o;
  }
  const KinematicModel& before_commands() const override { return nominal_; }
  std::unique_ptr<preview::BlockEvaluator> before_executed() const override {
    const comp::MachineModel* on = executing_ ? executing_.get() : model_.get();
    if (on)
      return std::make_unique<preview::ModelEvaluator<comp::ErrorFunctor<double>>>(on->machine(), r_.setup,
                                                                                   on->errors());
    return std::make_unique<preview::ModelEvaluator<NominalErrors>>(machine_, r_.setup);
  }
  void add_figures(const SolverData& data, PostAccount& account) const override {
    if (!actual_) return;
    account.uncompensated_tip_max_mm = data.uncompensated.max_mm;
    account.uncompensated_tip_rms_mm = data.uncompensated.rms_mm();
  }

 private:
  const KinematicModel& solver() const {
    return actual_solver_ ? *actual_solver_ : static_cast<const KinematicModel&>(nominal_);
  }

  const Machine& machine_;
  const PostRequest& r_;
  NominalSolver nominal_;
  std::unique_ptr<comp::MachineModel> model_;      ///< the machine the program compensates
  std::unique_ptr<KinematicModel> actual_solver_;  ///< IK on it
  const ActualSolver* actual_ = nullptr;
  std::unique_ptr<comp::MachineModel> executing_;  ///< the machine of `--verify-on`
  std::optional<ExecutedOn> executed_on_;
};

class SerialPostMachine final : public PostMachine {
 public:
  SerialPostMachine(Machine machine, std::optional<comp::ErrorParameters> model,
                    std::optional<comp::ErrorParameters> verify_on)
      : machine_(std::move(machine)), model_(std::move(model)), verify_on_(std::move(verify_on)) {}

  const std::string& name() const override { return machine_.name; }
  std::string letters() const override { return axis_letters(machine_); }
  bool has_model() const override { return model_.has_value(); }
  bool has_verify_on() const override { return verify_on_.has_value(); }
  std::string refuses(const PostRequest& r) const override {
    if (machine_.axes.empty()) return "no machine (load_machine)";
    if (r.tilted_plane && model_)
      return "tilted_plane: not with a model (the control maps the plane's coordinates on its nominal kinematics, so "
             "the compensation cannot be carried)";
    return {};
  }
  std::vector<std::string> header(const PostRequest& r, const std::optional<double>& tolerance_mm) const override {
    const Vec3d& o = r.setup.workpiece_origin_mm;
    return {header_origin_line(r), fmt::format("machine {} ({})", machine_.name, r.machine_source),
            fmt::format("workpiece origin {:.4f} {:.4f} {:.4f} mm, tool length {:.4f} mm", o.x(), o.y(), o.z(),
                        r.setup.tool_length_mm),
            header_model_line(r, has_model(), tolerance_mm),
            r.rtcp ? std::string("RTCP: tool tip in the workpiece frame") : std::string("machine axes, no RTCP")};
  }
  std::unique_ptr<PostModels> models(const PostRequest& r, bool account) const override {
    return std::make_unique<SerialModels>(machine_, model_, verify_on_, r, account);
  }

 private:
  Machine machine_;
  std::optional<comp::ErrorParameters> model_, verify_on_;
};

}  // namespace

std::shared_ptr<const PostMachine> serial_post_machine(Machine machine, std::optional<comp::ErrorParameters> model,
                                                       std::optional<comp::ErrorParameters> verify_on) {
  return std::make_shared<SerialPostMachine>(std::move(machine), std::move(model), std::move(verify_on));
}

}  // namespace ncpost
