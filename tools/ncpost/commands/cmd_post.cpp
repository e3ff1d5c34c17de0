// SPDX-License-Identifier: Apache-2.0
// ncpost post: CL data or G-code in, NC program out (spec/cli.md).
#include <fmt/format.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <optional>
#include <string>

#include "commands.hpp"
#include "dialect_option.hpp"
#include "file_checks.hpp"
#include "input_file.hpp"
#include "model_input.hpp"
#include "input_options.hpp"
#include "number_checks.hpp"
#include "atomic_ostream.hpp"
#include "ncpost/compensation/model_json.hpp"
#include "ncpost/postproc/verify/post_report.hpp"
#include "ncpost/postproc/machine/serial_post_machine.hpp"
#include "ncpost/postproc/post_request.hpp"
#include "ncpost/postproc/read/tool_table.hpp"
#include "machine_kind.hpp"

namespace ncpost::cli {

/// The serial machine of the job, and the models of --model and --verify-on checked against it.
void load_serial_post(const PostJobArgs& a, PostRequest& r) {
  LoadedJob job = load_job(a.job);
  std::optional<comp::ErrorParameters> model, verify_on;
  if (!a.model.empty()) model = read_model_for(a.model, job.machine, a.force_model).parameters;
  if (!a.verify_on.empty()) verify_on = read_model_for(a.verify_on, job.machine, a.force_model).parameters;
  r.machine = serial_post_machine(std::move(job.machine), std::move(model), std::move(verify_on));
  r.setup = job.setup;
  r.model_source = a.model;
  r.verify_on_source = a.verify_on;
}

namespace {

constexpr double kMaxToleranceMm = 10.0;  // a bound on the bow of a block: beyond it, a slip
constexpr double kMaxRetractMm = 2000.0;

struct PostArgs {
  JobOptions job;
  std::string model;
  std::string tolerance;               ///< --tolerance as given: MM, "none", or "" (the default)
  std::optional<double> tolerance_mm;  ///< resolved from `tolerance`: nullopt = none
  bool force_model = false;            // --force: model checks as warnings
  std::string nonlinear = "adaptive";
  bool rtcp = false;
  bool tilted_plane = false;
  std::string dialect = "fanuc";
  std::string tool_table;  ///< --tool-table: numbers of tools called by name ("" none)
  std::string feed_mode = "auto";
  bool verify = false;
  std::string report;
  std::string verify_on;
  double retract_mm = 50.0;
  std::string branch_plan = "greedy";
  int threads = 2;
  std::string output = "-";
  std::string input;       ///< the INPUT argument; in a run, the name in messages ("<stdin>" for "-")
  std::string input_path;  ///< in a run: the file read (the spool of standard input or a pipe)
};

/// --tolerance MM|none ("" = the default, kDefaultTolerance_mm).
std::optional<double> tolerance_of(const std::string& text) {
  if (text.empty()) return kDefaultTolerance_mm;
  if (text == "none") return std::nullopt;
  return std::stod(text);  // checked by the option's validator
}

/// Refuses combinations of options that cannot make a program, before anything is read.
void check_post_args(const PostArgs& given) {
  // every file checked before anything is computed: no output over an input, only writable places
  check_files({{"-o", given.output}, {"--report", given.report}}, {{"INPUT", given.input},
                                                                   {"--machine", given.job.machine},
                                                                   {"--model", given.model},
                                                                   {"--verify-on", given.verify_on}});
  if (given.tilted_plane && given.rtcp)
    throw UsageError("--tilted-plane: not with --rtcp (in a tilted plane the control carries the tool tip itself)");
  if (given.tilted_plane && !given.model.empty())
    throw UsageError(
        "--tilted-plane: not with --model (the control maps the plane's coordinates on its nominal "
        "kinematics, so the compensation cannot be carried); post --model without --tilted-plane");
}

/// The post request of the arguments: dialect, input, options, and the machine and models loaded.
PostRequest post_request_of(const PostArgs& a) {
  PostRequest r;
  try {
    r.dialect = dialect_named(a.dialect);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--dialect: ") + e.what());
  }
  r.machine_source = a.job.machine;
  r.input_name = a.input;
  r.input_file = a.input_path;
  r.input_kind = input_kind_named(a.job.input_kind);
  r.reader = reader_options(a.job);
  if (!a.tool_table.empty()) r.tool_table = std::make_shared<const ToolTable>(load_tool_table(a.tool_table));
  r.reader.tool_table = r.tool_table;  // (Klartext CYCL DEF 208: the tools' diameters)
  r.reader.control = r.dialect.input_control;
  r.reader.tool_offset_writes = r.dialect.input_tool_offsets;
  r.reader.power_on = r.dialect.input_power_on;
  if (r.reader.integer_words == cl::IntegerWords::automatic && r.dialect.input_integer_words)
    r.reader.integer_words = *r.dialect.input_integer_words;  // the control's own reading (--integer-words auto)
  r.reader.power_on_source = fmt::format("the {} dialect's [input] power_on", r.dialect.name);
  r.tolerance_mm = tolerance_of(a.tolerance);
  r.tolerance_is_default = a.tolerance.empty();
  r.nonlinear = *nonlinear::method_named(a.nonlinear);
  r.rtcp = a.rtcp;
  r.tilted_plane = a.tilted_plane;
  r.feed_mode = a.feed_mode == "g93"   ? PostOptions::FeedMode::inverse_time
                : a.feed_mode == "g94" ? PostOptions::FeedMode::per_minute
                                       : PostOptions::FeedMode::automatic;
  r.retract_mm = a.retract_mm;
  r.branch_choice =
      a.branch_plan == "greedy" ? PostOptions::BranchChoice::greedy : PostOptions::BranchChoice::lookahead;
  r.threads = a.threads;
  r.verify = a.verify || !a.report.empty();
  machine_kind(a.job.machine).load_post({a.job, a.model, a.verify_on, a.force_model}, r);
  return r;
}

/// Progress only where someone watches: stderr on a terminal (and the program not on that terminal).
void watch_progress(PostRequest& r, const std::string& output) {
  const bool tty = ::isatty(STDERR_FILENO) && !(output == "-" && ::isatty(STDOUT_FILENO));
  if (tty) r.progress.posting = [](std::size_t n) { fmt::print(stderr, "\rposting: {} motions", n); };
  r.progress.posted = [tty](const PostSummary& summary) {
    if (tty) fmt::print(stderr, "\r\033[K");
    for (const auto& n : summary.notices) fmt::print(stderr, "notice: {}\n", n);
  };
  if (::isatty(STDERR_FILENO)) {
    r.progress.measuring = [](std::size_t n) {
      fmt::print(stderr, "\rmeasuring the uncompensated program: {} motions", n);
    };
    r.progress.measured = [] { fmt::print(stderr, "\r\033[K"); };
  }
}

/// What the run did: blocks written, the re-executed error, the report.
void print_post_result(const PostArgs& a, const PostRequest& r, const PostResult& result) {
  const PostSummary& summary = result.summary;
  if (a.output != "-")
    fmt::print(stderr, "ncpost post: {} CL motions -> {} blocks in {}\n", summary.motions_in, summary.blocks_out,
               a.output);
  if (r.verify || r.machine->has_verify_on()) {
    if (a.rtcp)
      fmt::print(stderr, "verify: with --rtcp the control does the kinematics; nothing re-executed\n");
    else
      fmt::print(stderr, "{}", account_text(result.account));
  }
  if (!a.report.empty()) fmt::print(stderr, "report written to {}\n", a.report);
}

int run_post(const PostArgs& given) {
  check_post_args(given);
  const InputFile input(given.input);
  PostArgs a = given;
  a.input = input.name();
  a.input_path = input.path();
  a.tolerance_mm = tolerance_of(a.tolerance);
  if (a.rtcp && a.tolerance.empty()) a.tolerance_mm.reset();  // the control interpolates the tool tip
  PostRequest r = post_request_of(a);
  if (a.tolerance_mm && a.rtcp)  // given explicitly
    fmt::print(stderr, "notice: --tolerance has no effect with --rtcp (the control interpolates the tool tip)\n");
  watch_progress(r, a.output);

  std::ifstream in(a.input_path, std::ios::binary);
  if (!in) throw InputError({a.input, 0, 0}, "cannot open the input file");
  AtomicFile out(a.output);
  AtomicOstream program(out);
  const PostResult result = post(in, program, r);
  // everything computed: now the files appear, all or none
  std::optional<AtomicFile> report;
  if (!a.report.empty()) {
    report.emplace(a.report);
    report->write(render_post_html(result.account));
  }
  out.commit();
  if (report) report->commit();
  print_post_result(a, r, result);
  return 0;
}

}  // namespace

void add_post(CLI::App& app, Action& action) {
  auto a = std::make_shared<PostArgs>();
  CLI::App* sub = app.add_subcommand("post", "Post-process CL data (APT) or G-code into an NC program");
  add_job_options(*sub, a->job);
  sub->add_option("--model", a->model, "Error model JSON (identify): compensate the machine's geometric errors");
  add_model_force_option(*sub, a->force_model);
  sub->add_option("--tolerance", a->tolerance,
                  fmt::format("Bound the nonlinear error of every block (mm, in W): blocks that bow more are cut "
                              "into shorter ones. Default {} mm; 'none' writes one block per CL motion",
                              kDefaultTolerance_mm))
      ->type_name("MM|none")
      ->check(CLI::Validator(
          [](std::string& v) -> std::string {
            if (v == "none") return {};
            try {
              std::size_t used = 0;
              const double x = std::stod(v, &used);
              if (used == v.size() && x > 0 && std::isfinite(x) && x <= kMaxToleranceMm) return {};
            } catch (const std::exception&) {
            }
            return fmt::format(
                "expected a finite number above 0 and at most {} (mm), got '{}' ('none' turns the "
                "linearization off)",
                kMaxToleranceMm, v);
          },
          ""));
  sub->add_option("--nonlinear", a->nonlinear,
                  "Nonlinear-error compensation: adaptive (default) or harmonic (README \"Nonlinear error\")")
      ->check(CLI::IsMember({"adaptive", "harmonic"}));
  sub->add_flag("--rtcp", a->rtcp, "Write tool-tip coordinates with rotary angles for a control with RTCP/TCPM");
  sub->add_flag("--tilted-plane", a->tilted_plane,
                "3+2: write each run of motions with a constant tilted tool axis (opened by a rapid) in a tilted "
                "work plane: Fanuc G68.2/G53.1 ... G69, Haas G268/G253 ... G269, Sinumerik CYCLE800, Heidenhain "
                "PLANE SPATIAL ... STAY (the dialect's [tilted_plane]; LinuxCNC: machine axes as without it), X Y Z in "
                "the plane, G2/G3 and drilling cycles in its XY. Not with --rtcp or --model");
  sub->add_option("--dialect", a->dialect,
                  "A built-in dialect: fanuc (default), haas, linuxcnc, sinumerik, heidenhain; or the path of a "
                  "dialect file (a copy of postproc/dialects/fanuc.toml, edited; docs/usage.md \"Dialect files\")")
      ->type_name("NAME|PATH")
      ->check(dialect_name_or_path());
  sub->add_option("--tool-table", a->tool_table,
                  "Tools called by name in the input (TOOL CALL \"name\", T=\"name\"): their numbers (and lengths) "
                  "for a dialect that calls tools by number (TOML: [tools] then \"name\" = number, or \"name\" = "
                  "{ number = n, length = mm }); without it such a tool is refused. Heidenhain and Sinumerik "
                  "output keeps the name")
      ->check(CLI::ExistingFile);
  sub->add_option("--feed-mode", a->feed_mode, "auto (G93 for simultaneous rotary moves, default), g93, g94")
      ->check(CLI::IsMember({"auto", "g93", "g94"}));
  sub->add_flag("--verify", a->verify,
                "Re-execute the program on the machine (of --model) and print the error before and after");
  sub->add_option("--retract", a->retract_mm,
                  "When the axis limits force a change of solution mid-path: retract this far along the tool axis "
                  "(mm, default 50), reorient, re-engage; 0 refuses (exit 3)")
      ->check(finite_in(0.0, kMaxRetractMm, "mm"));
  sub->add_option("--branch-plan", a->branch_plan,
                  "How the rotary solution of each feed motion is chosen: greedy (default) takes the solution nearest "
                  "the previous commands, motion by motion; lookahead plans each run of feed motions with the rapid "
                  "before it (up to 8192 motions; longer runs are posted greedily) for the fewest limit-forced "
                  "changes of solution (retracts), then the least rotary travel, and leaves runs without a forced "
                  "change as greedy writes them")
      ->check(CLI::IsMember({"lookahead", "greedy"}));
  sub->add_option(
      "--verify-on", a->verify_on,
      "Re-execute the program on the machine of this model JSON (e.g. a simulated truth) instead of --model's");
  sub->add_option("--report", a->report, "Write an HTML report of the error before and after (implies --verify)");
  sub->add_option("--threads", a->threads,
                  "1: everything on one thread; 2 (default): the CL records are read and their motions solved "
                  "ahead on other threads (models with reversal: read only). The program is the same either way")
      ->check(CLI::Range(1, 2));
  sub->add_option("-o,--output", a->output, "Output NC program (default: standard output)");
  sub->add_option("INPUT", a->input, "APT CL data or G-code; - reads standard input")
      ->required()
      ->check(existing_input());
  sub->callback([a, &action] { action = [a] { return run_post(*a); }; });
}

}  // namespace ncpost::cli
