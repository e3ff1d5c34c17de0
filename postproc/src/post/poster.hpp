// SPDX-License-Identifier: Apache-2.0
#pragma once
// The post loop (private to postproc): `Poster` turns the CL records of one input into the NC
// blocks of one program on one kinematic model. Its work is split by responsibility, a file each
// under postproc/src/post/:
//
//   poster.cpp          the driver: the record loop (read ahead or here) and the records that move nothing
//   motion_planning.cpp the branch plan of runs of feed motions (PostOptions::branch_choice, branch_plan.hpp)
//   motion.cpp          a CL motion to axis commands: solve (planned, read ahead or here), take-up, retract
//   block_writing.cpp   one motion block: its words, the commands the control executes, its feed
//   written_check.cpp   --verify: the blocks as written, read back and executed (read_back.hpp)
//   arc_writing.cpp     CL circles: native G2/G3 or points within the arc tolerance
//   cycle_writing.cpp   drilling cycles: native cycle words or moves along the tool axis
//   cutter_comp.cpp     CUTCOM as G41/G42 and the checks of the moves under it
//   tool_state.cpp      tool changes, length registers and RTCP on/off
//   plane_writing.cpp   tilted work planes (PostOptions::tilted_plane, tilted_plane.hpp)
//
// The state they share is the Poster's: the previous point, what the control has in force
// (written words, the executed commands) and the summary.
#include <array>
#include <deque>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "ncpost/postproc/post.hpp"
#include "ncpost/postproc/solve/post_hooks.hpp"
#include "ncpost/postproc/write/tilted_plane.hpp"
#include "read/lookahead.hpp"
#include "verify/read_back.hpp"
#include "verify/record_blocks.hpp"

namespace ncpost::detail {

struct HolePlanes;
struct ToolCall;

class Poster {
 public:
  Poster(const std::string& input, const KinematicModel& solver, SolverData& data, NcWriter& writer,
         const PostOptions& options);

  PostSummary run(cl::Reader& reader);

 private:
  /// The next record from the input (read ahead or read here, errors kept in place).
  using Fetch = std::function<AheadItem()>;

  // ---- the driver (poster.cpp) ---------------------------------------------------------------
  void notice(cl::Location where, const std::string& what);
  void on(const cl::Motion& m);
  void on(const cl::Feed& f);
  void on(const cl::Spindle& s);
  void on(const cl::Coolant& c);
  void on(const cl::Circle& c);
  void on(const cl::Cycle& c);
  void on(const cl::Comment& c);
  void on(const cl::Unsupported& u);
  void on(const cl::Dwell& d);
  void on(const cl::Stop& s);
  void on(const cl::End&);
  void on(const cl::ToolOffset& t);

  // ---- branch planning (motion_planning.cpp) ---------------------------------------------------
  /// The most feed motions planned at once (memory: the records held, one back-pointer per candidate).
  static constexpr std::size_t kPlanWindow = 8192;
  bool starts_run(const AheadItem& item) const;
  bool continues_unplanned_run(const AheadItem& item);
  bool forced_change(const Vec3d& axis_W, const RotaryAngles& from, const RotaryAngles& to) const;
  void plan_run(AheadItem first, const Fetch& fetch);
  void plan_motions(std::deque<AheadItem>& items, std::vector<std::size_t> motions, bool window_full);
  std::size_t solve_greedily(std::deque<AheadItem>& items, std::vector<std::size_t>& motions,
                             std::vector<AxisPosition>& greedy);
  std::optional<std::size_t> plan_fewest_changes(std::deque<AheadItem>& items, const std::vector<std::size_t>& motions,
                                                 const std::vector<AxisPosition>& greedy, std::size_t greedy_changes);
  std::vector<RotaryAngles> turns(const RotaryAngles& rotary_rad) const;

  // ---- motion (motion.cpp) -------------------------------------------------------------------
  void move_to(const ClPoint& cl, int line, bool rapid, std::optional<RotaryAngles> rotary = std::nullopt);
  void hold_plane_rotary(const ClPoint& cl, std::optional<RotaryAngles>& rotary);
  SolvedPoint solve_motion(const ClPoint& cl, int line, const std::optional<RotaryAngles>& rotary);
  std::optional<IkOutcome> planned_solution(const ClPoint& cl, bool ahead_fits);
  void before_motion(int line, bool rapid);
  void take_up_reversal(const SolvedPoint& next, int line);
  void write_motion(const SolvedPoint& next, int line, bool rapid);
  bool branch_changed(const ClPoint& cl, const AxisPosition& q) const;
  void retract_and_reorient(const SolvedPoint& next, int line);

  // ---- one motion block (block_writing.cpp) ----------------------------------------------------
  void emit(const SolvedPoint& from, const SolvedPoint& to, int line, bool rapid);
  NcMotion motion_words(const SolvedPoint& to, bool rapid) const;
  AxisPosition executed_commands(const SolvedPoint& to, const NcMotion& m) const;
  void set_feed(NcMotion& m, const SolvedPoint& from, const SolvedPoint& to, const AxisPosition& executed, int line,
                bool rapid) const;
  const KinematicModel& feed_solver() const;
  bool write_retract_or_approach(const SolvedPoint& from, const SolvedPoint& to, const NcMotion& m);
  Vec3d tool_axis_in_program(const ClPoint& cl, const RotaryAngles& rotary_rad) const;
  double executed_tip_path_mm(const AxisPosition& q0, const AxisPosition& q1) const;

  // ---- --verify: the program as written, read back (written_check.cpp) ------------------------
  ReadBackBlock read_written(const WrittenState& in_force, const ClPoint& from, const ClPoint& to, int line);
  AxisPosition commands_of(const PerAxis<double>& v) const;
  PerAxis<double> words_at(const WrittenState& a, const WrittenState& b, double t) const;
  ToolPoseT<double> execute_words(const WrittenState& a, const WrittenState& b, double t) const;
  void check_written(const SolvedPoint& from, const SolvedPoint& to, int line, bool rapid, const NcMotion& m,
                     const std::optional<ReadBackBlock>& first, const std::optional<ReadBackBlock>& block);
  void check_written_rapid(const SolvedPoint& from, const SolvedPoint& to, int line,
                           const std::optional<ReadBackBlock>& first, const std::optional<ReadBackBlock>& block);
  void check_rapid_into_cut(const SolvedPoint& from, int line);
  void check_feed_word(const ReadBackBlock& b, const SolvedPoint& from, const SolvedPoint& to, int line,
                       const NcMotion& m);
  void check_arc_words(const ReadBackBlock& b, const NcArc& arc);
  void verify_native_arc(const ReadBackBlock& written, const NcArc& arc,
                         const std::optional<PerAxis<double>>& start_words, const Vec3d& normal, double angle,
                         const cl::Circle& c, const cl::Motion& end, const AxisPosition& executed_end);

  // ---- arcs (arc_writing.cpp) ------------------------------------------------------------------
  void move_along_arc(const cl::Circle& c, const cl::Motion& end, bool rapid);
  bool native_arc(const cl::Circle& c, const cl::Motion& end, bool rapid, double angle);
  void write_native_arc(const NcArc& arc, const Vec3d& xe, const Vec3d& normal, double angle, const cl::Circle& c,
                        const cl::Motion& end, const AxisPosition& solved_end);

  // ---- cycles (cycle_writing.cpp) --------------------------------------------------------------
  void drill(const cl::Motion& m);
  bool native_hole(const HolePlanes& p, double feed, int line);
  void verify_native_hole(const HolePlanes& p, const RotaryAngles& rotary,
                          const std::function<Vec3d(const ClPoint&)>& frame, int line);

  // ---- cutter radius compensation (cutter_comp.cpp) --------------------------------------------
  void on(const cl::CutterComp& c);
  void check_comp(const cl::Motion& m);

  // ---- tools (tool_state.cpp) ------------------------------------------------------------------
  void on(const cl::ToolChange& change);
  void on(const cl::LengthOffset& l);
  bool length_in_kinematics() const;
  void check_tool_length(const cl::ToolChange& t, const ToolCall& call) const;
  /// The length register in force: the program's (G43 H), else the tool's own.
  int length_register() const { return length_register_.value_or(tool_); }

  // ---- tilted work planes (plane_writing.cpp) --------------------------------------------------
  /// The plane the program is in: its words (what the control reads) and where the control turns
  /// the rotary axes (the tool along the plane's Z).
  struct Plane {
    TiltedPlane words;
    Vec3d axis_W = Vec3d::UnitZ();     ///< the CL tool axis of the run
    RotaryAngles rotary_rad;           ///< the post's solution (limits, continuity)
    RotaryAngles executed_rotary_rad;  ///< the control's: the tool along the words' Z, nearest it
  };
  Vec3d home_offset() const;
  void update_plane(const cl::Motion& m, bool rapid);
  void open_plane(const ClPoint& cl);
  int plane_solution_direction(const ClPoint& cl, const RotaryAngles& rotary) const;
  std::vector<std::string> plane_on_blocks(const Plane& p, const std::array<double, 3>& angles,
                                           const RotaryAngles& rotary, int dir) const;
  void close_plane();
  AxisPosition plane_executed(const Vec3d& in_plane) const;

  // ---- state -----------------------------------------------------------------------------------
  const std::string& input_;
  const AheadSolve* ahead_ = nullptr;           ///< the current record's motion solved ahead
  AheadCut* ahead_cut_ = nullptr;               ///< ... and cut ahead (its points are moved out)
  std::optional<RotaryAngles> planned_rotary_;  ///< the current record's rotary angles chosen by the branch plan
  bool unplanned_run_ = false;                  ///< in a run too long to plan (continues_unplanned_run)
  std::deque<AheadItem> pending_;               ///< records read and planned, not posted yet
  std::optional<AheadItem> carry_;              ///< a rapid read by the last plan: it opens the next run
  SolverData plan_data_;                        ///< the solver's working data of the branch plan
  const KinematicModel& solver_;
  const PostHooks& hooks_;  ///< the solver's post hooks (reversal, RTCP tip)
  SolverData& data_;        ///< the solver's working data on the post's thread
  NcWriter& writer_;
  const PostOptions& options_;
  const Machine& machine_;
  const CommandWords words_;  ///< what each command slot is (read once: no virtual call per point)
  PostSummary summary_;
  SolvedPoint previous_{};
  AxisPosition last_executed_{};
  /// The tool tip (W, mm) the feed model gave at the end of the last block's path (q), for the next.
  struct FeedTip {
    AxisPosition q;
    Vec3d tip_mm;
  };
  mutable std::optional<FeedTip> last_feed_tip_;
  std::optional<PerAxis<double>> last_values_;   ///< words of the last motion block (mm, deg)
  std::optional<WrittenBlockReader> read_back_;  ///< --verify: the blocks as written, read back
  std::optional<ReadBackBlock> last_rapid_;      ///< the last rapid written (an approach if a feed follows)
  bool last_was_feed_ = false;                   ///< the last motion written was a feed move
  bool have_position_ = false;
  bool rtcp_on_ = false;
  int tool_ = 1;                        ///< the tool whose length is active (1 until the first tool change)
  bool tool_numbered_ = true;           ///< false: the tool was called by name and has no number (tool_ is 0)
  std::optional<int> length_register_;  ///< the length register written (the tool's, or a G43 H of the input)
  RecordBlocks records_{writer_};
  bool default_feed_noticed_ = false;
  std::optional<cl::Circle> pending_circle_;
  cl::Cycle cycle_;
  std::optional<cl::CutterComp> comp_;  ///< the last CUTCOM
  int noticed_cycle_line_ = 0;          ///< the cycle record whose native form was noticed
  std::optional<Plane> plane_;
  std::optional<std::array<double, 3>> last_plane_angles_;  ///< of the last plane (continuity)
  const Vec3d home_offset_ = home_offset();
};

}  // namespace ncpost::detail
