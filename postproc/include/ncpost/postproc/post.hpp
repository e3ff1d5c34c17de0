// SPDX-License-Identifier: Apache-2.0
#pragma once
// The post-processor: CL records in, NC blocks out (docs/cli.md `ncpost post`).
//
// Every CL motion becomes one block (circles and cycles are expanded into motions first), unless
// a subdivider is given (`--tolerance`: the nonlinear error of each block is bounded). Commands
// come from a KinematicModel (nominal or actual machine); without RTCP the program holds machine
// axis positions (X Y Z of the TCP in M, rotary angles in degrees); with RTCP it holds the tool
// tip in W and the rotary angles, and the control does the kinematics.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "ncpost/postproc/read/cl_record.hpp"
#include "ncpost/postproc/read/tool_table.hpp"
#include "ncpost/postproc/solve/motion_solver.hpp"
#include "ncpost/postproc/write/nc_writer.hpp"
#include "ncpost/postproc/verify/verify.hpp"

namespace ncpost {

/// One output point of a block split to meet a tolerance: CL point and its commands.
struct SolvedPoint {
  ClPoint cl;
  AxisPosition q;
  /// The pose the machine executes at q (W), when the solver evaluated it (IkOutcome::executed)
  std::optional<ToolPoseT<double>> executed = std::nullopt;
};

/// A motion block as written: its CL segment and the commands the control reads at its ends
/// (rounded to the dialect's decimals), for PostOptions::on_block.
struct WrittenBlock {
  int line = 0;  ///< the CL line it comes from
  bool rapid = false;
  ClPoint from_cl, to_cl;
  AxisPosition from, to;
};

/// Splits the block (from, to) into points ending with `to`'s; given by `--tolerance`. It solves
/// with the post's SolverData (where the axes stand, the solver's caches), passed on each call.
class Subdivider {
 public:
  using Cut = std::function<std::vector<SolvedPoint>(const SolvedPoint& from, const SolvedPoint& to, SolverData& data)>;
  Subdivider() = default;
  /// `cut(from, to, data)`. `takes_up_play`: the subdivision takes up the reversal play inside
  /// blocks (play_subdivision.hpp), so the post writes no take-up blocks at the CL points
  /// (KinematicModel::take_up).
  template <class F>
  requires std::is_invocable_r_v < std::vector<SolvedPoint>,
  const F&, const SolvedPoint&, const SolvedPoint&,
      SolverData& >
          Subdivider(F cut, bool takes_up_play = false)  // NOLINT(google-explicit-constructor): as a std::function
      : cut_(std::move(cut)),
  takes_up_play_(takes_up_play) {}
  /// A subdivision that needs no solver data: `f(from, to)`.
  template <class F>
  requires std::is_invocable_r_v < std::vector<SolvedPoint>,
  const F&, const SolvedPoint&,
      const SolvedPoint& >
          Subdivider(F f)  // NOLINT(google-explicit-constructor): assigned from a lambda like a std::function
      : cut_([f = std::move(f)](const SolvedPoint& from, const SolvedPoint& to, SolverData&) { return f(from, to); }) {}

  explicit operator bool() const { return static_cast<bool>(cut_); }
  std::vector<SolvedPoint> operator()(const SolvedPoint& from, const SolvedPoint& to, SolverData& data) const {
    return cut_(from, to, data);
  }
  bool takes_up_play() const { return takes_up_play_; }

 private:
  Cut cut_;
  bool takes_up_play_ = false;
};

struct PostOptions {
  bool rtcp = false;
  enum class FeedMode { automatic, per_minute, inverse_time } feed_mode = FeedMode::automatic;
  double arc_tolerance_mm = 0.001;  ///< chord error of expanded CIRCLE records
  /// Write a CIRCLE as G2/G3 where it can be: a planar arc with the tool axis normal to it whose
  /// plane is principal in the program's frame (M, or W under RTCP), on the nominal machine (off
  /// under `--model`: the actual machine would not follow the control's circle exactly), not Klartext.
  bool native_arcs = true;
  /// Write CYCLE/DRILL and CYCLE/DEEP holes as G81/G83 where the hole runs along −Z of the program
  /// frame and the dialect has them (fanuc, haas, linuxcnc); otherwise explicit moves.
  bool native_cycles = true;
  /// Rapid moves in two blocks: when the target is higher, first out along the tool axis until
  /// level with it (Z alone for a tool along Z), then the rest; when it is lower, first to the
  /// point on the target's tool-axis line level with the tool, then down that line — the tool
  /// never descends while it travels or turns, and leaves and enters a tilted hole along its axis.
  /// Z is that of the program frame (M, W under RTCP, the plane's in a tilted plane). A tool axis
  /// within 60 deg of horizontal there: one straight block (as the CL data give it).
  bool order_rapids = true;
  /// Cut rapid moves to the tolerance too (`subdivide`): machines whose control interpolates rapids
  /// in axis space far from the straight line (the TRR-XY sliders), where the rapid would not clear.
  bool subdivide_rapids = false;
  /// After a tool call, the dialect's tool-length block (G43 H..): off for machines whose tool length
  /// is part of the kinematics (the TRR-XY `tool_offset`), with no Z word to compensate.
  bool tool_length_on_change = true;
  /// The tool length (mm) the solver places head pivots with (--tool-length): a LOADTL length
  /// that differs from it is refused where the axis positions depend on it (a head without RTCP).
  std::optional<double> tool_length_mm;
  /// The tool table (--tool-table): the numbers (and lengths) of the tools a program calls by name,
  /// for dialects that call tools by number (tool_table.hpp); null: none given.
  std::shared_ptr<const ToolTable> tool_table;
  /// Machines with reversal (`--model` with `reversal:` terms): before a feed block that reverses
  /// an axis, a block that moves only the commands through the play (the tool stands still), so the
  /// block itself runs without lag. On with `--tolerance` (the lag would otherwise bow the tip by
  /// up to the play at the block start).
  bool take_up_reversal = false;
  double default_feed_mm_min = 1000.0;  ///< used (with a notice) before the first FEDRAT
  Subdivider subdivide;                 ///< empty: one block per CL motion
  std::string program_name;
  std::vector<std::string> header_comments;
  std::function<void(std::size_t motions)> progress;  ///< called every 4096 motions
  /// When the limits force a change of solution between two feed motions (the continuous branch
  /// leaves the travel): retract this far along the tool axis, reorient, re-engage, with a notice.
  /// 0: no retract strategy, the post fails (Infeasible) naming the CL line.
  double retract_mm = 50.0;
  double branch_change_rad = 0.2;  ///< extra rotary travel (sum over the axes) that counts as a change
  /// How the post chooses among the inverse solutions (branches, turns of a rotary axis) of the
  /// feed motions: `greedy` (default), each nearest the previous commands; `lookahead`, over each
  /// run of feed motions (up to 8192, between rapids, tool changes, arcs and cycles; longer runs
  /// are posted greedily as a whole): where the greedy choice runs into limit-forced changes of solution
  /// (retracts), the choice with the fewest (branch_plan.hpp), else the greedy one unchanged.
  /// Two-rotary serial machines whose solver is concurrent() (not models with reversal).
  enum class BranchChoice { greedy, lookahead } branch_choice = BranchChoice::greedy;
  /// 2: other threads read the CL records and solve their motions ahead (solving only for a
  /// concurrent() solver; the program is the same as with 1). With such a solver another thread
  /// also runs the subdivider on each motion solved ahead (used where the post cuts the same two points).
  int threads = 1;
  /// `--tilted-plane`: a run of motions with a constant tool axis other than +Z of W, opened by a
  /// rapid (or the first motion), is written in a tilted work plane (the dialect's [tilted_plane]
  /// words, tilted_plane.hpp) with X Y Z in the plane's frame; simultaneous motions stay as they
  /// are. Machine-axis programs on the nominal machine only (not with `rtcp`).
  bool tilted_plane = false;
  /// Read every written motion block back and execute it (VerifyReport in the summary, defects
  /// included: read_back.hpp).
  bool verify = false;
  /// The model the inverse-time (G93) feeds are computed on; null: the post's solver. `post()` gives
  /// the nominal kinematics: the machine's errors change a block's path length by far less than the
  /// F word's resolution, and under --verify-on the post's solver executes on the verifying machine.
  const KinematicModel* feed_solver = nullptr;
  /// With `verify`: called for every re-executed feed block with its CL line and contour error (mm).
  std::function<void(int line, double contour_mm)> on_verified;
  /// Called for every written motion block that starts from a known position (rapids included;
  /// not arcs and cycle blocks, which the control interpolates itself): `preview` on the TRR-XY machine.
  std::function<void(const WrittenBlock& block)> on_block;
};

struct PostSummary {
  std::size_t motions_in = 0;
  std::size_t blocks_out = 0;
  std::size_t rapid_splits = 0;   ///< rapid moves written in two blocks (order_rapids)
  std::size_t cycles_out = 0;     ///< drilled holes written as G81/G83
  std::size_t arcs_out = 0;       ///< CIRCLE records written as G2/G3 (not re-executed by --verify)
  std::size_t tilted_planes = 0;  ///< tilted work planes written (`tilted_plane`)
  std::size_t retracts = 0;       ///< limit-forced changes of solution (retract, reorient, re-engage)
  std::size_t planned_runs = 0;   ///< runs of feed motions whose solutions the branch plan changed
  std::vector<std::string> notices;
  VerifyReport verify;
};

/// Posts the whole input. Throws InputError (bad input) or Infeasible (a CL point with no
/// admissible solution; the message names the file and line). `data` is the solver's working data
/// on the post's thread: its figures (SolverData::uncompensated, max_residual_mm) are those of the
/// points the program uses (read-ahead threads solve with data of their own).
PostSummary post_program(cl::Reader& reader, const std::string& input_name, const KinematicModel& solver,
                         NcWriter& writer, const PostOptions& options, SolverData& data);
/// The same with fresh working data, dropped at the end (no figures wanted).
PostSummary post_program(cl::Reader& reader, const std::string& input_name, const KinematicModel& solver,
                         NcWriter& writer, const PostOptions& options);

}  // namespace ncpost
