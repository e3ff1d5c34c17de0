// SPDX-License-Identifier: Apache-2.0
// The TRR-XY paths of `ncpost post` and `ncpost preview`.
#include "trr_commands.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "ncpost/compensation/trr_model.hpp"
#include "ncpost/machines/trr_xy_file.hpp"
#include "ncpost/postproc/apt_reader.hpp"
#include "ncpost/postproc/atomic_file.hpp"
#include "ncpost/postproc/preview_csv.hpp"
#include "ncpost/compensation/trr_block_error.hpp"
#include "ncpost/postproc/nc_writer.hpp"
#include "ncpost/postproc/post.hpp"
#include "ncpost/postproc/trr_solver.hpp"
#include "ncpost/postproc/trr_subdivider.hpp"
#include "ncpost/postproc/trr_preview_html.hpp"
#include "ncpost/version.hpp"

namespace ncpost::cli {
namespace {

struct TrrPreviewJob {
  trr::Machine machine;
  Vec3d workpiece_origin_mm = Vec3d::Zero();
};

std::optional<TrrPreviewJob> load_trr_job(const JobOptions& o) {
  if (machine_file_kind(o.machine) != "trr-xy") return std::nullopt;
  TrrPreviewJob job;
  job.machine = load_trr_xy_machine(o.machine);
  job.workpiece_origin_mm = workpiece_origin_mm(o);
  if (o.tool_length_mm != 0.0)
    throw UsageError("--tool-length: the TRR-XY machine takes its tool offset from the machine file (tool_offset)");
  if (o.input_kind == "rtcp")
    throw UsageError("--input-kind rtcp: the TRR-XY machine has no RTCP programs (its G-code input is X Y U V W)");
  return job;
}

/// Opens the input file `path` into `in` and its reader, named `name` in messages (InputError when
/// it cannot be opened): APT CL data, or a program of the words X Y U V W read back through the
/// nominal machine `reading` (which must outlive the reader).
std::unique_ptr<cl::Reader> open_input(std::ifstream& in, const std::string& path, const std::string& name,
                                       const JobOptions& o, const TrrSolver& reading) {
  in.open(path, std::ios::binary);
  if (!in) throw InputError({name, 0, 0}, "cannot open the input file");
  return open_cl_reader(in, name, input_kind_named(o.input_kind), reader_options(o), reading.machine(), Setup{},
                        [&reading](const AxisPosition& q, std::string* why) { return reading.pose(q, why); });
}

trr::Kinematics kinematics_for(const TrrPreviewJob& job, const std::string& model) {
  trr::Errors e;
  if (!model.empty()) e = trr::read_errors_json(model);
  try {
    return trr::Kinematics(job.machine, e);
  } catch (const std::runtime_error& ex) {
    throw Infeasible(ex.what());
  }
}

}  // namespace

TrrJob load_trr_post_job(const JobOptions& o, const std::string& model, const std::string& verify_on, bool rtcp) {
  if (rtcp) throw UsageError("--rtcp: the TRR-XY machine has no RTCP dialect; it is posted in X Y U V W");
  if (o.tool_length_mm != 0.0)
    throw UsageError("--tool-length: the TRR-XY machine takes its tool offset from the machine file (tool_offset)");
  if (o.input_kind == "rtcp")
    throw UsageError("--input-kind rtcp: the TRR-XY machine has no RTCP programs (its G-code input is X Y U V W)");
  TrrJob job;
  job.machine = load_trr_xy_machine(o.machine);
  if (!model.empty()) job.model = trr::read_errors_json(model);
  if (!verify_on.empty()) job.verify_on = trr::read_errors_json(verify_on);
  return job;
}

std::optional<int> preview_if_trr_xy(const TrrPreviewRequest& a) {
  const std::optional<TrrPreviewJob> job = load_trr_job(a.job);
  if (!job) return std::nullopt;
  const trr::Kinematics k = kinematics_for(*job, a.model);
  const trr::Kinematics nominal(job->machine);
  const TrrSolver reading(nominal, nominal, job->workpiece_origin_mm);
  std::ifstream in;
  auto reader = open_input(in, a.input_path, a.input, a.job, reading);

  // the program as posted without a tolerance (one block per CL motion), written nowhere
  const TrrSolver solver(k, k, job->workpiece_origin_mm);
  PostOptions o = trr_post_options();
  AtomicFile sink((std::filesystem::temp_directory_path() / "ncpost-trr-preview.nc").string());  // never committed
  NcWriter writer(sink, dialect_named("fanuc"), "XYUVW");
  std::optional<AtomicFile> csv_file;
  if (!a.csv.empty()) {
    csv_file.emplace(a.csv);
    csv_file->write(preview::kCsvHeader);
  }
  const trr::BlockEvaluator evaluator(k, job->workpiece_origin_mm);
  trr::EvaluatorWork work;
  std::size_t blocks = 0, over = 0;
  double worst = 0.0, sum = 0.0, worst_orientation = 0.0;
  int worst_line = 0;
  std::size_t worst_block = 0;
  PostSummary s;
  trr::PreviewReport report;
  o.on_block = [&](const WrittenBlock& wb) {
    if (wb.rapid) return;
    const trr::Block block{wb.from_cl, wb.to_cl, trr_command(wb.from), trr_command(wb.to)};
    const trr::BlockError e = evaluator.evaluate(block, work);
    ++blocks;
    if (!a.html.empty())
      report.rows.push_back({blocks, wb.line, e.max_mm, e.at_t, e.midpoint_mm, e.orientation_rad, wb.from_cl.tip_mm,
                             wb.to_cl.tip_mm});
    sum += e.max_mm;
    if (e.max_mm > 0.005) ++over;
    if (e.max_mm > worst) {
      worst = e.max_mm;
      worst_line = wb.line;
      worst_block = blocks;
    }
    worst_orientation = std::max(worst_orientation, e.orientation_rad);
    if (csv_file)
      csv_file->write(fmt::format("{},{},{:.6f},{:.4f},{:.6f},{:.6f},{:.4f},{:.6f}\n", blocks, wb.line, e.max_mm, e.at_t,
                                  e.midpoint_mm, rad_to_deg(e.orientation_rad), e.orientation_at_t,
                                  e.harmonic_residual_mm));
  };
  try {
    s = post_program(*reader, a.input, solver, writer, o);
  } catch (const std::runtime_error& e) {
    if (dynamic_cast<const InputError*>(&e) || dynamic_cast<const Infeasible*>(&e)) throw;
    throw Infeasible(e.what());
  }
  if (!a.html.empty()) {
    report.input_name = a.input;
    report.machine_name = fmt::format("{} ({})", job->machine.name, a.job.machine);
    report.model_name = a.model;
    report.motions = s.motions_in;
    write_file_atomically(a.html, trr::preview_html(report));
  }
  if (csv_file) csv_file->commit();
  for (const auto& n : s.notices) fmt::print(stderr, "notice: {}\n", n);
  fmt::print("{} CL motions, {} blocks previewed; largest nonlinear error {:.4f} mm (block {}, CL line {}), mean {:.4f} mm, "
             "largest orientation error {:.4f} deg; blocks over 5 µm: {}\n",
             s.motions_in, blocks, worst, worst_block, worst_line, blocks ? sum / static_cast<double>(blocks) : 0.0,
             rad_to_deg(worst_orientation), over);
  return 0;
}

}  // namespace ncpost::cli
