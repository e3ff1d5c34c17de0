// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/machine/trr_xy_post_machine.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "ncpost/kinematics/trr_xy_forward.hpp"
#include "ncpost/postproc/post_request.hpp"
#include "ncpost/postproc/read/cl_input.hpp"
#include "ncpost/postproc/solve/trr_preview_evaluator.hpp"
#include "ncpost/postproc/solve/trr_solver.hpp"
#include "ncpost/postproc/solve/trr_subdivider.hpp"

namespace ncpost {
namespace {

trr::Kinematics kinematics(const trr::Machine& m, const std::optional<trr::Errors>& e) {
  try {
    return trr::Kinematics(m, e.value_or(trr::Errors{}));
  } catch (const std::runtime_error& ex) {
    throw Infeasible(ex.what());
  }
}

/// One run on the TRR-XY machine: the nominal kinematics (reading G-code, the commands of the
/// "before"), those the commands compensate (the model's) and those the program runs on.
class TrrModels final : public PostModels {
 public:
  TrrModels(const trr::Machine& m, const std::optional<trr::Errors>& model, const std::optional<trr::Errors>& verify_on,
            const PostRequest& r)
      : r_(r),
        nominal_(kinematics(m, std::nullopt)),
        commanded_(kinematics(m, model)),
        executing_(kinematics(m, verify_on ? verify_on : model)),
        reading_(nominal_, nominal_, origin()),
        solver_(commanded_, executing_, origin()) {}

  const KinematicModel& posted() const override { return solver_; }
  /// APT CL data, or a program of machine words X Y U V W read back through the nominal machine.
  std::unique_ptr<cl::Reader> open_reader(std::istream& in) const override {
    const TrrSolver& reading = reading_;
    return open_cl_reader(in, r_.input_name, r_.input_kind, r_.reader, reading.machine(), r_.setup,
                          [&reading](const AxisPosition& q, std::string* why) { return reading.pose(q, why); });
  }
  PostOptions options(const std::optional<double>& tolerance_mm) const override {
    PostOptions o = trr_post_options();
    if (tolerance_mm) o.subdivide = make_tolerance_subdivider(solver_, compensation(r_, *tolerance_mm), r_.dialect);
    return o;
  }
  const KinematicModel& before_commands() const override { return reading_; }
  std::unique_ptr<preview::BlockEvaluator> before_executed() const override {
    return std::make_unique<preview::TrrEvaluator>(executing_, origin());
  }

 private:
  const Vec3d& origin() const { return r_.setup.workpiece_origin_mm; }

  const PostRequest& r_;
  trr::Kinematics nominal_, commanded_, executing_;
  TrrSolver reading_;  ///< nominal commands, executed nominally
  TrrSolver solver_;   ///< the model's commands, executed on the machine the program runs on
};

class TrrPostMachine final : public PostMachine {
 public:
  TrrPostMachine(trr::Machine machine, std::optional<trr::Errors> model, std::optional<trr::Errors> verify_on)
      : machine_(std::move(machine)), model_(std::move(model)), verify_on_(std::move(verify_on)) {}

  const std::string& name() const override { return machine_.name; }
  std::string letters() const override { return "XYUVW"; }
  bool has_model() const override { return model_.has_value(); }
  bool has_verify_on() const override { return verify_on_.has_value(); }
  std::string refuses(const PostRequest& r) const override {
    if (r.rtcp) return "rtcp: the TRR-XY machine has no RTCP dialect (it is posted in X Y U V W)";
    if (r.tilted_plane) return "tilted_plane: the TRR-XY machine has no tilted work plane (no rotary axes)";
    return {};
  }
  std::vector<std::string> header(const PostRequest& r, const std::optional<double>& tolerance_mm) const override {
    const Vec3d& o = r.setup.workpiece_origin_mm;
    return {header_origin_line(r),
            fmt::format("machine {} ({}): TRR-XY, X Y table, U V W sliders of chains a b c", machine_.name,
                        r.machine_source),
            fmt::format("workpiece origin {:.4f} {:.4f} {:.4f} mm", o.x(), o.y(), o.z()),
            header_model_line(r, has_model(), tolerance_mm)};
  }
  std::unique_ptr<PostModels> models(const PostRequest& r, bool /*account*/) const override {
    return std::make_unique<TrrModels>(machine_, model_, verify_on_, r);
  }

 private:
  trr::Machine machine_;
  std::optional<trr::Errors> model_, verify_on_;
};

}  // namespace

std::shared_ptr<const PostMachine> trr_xy_post_machine(trr::Machine machine, std::optional<trr::Errors> model,
                                                       std::optional<trr::Errors> verify_on) {
  return std::make_shared<TrrPostMachine>(std::move(machine), std::move(model), std::move(verify_on));
}

}  // namespace ncpost
