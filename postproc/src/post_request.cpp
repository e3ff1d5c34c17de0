// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/post_request.hpp"

#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <stdexcept>

#include "ncpost/compensation/machine_model.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/postproc/solve/actual_solver.hpp"
#include "ncpost/postproc/write/atomic_file.hpp"
#include "ncpost/postproc/solve/executed_on.hpp"
#include "ncpost/postproc/write/nc_writer.hpp"
#include "ncpost/postproc/verify/preview_blocks.hpp"
#include "ncpost/version.hpp"
#include "verify/post_account_fill.hpp"
#include "trr_post_request.hpp"

namespace ncpost {
namespace {

const char* method_word(nonlinear::Method m) { return m == nonlinear::Method::harmonic ? "harmonic" : "adaptive"; }

/// The "before" of the account: the program with nominal commands, one block per CL motion,
/// executed on the job's machine (the model's, or the nominal one), read again from `in` at `start`.
void measure_before(std::istream& in, std::istream::pos_type start, const PostRequest& r,
                    const comp::MachineModel* model, PostAccount& account) {
  in.clear();
  in.seekg(start);
  if (!in) throw InputError({r.input_name, 0, 0}, "cannot read the input again (the stream is not seekable)");
  auto reader = open_cl_reader(in, r.input_name, r.input_kind, r.reader, r.machine, r.setup);
  const NominalSolver nominal(r.machine, r.setup);
  std::unique_ptr<preview::BlockEvaluator> evaluator;
  if (model)
    evaluator = std::make_unique<preview::ModelEvaluator<comp::ErrorFunctor<double>>>(model->machine(), r.setup,
                                                                                       model->errors());
  else
    evaluator = std::make_unique<preview::ModelEvaluator<NominalErrors>>(r.machine, r.setup);
  detail::measure_before(*reader, nominal, *evaluator, r, account);
}

std::vector<std::string> header_comments(const PostRequest& r, const std::optional<double>& tolerance_mm) {
  const Vec3d& o = r.setup.workpiece_origin_mm;
  return {fmt::format("ncpost {} from {}", ncpost::version_string, r.input_name),
          fmt::format("machine {} ({})", r.machine.name, r.machine_source),
          fmt::format("workpiece origin {:.4f} {:.4f} {:.4f} mm, tool length {:.4f} mm", o.x(), o.y(), o.z(),
                      r.setup.tool_length_mm),
          fmt::format("model {}, tolerance {}", r.model ? r.model_source : std::string("none (nominal machine)"),
                      tolerance_mm ? fmt::format("{} mm ({}{})", *tolerance_mm, method_word(r.nonlinear),
                                                 r.tolerance_is_default ? ", the default" : "")
                                   : std::string("none")),
          r.rtcp ? std::string("RTCP: tool tip in the workpiece frame") : std::string("machine axes, no RTCP")};
}

}  // namespace

std::string PostRequest::validate() const {
  if (machine.axes.empty() && !trr) return "no machine (load_machine)";
  if (trr && rtcp) return "rtcp: the TRR-XY machine has no RTCP dialect (it is posted in X Y U V W)";
  if (trr && tilted_plane) return "tilted_plane: the TRR-XY machine has no tilted work plane (no rotary axes)";
  if (tolerance_mm && !(*tolerance_mm > 0 && std::isfinite(*tolerance_mm)))
    return fmt::format("tolerance_mm: expected a finite number above 0, got {}", *tolerance_mm);
  if (!(retract_mm >= 0 && std::isfinite(retract_mm))) return fmt::format("retract_mm: expected 0 or more, got {}", retract_mm);
  if (threads < 1 || threads > 2) return fmt::format("threads: expected 1 or 2, got {}", threads);
  if (tilted_plane && rtcp) return "tilted_plane: not with rtcp (the tilted plane carries the tool tip itself)";
  if (tilted_plane && model)
    return "tilted_plane: not with a model (the control maps the plane's coordinates on its nominal kinematics, so "
           "the compensation cannot be carried)";
  return {};
}

namespace {

/// The solver the program is posted with: the actual machine (error model) or the nominal one.
struct PostSolver {
  std::unique_ptr<comp::MachineModel> model;
  std::unique_ptr<KinematicModel> solver;
  const ActualSolver* actual = nullptr;  ///< the solver, when it carries an error model
};

PostSolver make_post_solver(const PostRequest& r, bool account) {
  PostSolver p;
  if (!r.model) {
    p.solver = std::make_unique<NominalSolver>(r.machine, r.setup);
    return p;
  }
  p.model = std::make_unique<comp::MachineModel>(r.machine, *r.model);
  auto s = std::make_unique<ActualSolver>(*p.model, r.setup);
  s->set_measure_uncompensated(account);  // the uncompensated error of each CL point, when reported
  p.actual = s.get();
  p.solver = std::move(s);
  return p;
}

/// The post's options for the request; verified contour errors go into `acc`.
PostOptions post_options(const PostRequest& r, const std::optional<double>& tolerance_mm, bool account,
                         const PostSolver& p, PostAccount& acc) {
  PostOptions options;
  options.rtcp = r.rtcp;
  options.tool_length_mm = r.setup.tool_length_mm;
  options.tool_table = r.tool_table;
  options.retract_mm = r.retract_mm;
  options.branch_choice = r.branch_choice;
  options.native_arcs = !r.model;  // the actual machine would not follow the control's circle
  options.native_cycles = !r.model;
  options.tilted_plane = r.tilted_plane;
  options.verify = account;
  options.threads = r.threads;
  options.feed_mode = r.feed_mode;
  options.program_name = r.program_name;
  options.header_comments = header_comments(r, tolerance_mm);
  options.progress = r.progress.posting;
  if (account)
    options.on_verified = [&acc](int line, double contour_mm) {
      acc.after_series.add(line, contour_mm);
      acc.path.add_after(line, contour_mm);
    };
  if (tolerance_mm) {
    nonlinear::CompensationOptions comp;
    comp.method = r.nonlinear;
    comp.tolerance_mm = *tolerance_mm;
    options.take_up_reversal = true;
    options.subdivide = make_tolerance_subdivider(r.machine, r.setup, *p.solver, p.actual, comp, r.dialect, r.input_name);
  }
  return options;
}

/// Posts the records of `reader` to `program` (committed only when the whole program is written).
PostSummary write_program(cl::Reader& reader, std::ostream& program, const PostRequest& r, const PostSolver& p,
                          const comp::MachineModel* executing, const PostOptions& options, SolverData& data) {
  AtomicFile out(program);
  NcWriter writer(out, r.dialect, axis_letters(r.machine));
  std::optional<ExecutedOn> verify_solver;
  if (executing) verify_solver.emplace(*p.solver, *executing, r.setup);
  // the program's G93 times on the nominal kinematics: the machine's errors change a block's path
  // length by far less than the F word's resolution, the nominal chain is several times cheaper to
  // evaluate than the error model, and the times never depend on a verifying machine
  const NominalSolver nominal(r.machine, r.setup);
  PostOptions with_feeds = options;
  with_feeds.feed_solver = &nominal;
  PostSummary summary;
  try {
    summary = post_program(reader, r.input_name,
                           verify_solver ? static_cast<const KinematicModel&>(*verify_solver) : *p.solver, writer,
                           with_feeds, data);
  } catch (const Infeasible& e) {  // what in the input most likely explains it (e.g. NX MSYS)
    const std::string hint = reader.failure_hint();
    if (hint.empty()) throw;
    throw Infeasible(std::string(e.what()) + "\n  " + hint);
  }
  if (!summary.verify.defects.empty()) {
    std::string list;
    for (const std::string& d : summary.verify.defects) list += "\n  " + d;
    throw VerifyFailed(fmt::format("{}: --verify: the written program does not do what the input means ({} defect{}); "
                                   "no program is written:{}", r.input_name, summary.verify.defects.size(),
                                   summary.verify.defects.size() == 1 ? "" : "s", list));
  }
  out.commit();  // flushes `program`
  return summary;
}

}  // namespace

PostResult post(std::istream& input, std::ostream& program, const PostRequest& r) {
  if (const std::string why = r.validate(); !why.empty()) throw std::invalid_argument("ncpost::post: " + why);
  if (r.trr) return detail::post_trr(input, program, r);
  // the control interpolates the tool tip under RTCP: no tolerance unless asked for
  std::optional<double> tolerance_mm = r.tolerance_mm;
  if (r.rtcp && r.tolerance_is_default) tolerance_mm.reset();
  const bool account = r.verify || r.verify_on.has_value();

  const PostSolver p = make_post_solver(r, account);
  std::unique_ptr<comp::MachineModel> executing;  // the machine the program is re-executed on
  if (r.verify_on) executing = std::make_unique<comp::MachineModel>(r.machine, *r.verify_on);
  const std::istream::pos_type start = input.tellg();
  auto reader = open_cl_reader(input, r.input_name, r.input_kind, r.reader, r.machine, r.setup);

  PostResult result;
  PostAccount& acc = result.account;
  acc = detail::account_of(r, r.machine.name, r.model.has_value(), r.verify_on.has_value(), tolerance_mm);
  PostOptions options = post_options(r, tolerance_mm, account, p, acc);
  for (std::string& note : reader->header_notes()) options.header_comments.push_back(std::move(note));
  SolverData data;  // the solver's working data on this thread (reversal state, figures)
  result.summary = write_program(*reader, program, r, p, executing.get(), options, data);
  reader.reset();
  if (r.tilted_plane && !r.dialect.tilted_plane)
    result.summary.notices.push_back(fmt::format(
        "--tilted-plane: the {} dialect ({}) has no tilted work plane ([tilted_plane] native = false or absent): the "
        "3+2 runs are written with the machine's axes, as without the option", r.dialect.name, r.dialect.file));
  if (r.progress.posted) r.progress.posted(result.summary);
  detail::add_posted(acc, result.summary);
  if (p.actual) {
    acc.uncompensated_tip_max_mm = data.uncompensated.max_mm;
    acc.uncompensated_tip_rms_mm = data.uncompensated.rms_mm();
  }
  if (account && !r.rtcp) {
    measure_before(input, start, r, executing ? executing.get() : p.model.get(), acc);
    if (r.progress.measured) r.progress.measured();
    result.verified = true;
  }
  return result;
}

}  // namespace ncpost
