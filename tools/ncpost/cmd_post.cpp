// ncpost post: CL data or G-code in, NC program out (spec/cli.md).
#include <fmt/format.h>
#include <unistd.h>

#include <fstream>

#include "commands.hpp"
#include "input_options.hpp"
#include "trr_commands.hpp"
#include "ncpost/postproc/apt_reader.hpp"
#include "ncpost/postproc/post.hpp"

namespace ncpost::cli {
namespace {

struct PostArgs {
  JobOptions job;
  std::string model;
  std::optional<double> tolerance_mm;
  std::string nonlinear = "adaptive";
  bool rtcp = false;
  std::string dialect = "fanuc";
  std::string feed_mode = "auto";
  bool verify = false;
  std::string report;
  std::string output = "-";
  std::string input;
};

int run_post(const PostArgs& a) {
  if (auto rc = post_if_trr_xy({a.job, a.model, a.tolerance_mm, a.rtcp, a.dialect, a.verify, a.report, a.output, a.input})) return *rc;
  if (!a.model.empty()) throw UsageError("--model: compensated posting is not built yet (issue 5)");
  if (a.tolerance_mm) throw UsageError("--tolerance: nonlinear-error compensation is not built yet (issue 4)");
  if (!a.report.empty()) throw UsageError("--report: the post report is not built yet (issue 4)");
  Dialect dialect;
  try {
    dialect = dialect_named(a.dialect);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--dialect: ") + e.what());
  }
  const LoadedJob job = load_job(a.job);
  std::ifstream in(a.input, std::ios::binary);
  if (!in) throw InputError({a.input, 0, 0}, "cannot open the input file");
  auto reader = open_cl_reader(in, a.input, a.job, job);

  PostOptions options;
  options.rtcp = a.rtcp;
  options.verify = a.verify;
  options.feed_mode = a.feed_mode == "g93" ? PostOptions::FeedMode::inverse_time
                    : a.feed_mode == "g94" ? PostOptions::FeedMode::per_minute
                                           : PostOptions::FeedMode::automatic;
  options.program_name = "NCPOST";
  options.header_comments = {
      fmt::format("ncpost 0.1.0 from {}", a.input),
      fmt::format("machine {} ({})", job.machine.name, a.job.machine),
      fmt::format("workpiece origin {:.4f} {:.4f} {:.4f} mm, tool length {:.4f} mm", job.setup.workpiece_origin_mm.x(),
                  job.setup.workpiece_origin_mm.y(), job.setup.workpiece_origin_mm.z(), job.setup.tool_length_mm),
      fmt::format("model {}, tolerance {}", a.model.empty() ? "none (nominal machine)" : a.model,
                  a.tolerance_mm ? fmt::format("{} mm", *a.tolerance_mm) : std::string("none")),
      a.rtcp ? std::string("RTCP: tool tip in the workpiece frame") : std::string("machine axes, no RTCP")};
  const bool tty = ::isatty(STDERR_FILENO) && a.output != "-";
  if (tty) options.progress = [](std::size_t n) { fmt::print(stderr, "\rposting: {} motions", n); };

  NominalSolver solver(job.machine, job.setup);
  AtomicFile out(a.output);
  NcWriter writer(out, dialect, axis_letters(job.machine));
  const PostSummary summary = post_program(*reader, a.input, solver, writer, options);
  out.commit();
  if (tty) fmt::print(stderr, "\r");
  for (const auto& n : summary.notices) fmt::print(stderr, "notice: {}\n", n);
  if (a.output != "-")
    fmt::print(stderr, "ncpost post: {} CL motions -> {} blocks in {}\n", summary.motions_in, summary.blocks_out, a.output);
  if (a.verify) {
    const VerifyReport& v = summary.verify;
    fmt::print(stderr, "verify: {} blocks re-executed; largest contour error {:.4f} mm (CL line {}), orientation {:.4f} deg, "
               "block-end error {:.4f} mm\n", v.blocks, v.max_contour_mm, v.worst_line, rad_to_deg(v.max_orientation_rad),
               v.max_endpoint_mm);
  }
  return 0;
}

}  // namespace

void add_post(CLI::App& app, Action& action) {
  auto a = std::make_shared<PostArgs>();
  CLI::App* sub = app.add_subcommand("post", "Post-process CL data (APT) or G-code into an NC program");
  add_job_options(*sub, a->job);
  sub->add_option("--model", a->model, "Error model JSON (identify): compensate the machine's geometric errors");
  sub->add_option("--tolerance", a->tolerance_mm, "Bound the nonlinear error of every block (mm, in W)")->check(CLI::PositiveNumber);
  sub->add_option("--nonlinear", a->nonlinear, "Nonlinear-error compensation method")->check(CLI::IsMember({"adaptive", "harmonic"}));
  sub->add_flag("--rtcp", a->rtcp, "Write tool-tip coordinates with rotary angles for a control with RTCP/TCPM");
  sub->add_option("--dialect", a->dialect, "fanuc (default), haas, linuxcnc, sinumerik, heidenhain")
      ->check(CLI::IsMember({"fanuc", "haas", "linuxcnc", "sinumerik", "heidenhain"}));
  sub->add_option("--feed-mode", a->feed_mode, "auto (G93 for simultaneous rotary moves, default), g93, g94")
      ->check(CLI::IsMember({"auto", "g93", "g94"}));
  sub->add_flag("--verify", a->verify, "Re-execute the program through the forward kinematics and report the errors");
  sub->add_option("--report", a->report, "Write an HTML report");
  sub->add_option("-o,--output", a->output, "Output NC program (default: standard output)");
  sub->add_option("INPUT", a->input, "APT CL data or G-code")->required()->check(CLI::ExistingFile);
  sub->callback([a, &action] { action = [a] { return run_post(*a); }; });
}

}  // namespace ncpost::cli
