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
#include "ncpost/postproc/trr_post.hpp"
#include "ncpost/postproc/trr_preview_html.hpp"
#include "ncpost/version.hpp"

namespace ncpost::cli {
namespace {

struct TrrJob {
  trr::Machine machine;
  Vec3d workpiece_origin_mm = Vec3d::Zero();
};

std::optional<TrrJob> load_trr_job(const JobOptions& o) {
  if (machine_file_kind(o.machine) != "trr-xy") return std::nullopt;
  TrrJob job;
  job.machine = load_trr_xy_machine(o.machine);
  job.workpiece_origin_mm = workpiece_origin_mm(o);
  if (o.tool_length_mm != 0.0)
    throw UsageError("--tool-length: the TRR-XY machine takes its tool offset from the machine file (tool_offset)");
  if (o.input_kind != "auto" && o.input_kind != "cl")
    throw UsageError("--input-kind: the TRR-XY machine posts APT CL data only");
  return job;
}

/// Opens the input file `path` into `in` and an APT reader on it, named `name` in messages
/// (InputError when it cannot be opened or is not APT CL data).
std::unique_ptr<cl::Reader> open_apt(std::ifstream& in, const std::string& path, const std::string& name,
                                     const JobOptions& o) {
  in.open(path, std::ios::binary);
  if (!in) throw InputError({name, 0, 0}, "cannot open the input file");
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  in.clear();
  in.seekg(0);
  if (o.input_kind != "cl" && !cl::looks_like_apt(head))
    throw InputError({name, 1, 1}, "expected APT CL data: G-code input is not supported on the TRR-XY machine");
  return std::make_unique<cl::AptReader>(in, name, reader_options(o));
}

trr::Kinematics kinematics_for(const TrrJob& job, const std::string& model) {
  trr::Errors e;
  if (!model.empty()) e = trr::read_errors_json(model);
  try {
    return trr::Kinematics(job.machine, e);
  } catch (const std::runtime_error& ex) {
    throw Infeasible(ex.what());
  }
}

}  // namespace

std::optional<int> post_if_trr_xy(const TrrPostRequest& a) {
  const std::optional<TrrJob> job = load_trr_job(a.job);
  if (!job) return std::nullopt;
  if (a.rtcp) throw UsageError("--rtcp: the TRR-XY machine has no RTCP dialect; it is posted in X Y U V W");
  if (!a.report.empty()) throw UsageError("--report: not available for the TRR-XY machine (use preview --html)");
  if (a.tolerance_mm && a.nonlinear == "harmonic")
    fmt::print(stderr, "notice: --nonlinear harmonic: the TRR-XY post meets the tolerance by adaptive insertion\n");
  if (!a.verify_on.empty()) throw UsageError("--verify-on: not available for the TRR-XY machine (--verify runs on --model)");
  Dialect dialect;
  try {
    dialect = dialect_named(a.dialect);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--dialect: ") + e.what());
  }
  const trr::Kinematics k = kinematics_for(*job, a.model);
  std::ifstream in;
  auto reader = open_apt(in, a.input_path, a.input, a.job);

  trr::PostOptions o;
  o.workpiece_origin_mm = job->workpiece_origin_mm;
  o.tolerance_mm = a.tolerance_mm;
  o.verify = a.verify;
  o.program_name = "NCPOST";
  o.header_comments = {
      fmt::format("ncpost {} from {}", ncpost::version_string, a.input),
      fmt::format("machine {} ({}): TRR-XY, X Y table, U V W sliders of chains a b c", job->machine.name, a.job.machine),
      fmt::format("workpiece origin {:.4f} {:.4f} {:.4f} mm", o.workpiece_origin_mm.x(), o.workpiece_origin_mm.y(),
                  o.workpiece_origin_mm.z()),
      fmt::format("model {}, tolerance {}", a.model.empty() ? "none (nominal machine)" : a.model,
                  a.tolerance_mm ? fmt::format("{} mm", *a.tolerance_mm) : std::string("none"))};
  AtomicFile out(a.output);
  NcWriter writer(out, dialect, "XYUVW");
  trr::PostSummary s;
  try {
    s = trr::post_program(*reader, a.input, k, writer, o);
  } catch (const std::runtime_error& e) {
    if (dynamic_cast<const InputError*>(&e) || dynamic_cast<const Infeasible*>(&e)) throw;
    throw Infeasible(e.what());
  }
  out.commit();
  for (const auto& n : s.notices) fmt::print(stderr, "notice: {}\n", n);
  if (a.output != "-")
    fmt::print(stderr, "ncpost post: {} CL motions -> {} blocks in {}{}\n", s.motions_in, s.blocks_out, a.output,
               a.tolerance_mm ? fmt::format(" ({} inserted; largest block error {:.4f} mm)", s.blocks_inserted,
                                            s.max_block_error_mm)
                              : std::string());
  if (a.verify) {
    const VerifyReport& v = s.verify;
    fmt::print(stderr, "verify: {} blocks re-executed; largest contour error {:.4f} mm (CL line {}), orientation {:.4f} deg, "
               "block-end error {:.4f} mm\n", v.blocks, v.max_contour_mm, v.worst_line, rad_to_deg(v.max_orientation_rad),
               v.max_endpoint_mm);
  }
  return 0;
}

std::optional<int> preview_if_trr_xy(const TrrPreviewRequest& a) {
  const std::optional<TrrJob> job = load_trr_job(a.job);
  if (!job) return std::nullopt;
  const trr::Kinematics k = kinematics_for(*job, a.model);
  std::ifstream in;
  auto reader = open_apt(in, a.input_path, a.input, a.job);

  // the program as posted without a tolerance (one block per CL motion), written nowhere
  trr::PostOptions o;
  o.workpiece_origin_mm = job->workpiece_origin_mm;
  AtomicFile sink((std::filesystem::temp_directory_path() / "ncpost-trr-preview.nc").string());  // never committed
  NcWriter writer(sink, dialect_named("fanuc"), "XYUVW");
  std::optional<AtomicFile> csv_file;
  if (!a.csv.empty()) {
    csv_file.emplace(a.csv);
    csv_file->write(preview::kCsvHeader);
  }
  const trr::BlockEvaluator evaluator(k, o.workpiece_origin_mm);
  std::size_t blocks = 0, over = 0;
  double worst = 0.0, sum = 0.0, worst_orientation = 0.0;
  int worst_line = 0;
  std::size_t worst_block = 0;
  trr::PostSummary s;
  trr::PreviewReport report;
  try {
    s = trr::post_program(*reader, a.input, k, writer, o, [&](const trr::PostedBlock& pb) {
      if (pb.rapid) return;
      const trr::BlockError e = evaluator.evaluate(pb.block);
      ++blocks;
      if (!a.html.empty())
        report.rows.push_back({blocks, pb.line, e.max_mm, e.at_t, e.midpoint_mm, e.orientation_rad,
                               pb.block.from_cl.tip_mm, pb.block.to_cl.tip_mm});
      sum += e.max_mm;
      if (e.max_mm > 0.005) ++over;
      if (e.max_mm > worst) {
        worst = e.max_mm;
        worst_line = pb.line;
        worst_block = blocks;
      }
      worst_orientation = std::max(worst_orientation, e.orientation_rad);
      if (csv_file)
        csv_file->write(fmt::format("{},{},{:.6f},{:.4f},{:.6f},{:.6f},{:.4f},{:.6f}\n", blocks, pb.line, e.max_mm, e.at_t,
                                    e.midpoint_mm, rad_to_deg(e.orientation_rad), e.orientation_at_t,
                                    e.harmonic_residual_mm));
    });
  } catch (const std::runtime_error& e) {
    if (dynamic_cast<const InputError*>(&e) || dynamic_cast<const Infeasible*>(&e)) throw;
    throw Infeasible(e.what());
  }
  if (!a.html.empty()) {
    report.input_name = a.input;
    report.machine_name = fmt::format("{} ({})", job->machine.name, a.job.machine);
    report.model_name = a.model;
    report.inputs.push_back({"CL input", a.input_path, a.input});
    report.inputs.push_back({"machine file", a.job.machine});
    if (!a.model.empty()) report.inputs.push_back({"error model", a.model});
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
