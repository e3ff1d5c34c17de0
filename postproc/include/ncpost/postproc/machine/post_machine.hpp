// SPDX-License-Identifier: Apache-2.0
#pragma once
// The machine a post runs on, of any kind (a serial chain: serial_post_machine.hpp; the TRR-XY
// machine: trr_xy_post_machine.hpp): the machine with the errors of `--model` (the program
// compensates them) and of `--verify-on` (the program is re-executed there). `post()`
// (post_request.hpp) is one driver for every kind; it asks the machine only for what differs
// between kinds, through PostModels: the kinematic models of the run (kinematic_model.hpp), the
// reader of the input in the machine's words, the post's options of the kind (its subdivider
// among them) and the machine of the "before". Units: mm and rad; CL in W.
#include <istream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ncpost/compensation/nonlinear_compensation.hpp"
#include "ncpost/kinematics/kinematic_model.hpp"
#include "ncpost/postproc/post.hpp"
#include "ncpost/postproc/read/cl_record.hpp"
#include "ncpost/postproc/verify/post_report.hpp"
#include "ncpost/postproc/verify/preview_blocks.hpp"

namespace ncpost {

struct PostRequest;

/// The kinematic models one run of post() uses, made for the request (its setup, its dialect).
class PostModels {
 public:
  virtual ~PostModels() = default;
  /// The model the program is posted with: its commands (nominal, or compensating the model's
  /// errors), executed on the machine the program runs on (that of `--verify-on`, else the same).
  virtual const KinematicModel& posted() const = 0;
  /// The model of the G93 block times (nullptr: posted()).
  virtual const KinematicModel* feeds() const { return nullptr; }
  /// The reader of `in` from where it stands: CL data, or G-code in the machine's words read back
  /// through its nominal forward kinematics.
  virtual std::unique_ptr<cl::Reader> open_reader(std::istream& in) const = 0;
  /// The post's options of this kind for a run with this tolerance (nullopt: one block per CL
  /// motion): rtcp, tool length, native arcs and cycles, the subdivider. The request's own options
  /// (feeds, threads, header, verification) are set by post().
  virtual PostOptions options(const std::optional<double>& tolerance_mm) const = 0;
  /// The "before": the nominal commands of the plain post ...
  virtual const KinematicModel& before_commands() const = 0;
  /// ... executed on the machine the program runs on.
  virtual std::unique_ptr<preview::BlockEvaluator> before_executed() const = 0;
  /// The figures of the posted solver (the uncompensated tip error of a model's commands) into
  /// the account, from the post's solver data.
  virtual void add_figures(const SolverData& /*data*/, PostAccount& /*account*/) const {}
};

/// A machine with its models (immutable; shared by copies of a PostRequest).
class PostMachine {
 public:
  virtual ~PostMachine() = default;
  virtual const std::string& name() const = 0;
  /// The axis words of the program, e.g. "XYZAC" or "XYUVW".
  virtual std::string letters() const = 0;
  virtual bool has_model() const = 0;      ///< the program compensates the errors of `--model`
  virtual bool has_verify_on() const = 0;  ///< it is re-executed on the machine of `--verify-on`
  /// Empty when `r` can run on this machine, else why not (options the kind cannot take).
  virtual std::string refuses(const PostRequest& r) const = 0;
  /// The program header's comments (PostRequest's names, the setup, the tolerance `tolerance_mm`).
  virtual std::vector<std::string> header(const PostRequest& r, const std::optional<double>& tolerance_mm) const = 0;
  /// The models of one run of `r` (Infeasible when the machine's kinematics cannot be built).
  virtual std::unique_ptr<PostModels> models(const PostRequest& r, bool account) const = 0;
};

/// The nonlinear-error options of `r` with this tolerance (every kind's subdivider takes them).
nonlinear::CompensationOptions compensation(const PostRequest& r, double tolerance_mm);

/// The header's first comment ("ncpost VERSION from INPUT") and its model and tolerance line, the
/// same on every machine.
std::string header_origin_line(const PostRequest& r);
std::string header_model_line(const PostRequest& r, bool has_model, const std::optional<double>& tolerance_mm);

}  // namespace ncpost
