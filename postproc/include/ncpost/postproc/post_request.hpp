// SPDX-License-Identifier: Apache-2.0
#pragma once
// The library entry point of `ncpost post` (docs/cli.md): CL data or G-code from a stream, the NC
// program to a stream, with the policy of the command, one driver for every machine kind
// (machine/post_machine.hpp) — the solver (nominal machine, or the actual machine of an error
// model), the nonlinear-error tolerance (on by default, off under RTCP unless
// asked for), native arcs and cycles only on the nominal machine, the program header, and the
// before/after account of `--verify` (the plain post executed on the job's machine against the
// written program re-executed on it). The `ncpost post` command only parses its arguments, reads
// the files (machine, models) and calls `post`; a program from code gets the same program.
//
//   #include "ncpost/postproc/machine/serial_post_machine.hpp"
//   ncpost::PostRequest r;
//   r.machine = ncpost::serial_post_machine(ncpost::load_machine("machines/ac-trunnion.toml"));
//   r.machine_source = "machines/ac-trunnion.toml";
//   r.setup.workpiece_origin_mm = {0, 0, 80};
//   r.verify = true;
//   std::ifstream in("samples/hemisphere_5axis.cls", std::ios::binary);
//   std::ofstream out("hemisphere.nc", std::ios::binary);
//   const ncpost::PostResult result = ncpost::post(in, out, r);
//   // result.account.before_max_mm, result.account.after.max_contour_mm, result.summary.notices
//
// Units: mm and radians inside; CL data in the workpiece frame W (conventions.md).
#include <cstddef>
#include <functional>
#include <istream>
#include <memory>
#include <optional>
#include <ostream>
#include <string>

#include "ncpost/compensation/nonlinear_compensation.hpp"
#include "ncpost/kinematics/machine.hpp"
#include "ncpost/postproc/machine/post_machine.hpp"
#include "ncpost/postproc/read/cl_input.hpp"
#include "ncpost/postproc/read/cl_record.hpp"
#include "ncpost/postproc/write/dialect.hpp"
#include "ncpost/postproc/post.hpp"
#include "ncpost/postproc/verify/post_report.hpp"
#include "ncpost/postproc/solve/tolerance_subdivider.hpp"

namespace ncpost {

/// Progress and events of a run, each optional; called on the caller's thread.
struct PostProgress {
  std::function<void(std::size_t motions)> posting;  ///< every 4096 CL motions of the post
  /// The program is written: its summary (notices known), before the account is measured.
  std::function<void(const PostSummary& summary)> posted;
  std::function<void(std::size_t motions)> measuring;  ///< every 4096 CL motions of the "before"
  std::function<void()> measured;                      ///< the "before" is measured
};

struct PostRequest {
  // the job
  /// The machine of any kind, with the errors its program compensates (`--model`) and those of the
  /// machine it is re-executed on (`--verify-on`): serial_post_machine.hpp, trr_xy_post_machine.hpp.
  std::shared_ptr<const PostMachine> machine;
  std::string machine_source;  ///< where it came from (the machine file), named in the program header
  Setup setup;                 ///< workpiece origin and tool length (TRR-XY: the machine file's tool offset)
  // the input
  std::string input_name = "<input>";  ///< the name in messages (file:line:col) and the program header
  std::string input_file;              ///< the file the input is read from, hashed in the report (empty: input_name)
  InputKind input_kind = InputKind::automatic;
  cl::ReaderOptions reader;  ///< units of a file that does not say, unterminated files, NX MSYS
  /// The numbers of the tools the input calls by name (`--tool-table`; PostOptions::tool_table).
  std::shared_ptr<const ToolTable> tool_table;
  // the machine the program is for (its errors: `machine`)
  std::string model_source;  ///< the model file, named in the header and the account
  // the nonlinear error
  /// Bound on every block's nonlinear error (mm, in W); nullopt: one block per CL motion.
  std::optional<double> tolerance_mm = kDefaultTolerance_mm;
  /// True when `tolerance_mm` is the default rather than asked for: then RTCP turns it off (the
  /// control interpolates the tool tip) and the header says "the default".
  bool tolerance_is_default = true;
  nonlinear::Method nonlinear = nonlinear::Method::adaptive;
  // the program
  Dialect dialect = dialect_named("fanuc");
  bool rtcp = false;  ///< tool tip in W with rotary angles, for a control with RTCP/TCPM
  /// 3+2 runs in tilted work planes (PostOptions::tilted_plane; the dialect's [tilted_plane]);
  /// not with `rtcp` nor a model (the control maps the plane's coordinates on its nominal kinematics).
  bool tilted_plane = false;
  PostOptions::FeedMode feed_mode = PostOptions::FeedMode::automatic;
  double retract_mm = 50.0;  ///< retract when the limits force a change of solution; 0 refuses
  /// greedy or planned over each run of feed motions (PostOptions::branch_choice)
  PostOptions::BranchChoice branch_choice = PostOptions::BranchChoice::greedy;
  int threads = 2;  ///< 1 or 2 (read and solve ahead); the program is the same
  std::string program_name = "NCPOST";
  // verification
  /// Re-execute the written program and measure the plain post (one block per CL motion, nominal
  /// commands) on the same machine: PostResult::account. Implied by a machine with `--verify-on`.
  bool verify = false;
  std::string verify_on_source;  ///< the file of `--verify-on` (e.g. a simulated truth), named in the account
  PostProgress progress;

  /// Empty when the request can run, else what is wrong with it.
  std::string validate() const;
};

struct PostResult {
  PostSummary summary;  ///< CL motions, blocks, notices, and (with verification) the written program re-executed
  /// Names, counts and notices always; with verification the figures before and after (account_text,
  /// render_post_html). Under RTCP nothing is re-executed (the control does the kinematics).
  PostAccount account;
  bool verified = false;  ///< the account holds the before/after figures
};

/// Posts `input` (read from where it stands; seekable: it is read again for the "before") into
/// `program`. Throws InputError (bad input, naming input_name:line:col), Infeasible (a CL point
/// the machine cannot reach, naming the line), FileError (`program` failed), std::invalid_argument
/// (PostRequest::validate()).
PostResult post(std::istream& input, std::ostream& program, const PostRequest& request);

}  // namespace ncpost
