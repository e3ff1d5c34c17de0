// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/post_request.hpp"

#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <stdexcept>

#include "ncpost/machines/input_error.hpp"
#include "ncpost/postproc/write/atomic_file.hpp"
#include "ncpost/postproc/write/nc_writer.hpp"
#include "ncpost/version.hpp"
#include "verify/post_account_fill.hpp"

namespace ncpost {

std::string header_origin_line(const PostRequest& r) {
  return fmt::format("ncpost {} from {}", ncpost::version_string, r.input_name);
}

std::string header_model_line(const PostRequest& r, bool has_model, const std::optional<double>& tolerance_mm) {
  const char* method = r.nonlinear == nonlinear::Method::harmonic ? "harmonic" : "adaptive";
  return fmt::format(
      "model {}, tolerance {}", has_model ? r.model_source : std::string("none (nominal machine)"),
      tolerance_mm ? fmt::format("{} mm ({}{})", *tolerance_mm, method, r.tolerance_is_default ? ", the default" : "")
                   : std::string("none"));
}

nonlinear::CompensationOptions compensation(const PostRequest& r, double tolerance_mm) {
  nonlinear::CompensationOptions c;
  c.method = r.nonlinear;
  c.tolerance_mm = tolerance_mm;
  return c;
}

std::string PostRequest::validate() const {
  if (!machine) return "no machine (serial_post_machine, trr_xy_post_machine)";
  if (const std::string why = machine->refuses(*this); !why.empty()) return why;
  if (tolerance_mm && !(*tolerance_mm > 0 && std::isfinite(*tolerance_mm)))
    return fmt::format("tolerance_mm: expected a finite number above 0, got {}", *tolerance_mm);
  if (!(retract_mm >= 0 && std::isfinite(retract_mm)))
    return fmt::format("retract_mm: expected 0 or more, got {}", retract_mm);
  if (threads < 1 || threads > 2) return fmt::format("threads: expected 1 or 2, got {}", threads);
  if (tilted_plane && rtcp) return "tilted_plane: not with rtcp (the tilted plane carries the tool tip itself)";
  return {};
}

namespace {

/// The "before" of the account: nominal commands, one block per CL motion, executed on the machine
/// the program runs on (post_account_fill.hpp), the input read again from `in` at `start`.
void measure_before(std::istream& in, std::istream::pos_type start, const PostRequest& r, const PostModels& models,
                    PostAccount& account) {
  in.clear();
  in.seekg(start);
  if (!in) throw InputError({r.input_name, 0, 0}, "cannot read the input again (the stream is not seekable)");
  auto reader = models.open_reader(in);
  const std::unique_ptr<preview::BlockEvaluator> executed = models.before_executed();
  detail::measure_before(*reader, models.before_commands(), *executed, r, account);
}

/// The post's options for the request: the kind's, then the request's; verified contour errors go into `acc`.
PostOptions post_options(const PostRequest& r, const std::optional<double>& tolerance_mm, bool account,
                         const PostModels& models, PostAccount& acc) {
  PostOptions options = models.options(tolerance_mm);
  options.tool_table = r.tool_table;
  options.retract_mm = r.retract_mm;
  options.branch_choice = r.branch_choice;
  options.verify = account;
  options.threads = r.threads;
  options.feed_mode = r.feed_mode;
  options.program_name = r.program_name;
  options.header_comments = r.machine->header(r, tolerance_mm);
  options.progress = r.progress.posting;
  options.feed_solver = models.feeds();
  if (account)
    options.on_verified = [&acc](int line, double contour_mm) {
      acc.after_series.add(line, contour_mm);
      acc.path.add_after(line, contour_mm);
    };
  return options;
}

/// Posts the records of `reader` to `program` (committed only when the whole program is written).
PostSummary write_program(cl::Reader& reader, std::ostream& program, const PostRequest& r, const PostModels& models,
                          const PostOptions& options, SolverData& data) {
  AtomicFile out(program);
  NcWriter writer(out, r.dialect, r.machine->letters());
  PostSummary summary;
  try {
    summary = post_program(reader, r.input_name, models.posted(), writer, options, data);
  } catch (const Infeasible& e) {  // what in the input most likely explains it (e.g. NX MSYS)
    const std::string hint = reader.failure_hint();
    if (hint.empty()) throw;
    throw Infeasible(std::string(e.what()) + "\n  " + hint);
  }
  if (!summary.verify.defects.empty()) {
    std::string list;
    for (const std::string& d : summary.verify.defects) list += "\n  " + d;
    throw VerifyFailed(
        fmt::format("{}: --verify: the written program does not do what the input means ({} defect{}); "
                    "no program is written:{}",
                    r.input_name, summary.verify.defects.size(), summary.verify.defects.size() == 1 ? "" : "s", list));
  }
  out.commit();  // flushes `program`
  return summary;
}

}  // namespace

PostResult post(std::istream& input, std::ostream& program, const PostRequest& r) {
  if (const std::string why = r.validate(); !why.empty()) throw std::invalid_argument("ncpost::post: " + why);
  // the control interpolates the tool tip under RTCP: no tolerance unless asked for
  std::optional<double> tolerance_mm = r.tolerance_mm;
  if (r.rtcp && r.tolerance_is_default) tolerance_mm.reset();
  const PostMachine& machine = *r.machine;
  const bool account = r.verify || machine.has_verify_on();

  const std::unique_ptr<PostModels> models = machine.models(r, account);
  const std::istream::pos_type start = input.tellg();
  auto reader = models->open_reader(input);

  PostResult result;
  PostAccount& acc = result.account;
  acc = detail::account_of(r, tolerance_mm);
  PostOptions options = post_options(r, tolerance_mm, account, *models, acc);
  for (std::string& note : reader->header_notes()) options.header_comments.push_back(std::move(note));
  SolverData data;  // the solver's working data on this thread (reversal state, figures)
  result.summary = write_program(*reader, program, r, *models, options, data);
  reader.reset();
  if (r.tilted_plane && !r.dialect.tilted_plane)
    result.summary.notices.push_back(fmt::format(
        "--tilted-plane: the {} dialect ({}) has no tilted work plane ([tilted_plane] native = false or absent): the "
        "3+2 runs are written with the machine's axes, as without the option",
        r.dialect.name, r.dialect.file));
  if (r.progress.posted) r.progress.posted(result.summary);
  detail::add_posted(acc, result.summary);
  models->add_figures(data, acc);
  if (account && !r.rtcp) {
    measure_before(input, start, r, *models, acc);
    if (r.progress.measured) r.progress.measured();
    result.verified = true;
  }
  return result;
}

}  // namespace ncpost
