// SPDX-License-Identifier: Apache-2.0
#include "trr_post_request.hpp"
#include "verify/post_account_fill.hpp"

#include <fmt/format.h>


#include "ncpost/kinematics/trr_xy_forward.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/postproc/read/apt/apt_reader.hpp"
#include "ncpost/postproc/write/atomic_file.hpp"
#include "ncpost/postproc/write/nc_writer.hpp"
#include "ncpost/postproc/solve/trr_solver.hpp"
#include "ncpost/postproc/solve/trr_preview_evaluator.hpp"
#include "ncpost/postproc/solve/trr_subdivider.hpp"
#include "ncpost/version.hpp"

namespace ncpost::detail {
namespace {

trr::Kinematics kinematics(const trr::Machine& m, const std::optional<trr::Errors>& e) {
  try {
    return trr::Kinematics(m, e.value_or(trr::Errors{}));
  } catch (const std::runtime_error& ex) {
    throw Infeasible(ex.what());
  }
}

/// The reader of `in` from where it stands: APT CL data, or a program of machine words X Y U V W
/// read back through the nominal forward kinematics (`nominal`, which must outlive the reader).
std::unique_ptr<cl::Reader> open_input(std::istream& in, const PostRequest& r, const TrrSolver& nominal) {
  return open_cl_reader(in, r.input_name, r.input_kind, r.reader, nominal.machine(), r.setup,
                        [&nominal](const AxisPosition& q, std::string* why) { return nominal.pose(q, why); });
}

std::vector<std::string> header_comments(const PostRequest& r, const TrrJob& job) {
  const Vec3d& o = r.setup.workpiece_origin_mm;
  return {fmt::format("ncpost {} from {}", ncpost::version_string, r.input_name),
          fmt::format("machine {} ({}): TRR-XY, X Y table, U V W sliders of chains a b c", job.machine.name,
                      r.machine_source),
          fmt::format("workpiece origin {:.4f} {:.4f} {:.4f} mm", o.x(), o.y(), o.z()),
          fmt::format("model {}, tolerance {}", job.model ? r.model_source : std::string("none (nominal machine)"),
                      r.tolerance_mm ? fmt::format("{} mm ({}{})", *r.tolerance_mm,
                                                   r.nonlinear == nonlinear::Method::harmonic ? "harmonic" : "adaptive",
                                                   r.tolerance_is_default ? ", the default" : "")
                                     : std::string("none"))};
}

PostOptions trr_options(const PostRequest& r) {
  PostOptions o = trr_post_options();
  o.feed_mode = r.feed_mode;
  o.threads = r.threads;
  o.retract_mm = r.retract_mm;
  o.branch_choice = r.branch_choice;
  o.program_name = r.program_name;
  return o;
}

/// The "before" of the account: nominal commands, one block per CL motion, executed on `executing`
/// (the common measure, post_account_fill.hpp: its figures and the path map of the report).
void measure_before(std::istream& in, std::istream::pos_type start, const PostRequest& r, const trr::Kinematics& nominal,
                    const trr::Kinematics& executing, PostAccount& account) {
  in.clear();
  in.seekg(start);
  if (!in) throw InputError({r.input_name, 0, 0}, "cannot read the input again (the stream is not seekable)");
  const TrrSolver commands(nominal, nominal, r.setup.workpiece_origin_mm);
  auto reader = open_input(in, r, commands);
  const preview::TrrEvaluator executed(executing, r.setup.workpiece_origin_mm);
  detail::measure_before(*reader, commands, executed, r, account);
}

}  // namespace

PostResult post_trr(std::istream& input, std::ostream& program, const PostRequest& r) {
  const TrrJob& job = *r.trr;
  const bool account = r.verify || job.verify_on.has_value();
  const trr::Kinematics nominal = kinematics(job.machine, std::nullopt);
  const trr::Kinematics commanded = kinematics(job.machine, job.model);
  const trr::Kinematics executing = kinematics(job.machine, job.verify_on ? job.verify_on : job.model);
  const std::istream::pos_type start = input.tellg();
  const TrrSolver reading(nominal, nominal, r.setup.workpiece_origin_mm);
  auto reader = open_input(input, r, reading);
  const TrrSolver solver(commanded, executing, r.setup.workpiece_origin_mm);

  PostResult result;
  PostAccount& acc = result.account;
  acc = account_of(r, job.machine.name, job.model.has_value(), job.verify_on.has_value(), r.tolerance_mm);

  PostOptions options = trr_options(r);
  options.verify = account;
  options.header_comments = header_comments(r, job);
  options.progress = r.progress.posting;
  if (account) options.on_verified = [&acc](int line, double contour_mm) { acc.after_series.add(line, contour_mm); };
  if (r.tolerance_mm) options.subdivide = make_trr_subdivider(solver, r.dialect, TrrSubdivision{*r.tolerance_mm, r.nonlinear});

  AtomicFile out(program);
  NcWriter writer(out, r.dialect, "XYUVW");
  result.summary = post_program(*reader, r.input_name, solver, writer, options);
  out.commit();
  reader.reset();
  if (r.progress.posted) r.progress.posted(result.summary);
  add_posted(acc, result.summary);
  if (account) {
    measure_before(input, start, r, nominal, executing, acc);
    if (r.progress.measured) r.progress.measured();
    result.verified = true;
  }
  return result;
}

}  // namespace ncpost::detail
