// SPDX-License-Identifier: Apache-2.0
#include "ncpost/postproc/post.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <deque>

#include "read/lookahead.hpp"
#include "ncpost/postproc/solve/branch_plan.hpp"
#include "ncpost/compensation/nonlinear_block.hpp"
#include "ncpost/postproc/solve/unreachable.hpp"
#include "ncpost/postproc/write/cycle_words.hpp"
#include "ncpost/postproc/solve/inverse_time.hpp"
#include "ncpost/postproc/write/tilted_plane.hpp"
#include "ncpost/postproc/verify/verify_arc.hpp"
#include "write/post_cycle.hpp"
#include "write/tool_call.hpp"
#include "write/tool_offset_blocks.hpp"
#include "verify/read_back.hpp"
#include "verify/record_blocks.hpp"

namespace ncpost {
namespace {

/// Rotary angles (rad) in degrees for a message: "12.3450, -45.0000".
std::string degrees_list(const RotaryAngles& rotary_rad, int decimals) {
  std::string out;
  for (Eigen::Index k = 0; k < rotary_rad.size(); ++k)
    out += fmt::format("{}{:.{}f}", k ? ", " : "", rad_to_deg(rotary_rad[k]), decimals);
  return out;
}

using detail::RecordBlocks;

class Poster {
 public:
  Poster(const std::string& input, const KinematicModel& solver, SolverData& data, NcWriter& writer,
         const PostOptions& options)
      : input_(input),
        solver_(solver),
        data_(data),
        writer_(writer),
        options_(options),
        machine_(solver.machine()),
        words_(solver.words()) {
    previous_.q = words_.home();  // the program starts from home, sized for the model's axes
    last_executed_ = words_.home();
    if (options_.verify) {  // --verify reads every motion block back as written (read_back.hpp)
      read_back_.emplace(writer_.dialect(), writer_.letters());
      writer_.keep_last_line(true);
    }
  }

  PostSummary run(cl::Reader& reader) {
    writer_.begin_program(options_.program_name, options_.header_comments);
    std::optional<detail::Lookahead> ahead;
    if (options_.threads > 1) ahead.emplace(reader, solver_);
    // the next record from the input: read ahead (2 threads) or read here, errors kept in place
    auto fetch = [&]() -> detail::AheadItem {
      if (ahead) return ahead->next();
      detail::AheadItem item;
      try {
        item.record = reader.next();
        item.notices = reader.take_notices();
      } catch (...) {
        item.record.reset();
        item.error = std::current_exception();
      }
      return item;
    };
    for (;;) {
      detail::AheadItem item;
      if (!pending_.empty()) {
        item = std::move(pending_.front());
        pending_.pop_front();
      } else {
        item = carry_ ? std::move(*carry_) : fetch();
        carry_.reset();
        if (!continues_unplanned_run(item) && starts_run(item)) {
          plan_run(std::move(item), fetch);
          continue;
        }
      }
      if (item.error) std::rethrow_exception(item.error);
      if (!item.record) break;
      ahead_ = item.solved ? &*item.solved : nullptr;
      planned_rotary_ = item.planned_rotary_rad;
      std::visit([this](const auto& r) { on(r); }, *item.record);
      ahead_ = nullptr;
      planned_rotary_.reset();
      for (auto& n : item.notices) summary_.notices.push_back(std::move(n));
    }
    close_plane();
    if (options_.rtcp && rtcp_on_) writer_.rtcp(false, tool_, length_register());
    writer_.end_program();
    summary_.blocks_out = writer_.blocks_written();
    return summary_;
  }

 private:
  // ---- branch planning (PostOptions::branch_choice, branch_plan.hpp) ------------------------
  /// The most feed motions planned at once (memory: the records held, one back-pointer per candidate).
  static constexpr std::size_t kPlanWindow = 8192;

  /// A feed motion whose solution the post chooses (not a rapid, no programmed angles).
  static bool plannable(const cl::Motion& m) { return !m.rapid && !m.from && !m.rotary_rad; }
  /// A rapid (or FROM) whose solution the post chooses: it may open a run (any solution is free there).
  static bool free_start(const cl::Motion& m) { return (m.rapid || m.from) && !m.rotary_rad; }

  /// Records that may stand between the feed motions of one run (they move nothing).
  static bool passes(const cl::Record& r) {
    return std::holds_alternative<cl::Feed>(r) || std::holds_alternative<cl::Spindle>(r) ||
           std::holds_alternative<cl::Coolant>(r) || std::holds_alternative<cl::Comment>(r) ||
           std::holds_alternative<cl::Unsupported>(r) || std::holds_alternative<cl::Dwell>(r) ||
           std::holds_alternative<cl::Stop>(r);
  }

  /// True when `item` (read from the input, not planned yet) opens a run of feed motions to plan:
  /// a two-rotary serial machine whose solver depends on nothing the post's progress changes.
  bool starts_run(const detail::AheadItem& item) const {
    if (options_.branch_choice != PostOptions::BranchChoice::lookahead || !words_.serial || words_.rotary_count != 2 ||
        !solver_.concurrent() || item.error || !item.record)
      return false;
    const auto* m = std::get_if<cl::Motion>(&*item.record);
    return m && (plannable(*m) || free_start(*m)) && cycle_.kind == cl::Cycle::Kind::off && !pending_circle_;
  }

  /// True while the feed motions of a run longer than one window go on: such a run is posted
  /// greedily as a whole (a plan that starts mid-run is not attempted).
  bool continues_unplanned_run(const detail::AheadItem& item) {
    if (!unplanned_run_) return false;
    const auto* m = item.record ? std::get_if<cl::Motion>(&*item.record) : nullptr;
    if ((m && plannable(*m)) || (item.record && !m && passes(*item.record))) return true;
    unplanned_run_ = false;
    return false;
  }

  /// The continuity test of the post: moving the rotary axes from `from` to `to` for the tool axis
  /// `axis_W` travels clearly further than the machine without limits would (another branch).
  bool forced_change(const Vec3d& axis_W, const RotaryAngles& from, const RotaryAngles& to) const {
    const double chosen = (to - from).cwiseAbs().sum();
    if (chosen <= options_.branch_change_rad) return false;  // the free travel is >= 0
    const auto free = unlimited_rotary_travel(machine_, axis_W, from);
    if (!free) return false;
    return chosen > *free + options_.branch_change_rad;
  }

  /// Reads the run that `first` (a feed motion, or a rapid that leads to feed motions) opens: up to
  /// kPlanWindow motions, and the record that ends it (a rapid that ends it opens the next run),
  /// chooses the solution of each motion, and queues the records with the choice.
  template <class Fetch>
  void plan_run(detail::AheadItem first, Fetch& fetch) {
    std::deque<detail::AheadItem>& items = pending_;  // (empty: a run opens once all before it is posted)
    std::vector<std::size_t> motions{0};
    items.push_back(std::move(first));
    while (motions.size() < kPlanWindow && items.size() < 4 * kPlanWindow) {
      detail::AheadItem item = fetch();
      bool stop = item.error || !item.record;
      bool motion = false;
      if (!stop) {
        if (const auto* m = std::get_if<cl::Motion>(&*item.record))
          (plannable(*m) ? motion : stop) = true;
        else
          stop = !passes(*item.record);
      }
      if (stop && !item.error && item.record && starts_run(item)) {
        carry_ = std::move(item);  // a rapid: it opens the next run
        break;
      }
      items.push_back(std::move(item));
      if (motion) motions.push_back(items.size() - 1);
      if (stop) break;
    }
    plan_motions(items, motions, motions.size() == kPlanWindow);
  }

  /// The greedy solutions of the motions (kept as solved ahead: the post uses them as it goes);
  /// where the limits force changes of solution on that path, the plan with the fewest.
  /// `window_full`: the run goes on after these motions.
  void plan_motions(std::deque<detail::AheadItem>& items, std::vector<std::size_t> motions, bool window_full) {
    auto point = [&](std::size_t k) -> const ClPoint& { return std::get<cl::Motion>(*items[motions[k]].record).point; };
    // a rapid first: any solution is free there (the post tests no change of solution on rapids)
    const bool rapid_first = !plannable(std::get<cl::Motion>(*items[motions[0]].record));
    auto tested = [&](std::size_t k) { return k > 0 ? true : !rapid_first && have_position_; };
    AxisPosition q = previous_.q;
    std::vector<AxisPosition> greedy;  // the commands each motion is solved from, then its own
    std::size_t greedy_changes = 0;
    for (std::size_t k = 0; k < motions.size(); ++k) {
      detail::AheadItem& item = items[motions[k]];
      if (!(item.solved && item.solved->fits(point(k), q))) {
        detail::AheadSolve s{point(k), q, {}, {}};
        try {
          s.ik = solver_.solve_quiet(point(k), q, plan_data_, &s.figures);
        } catch (...) {
          s.ik = {};  // the post solves this motion itself and meets the failure there
        }
        item.solved.reset();
        if (s.ik.ok()) item.solved = std::move(s);
      }
      if (!item.solved || !item.solved->ik.ok()) {
        motions.resize(k);  // the post names the failure; the plan ends before it
        break;
      }
      const AxisPosition& next = *item.solved->ik.position;
      if (tested(k) && forced_change(point(k).axis, q.rotary_rad, next.rotary_rad)) ++greedy_changes;
      greedy.push_back(q);
      q = next;
    }
    if (window_full) {  // the run goes on beyond the window: posted greedily as a whole
      unplanned_run_ = true;
      if (greedy_changes > 0)
        summary_.notices.push_back(fmt::format(
            "{}:{}: a run of more than {} feed motions is not planned ahead (--branch-plan lookahead): its solutions "
            "are chosen motion by motion",
            input_, std::get<cl::Motion>(*items[motions.front()].record).where.line, kPlanWindow));
      return;
    }
    if (greedy_changes == 0) return;  // nothing to improve: the greedy program
    BranchCandidates candidates(motions.size());
    for (std::size_t k = 0; k < motions.size(); ++k) {
      std::vector<RotaryAngles>& list = candidates[k];
      list.push_back(items[motions[k]].solved->ik.position->rotary_rad);  // the greedy choice first
      std::vector<AxisPosition> branches;
      try {
        branches = solver_.branches(point(k), greedy[k], plan_data_);
      } catch (...) {
        return;  // (a solver that fails here fails the post at this motion, or solves it greedily)
      }
      for (const AxisPosition& b : branches)
        for (const RotaryAngles& turned : turns(b.rotary_rad))
          if (std::none_of(list.begin(), list.end(),
                           [&](const RotaryAngles& c) { return max_abs_step(c, turned) < 1e-9; }))
            list.push_back(turned);
    }
    // the free travel from one candidate to the next point, computed once for all its candidates
    struct {
      std::size_t k = SIZE_MAX;
      RotaryAngles from;
      std::optional<double> free;
    } last;
    const ForcedChange forced = [&](std::size_t k, const RotaryAngles& from, const RotaryAngles& to) {
      if (!tested(k)) return false;
      const double chosen = (to - from).cwiseAbs().sum();
      if (chosen <= options_.branch_change_rad) return false;
      if (last.k != k || last.from != from) last = {k, from, unlimited_rotary_travel(machine_, point(k).axis, from)};
      return last.free && chosen > *last.free + options_.branch_change_rad;
    };
    const BranchPlan plan = plan_branches(previous_.q.rotary_rad, candidates, forced, kPlanWindow);
    // (no retract allowed: the post fails at the first change either way, the greedy one names it)
    if (plan.changes >= greedy_changes || (plan.changes > 0 && options_.retract_mm <= 0.0)) return;
    for (std::size_t k = 0; k < motions.size(); ++k)
      items[motions[k]].planned_rotary_rad = candidates[k][plan.choice[k]];
    const int first_line = std::get<cl::Motion>(*items[motions.front()].record).where.line;
    const int last_line = std::get<cl::Motion>(*items[motions.back()].record).where.line;
    summary_.notices.push_back(fmt::format(
        "{}:{}: the rotary solutions of lines {} to {} are planned ahead: the axis limits force {} change{} of "
        "solution there instead of {} (--branch-plan greedy){}",
        input_, first_line, first_line, last_line, plan.changes, plan.changes == 1 ? "" : "s", greedy_changes, ""));
    ++summary_.planned_runs;
  }

  /// The rotary angles `rotary_rad` and their whole turns within the limits (at most two turns
  /// either way; an axis without limits: one turn either way).
  std::vector<RotaryAngles> turns(const RotaryAngles& rotary_rad) const {
    std::vector<RotaryAngles> out{rotary_rad};
    for (int k = 0; k < machine_.rotary_count(); ++k) {
      const Axis& axis = machine_.rotary(k);
      std::vector<RotaryAngles> grown;
      for (const RotaryAngles& partial : out)
        for (int t : {0, -1, 1, -2, 2}) {
          const double v = rotary_rad[k] + 2.0 * kPi * t;
          if (axis.limits ? !axis.limits->contains(v) : std::abs(t) > 1) continue;
          grown.push_back(partial);
          grown.back()[k] = v;
        }
      out = std::move(grown);
    }
    return out;
  }

  // ---- records ---------------------------------------------------------------------------
  void on(const cl::Motion& m) {
    ++summary_.motions_in;
    if (options_.progress && summary_.motions_in % 4096 == 0) options_.progress(summary_.motions_in);
    const bool rapid = m.rapid || m.from;
    records_.resume();  // the spindle and coolant a program stop turned off
    update_plane(m, rapid);
    check_comp(m);
    if (pending_circle_) {
      const cl::Circle c = *pending_circle_;
      pending_circle_.reset();
      if (have_position_) {
        move_along_arc(c, m, rapid);
        return;
      }
    }
    if (cycle_.kind != cl::Cycle::Kind::off && !rapid) {
      drill(m);
      return;
    }
    move_to(m.point, m.where.line, rapid, words_.serial ? m.rotary_rad : std::nullopt);  // angles: serial chains
  }

  void on(const cl::Feed& f) {
    if (auto n = records_.feed(f)) notice(f.where, *n);
  }
  void on(const cl::Spindle& s) { records_.spindle(s); }
  void on(const cl::Coolant& c) { records_.coolant(c); }

  /// Every tool runs with its own length: RTCP off around the change, the tool call, then the
  /// length (or RTCP with the length) of the new tool (the dialect's words).
  /// A tool called by name keeps it where the dialect calls tools by name, else takes its number
  /// from the tool table (tool_call.hpp).
  void on(const cl::ToolChange& change) {
    const Dialect& d = writer_.dialect();
    const detail::ToolCall call = detail::tool_call_of(change, d, options_.tool_table.get(),
                                                       SourcePosition{input_, change.where.line, change.where.column});
    cl::ToolChange t = change;
    t.number = call.number.value_or(0);
    t.length_mm = call.length_mm;
    if (t.length_mm) check_tool_length(t, call);
    close_plane();
    last_rapid_.reset();
    last_was_feed_ = false;
    std::vector<std::string> blocks;
    auto add = [&](const std::vector<std::string>& list) {
      for (const auto& b : list) blocks.push_back(with_tool(b, tool_, length_register()));
    };
    if (rtcp_on_) add(d.rtcp_off);
    tool_ = t.number;
    tool_numbered_ = call.number.has_value();
    length_register_ = t.number;
    add(call.blocks);
    if (options_.rtcp)
      add(d.rtcp_on);
    else if (options_.tool_length_on_change)
      add(d.tool_length_on);
    rtcp_on_ = options_.rtcp;
    writer_.tool_change(blocks);
    if (t.length_mm)
      writer_.comment(fmt::format(
          "{} length {:.4f} mm from {}: {}", call.label, *t.length_mm, call.length_from,
          length_in_kinematics() ? "the axes are solved for it" : "the control's length register applies it"));
  }

  /// True when the axis positions the post writes depend on the tool length: a rotary axis on the
  /// tool side (a head) and no RTCP (with RTCP the control places the tip with its own length).
  bool length_in_kinematics() const {
    if (options_.rtcp || !words_.serial) return false;
    return std::any_of(machine_.axes.begin(), machine_.axes.end(),
                       [](const Axis& a) { return a.is_rotary() && a.side == Side::tool; });
  }

  /// LOADTL/n,LENGTH,l: on a machine whose axis positions depend on the tool length the post solves
  /// for one length (--tool-length); a tool of another length would cut off by the difference.
  void check_tool_length(const cl::ToolChange& t, const detail::ToolCall& call) const {
    if (!length_in_kinematics() || !options_.tool_length_mm) return;
    if (std::abs(*t.length_mm - *options_.tool_length_mm) <= 5e-4) return;
    throw InputError(
        SourcePosition{input_, t.where.line, t.where.column},
        fmt::format("{} is {:.4f} mm long ({}), but the axes of {} are solved for a tool "
                    "length of {:.4f} mm (--tool-length): on this machine the axis positions depend on the "
                    "tool length (rotary axes in the head), and the tool would cut {:.4f} mm off the path. "
                    "Post with --tool-length {:.4f} (one run per tool length), or with --rtcp (the "
                    "control applies each tool's length)",
                    call.length_from == "the CL data" ? fmt::format("LOADTL: tool {}", t.number) : call.label,
                    *t.length_mm, call.length_from == "the CL data" ? "LENGTH" : call.length_from, machine_.name,
                    *options_.tool_length_mm, std::abs(*t.length_mm - *options_.tool_length_mm), *t.length_mm));
  }

  /// The length register in force: the program's (G43 H), else the tool's own.
  int length_register() const { return length_register_.value_or(tool_); }

  /// G43 H<n> of G-code input: the length of register n, written where it is not the one in force
  /// (the tool's own after its change), with the dialect's length words naming the register
  /// ("{length}"); a dialect whose tool call sets the length (Sinumerik D, Heidenhain TOOL CALL)
  /// cannot write another register: refused rather than cut with the wrong length.
  void on(const cl::LengthOffset& l) {
    if (length_register_ == l.register_number) return;
    if (!options_.rtcp && !options_.tool_length_on_change) return;  // (TRR-XY: the machine's lengths)
    const Dialect& d = writer_.dialect();
    const std::vector<std::string>& words = options_.rtcp ? d.rtcp_on : d.tool_length_on;
    if (std::none_of(words.begin(), words.end(),
                     [](const std::string& b) { return b.find("{length}") != std::string::npos; }))
      throw InputError(SourcePosition{input_, l.where.line, l.where.column},
                       fmt::format("H{}: the tool length of register {} {}cannot be written in the {} dialect (its "
                                   "[tool] {} words name no register: {{length}}); program the tool's own register "
                                   "after its change, or post with a dialect that writes one (fanuc, haas)",
                                   l.register_number, l.register_number,
                                   length_register_ ? fmt::format("(the tool in the spindle is T{}) ", tool_) : "",
                                   d.name, options_.rtcp ? "rtcp_on" : "length_on"));
    close_plane();
    length_register_ = l.register_number;
    if (options_.rtcp && !rtcp_on_) return;  // written when RTCP goes on, before the first motion
    writer_.tool_blocks(words, tool_, length_register());
  }

  void on(const cl::Circle& c) { pending_circle_ = c; }
  void on(const cl::Cycle& c) {
    cycle_ = c;
    if (c.kind == cl::Cycle::Kind::off) writer_.end_cycle();
  }
  void on(const cl::Comment& c) { records_.comment(c); }
  void on(const cl::Unsupported& u) { records_.unsupported(u); }
  void on(const cl::Dwell& d) {
    records_.resume();  // a dwell after a stop waits with the spindle turning (it may be its run-up)
    for (const std::string& b : dwell_blocks(writer_.dialect(), d.seconds)) writer_.block(b);
  }
  /// A program stop moves nothing: it is written where it stands, also in a tilted work plane (the
  /// plane, like every modal frame, holds across M0/M1 on the controls of the dialects).
  void on(const cl::Stop& s) { records_.stop(s); }
  void on(const cl::End&) {}
  void on(const cl::ToolOffset& t) { detail::write_tool_offset(writer_, t, input_); }

  // ---- motion ----------------------------------------------------------------------------
  void notice(cl::Location where, const std::string& what) {
    summary_.notices.push_back(fmt::format("{}:{}: {}", input_, where.line, what));
  }

  void move_to(const ClPoint& cl, int line, bool rapid, std::optional<RotaryAngles> rotary = std::nullopt) {
    if (plane_ && (cl.axis - plane_->axis_W).norm() > 1e-9) close_plane();  // (a motion of a cycle or arc)
    if (plane_ && !rotary) {
      // the rotary axes stand still in the plane, where the point is within the limits there;
      // else the plane ends and the motion is posted as without it (limits, retract, message)
      const IkOutcome ik = solver_.solve_quiet(cl, previous_.q, data_, nullptr);
      if (ik.ok() && max_abs_step(ik.position->rotary_rad, plane_->rotary_rad) < 1e-9)
        rotary = plane_->rotary_rad;
      else
        close_plane();
    }
    SolvedPoint next{cl, {}};
    if (rotary) {
      next.q = solver_.with_rotary(cl, *rotary, data_);
    } else {
      IkOutcome ik;
      const bool ahead_fits = ahead_ && ahead_->fits(cl, previous_.q);
      if (planned_rotary_ && !(ahead_fits && ahead_->ik.ok() && ahead_->ik.position->rotary_rad == *planned_rotary_)) {
        // the solution the branch plan chose: the one nearest its rotary angles (else the greedy one)
        AxisPosition toward = previous_.q;
        toward.rotary_rad = *planned_rotary_;
        SolveFigures figures;
        IkOutcome planned = solver_.solve_quiet(cl, toward, data_, &figures);
        // (the same branch and turn: solutions apart are >= branch_change_rad apart; under --model
        // the compensated angles may differ from the plan's in the last digits)
        if (planned.ok() && max_abs_step(planned.position->rotary_rad, *planned_rotary_) < 1e-6) {
          ik = std::move(planned);
          data_.record(figures);
        }
        ahead_ = nullptr;
      }
      planned_rotary_.reset();
      if (ik.ok()) {
      } else if (ahead_fits && ahead_) {  // solved on the read-ahead thread
        ik = ahead_->ik;
        data_.record(ahead_->figures);
        ahead_ = nullptr;
      } else {
        ik = solver_.solve(cl, previous_.q, data_);
      }
      if (!ik.ok())
        throw Infeasible(unreachable_message(input_, line, solver_, data_, cl, previous_.q, ik.failure.message));
      next.q = *ik.position;
      next.executed = ik.executed;
    }
    if (options_.rtcp && !rtcp_on_) {  // motion before any tool change: the tool in the spindle (1)
      writer_.rtcp(true, tool_, length_register());
      rtcp_on_ = true;
    }
    if (!rapid && !records_.feed_given() && !default_feed_noticed_) {
      summary_.notices.push_back(fmt::format("{}:{}: feed motion before any FEDRAT: using {:.0f} mm/min", input_, line,
                                             options_.default_feed_mm_min));
      default_feed_noticed_ = true;
    }
    if (have_position_ && !rapid && options_.take_up_reversal && !options_.subdivide.takes_up_play()) {
      // an actual machine with reversal: take up the play of reversing axes first (tool still)
      if (auto q = solver_.take_up(previous_.q, next.q, data_)) {
        const SolvedPoint still{previous_.cl, *q};
        emit(previous_, still, line, false);
        previous_ = still;
      }
    }
    if (have_position_ && !rapid && !rotary && words_.serial && words_.rotary_count == 2 &&
        branch_changed(cl, next.q)) {
      if (options_.retract_mm <= 0.0)
        throw Infeasible(
            fmt::format("{}:{}: the axis limits force a change of solution (rotary {} -> {} deg) and "
                        "no retract is allowed",
                        input_, line, degrees_list(previous_.q.rotary_rad, 4), degrees_list(next.q.rotary_rad, 4)));
      retract_and_reorient(next, line);
    }
    // (in a tilted plane the tool axis and the rotary axes are still: a straight line, nothing to bound)
    if (have_position_ && (!rapid || options_.subdivide_rapids) && options_.subdivide && !options_.rtcp && !plane_) {
      SolvedPoint from = previous_;
      std::vector<SolvedPoint> points;
      try {
        points = options_.subdivide(previous_, next, data_);
      } catch (const Infeasible& e) {
        throw Infeasible(fmt::format("{}:{}: {}", input_, line, e.what()));
      }
      for (const SolvedPoint& p : points) {
        emit(from, p, line, rapid);
        from = p;
      }
    } else {
      emit(previous_, next, line, rapid);
    }
    previous_ = next;
    have_position_ = true;
  }

  /// True when `q` (solved for `cl`) is on another branch than the continuous one because of the limits.
  bool branch_changed(const ClPoint& cl, const AxisPosition& q) const {
    return forced_change(cl.axis, previous_.q.rotary_rad, q.rotary_rad);
  }

  /// Retract along the tool axis from the previous point, reorient above `next` on its branch,
  /// then the caller re-engages (feeds down to `next`).
  void retract_and_reorient(const SolvedPoint& next, int line) {
    const double d = options_.retract_mm;
    const ClPoint up_here{previous_.cl.tip_mm + d * previous_.cl.axis, previous_.cl.axis};
    const ClPoint up_there{next.cl.tip_mm + d * next.cl.axis, next.cl.axis};
    const IkOutcome a = solver_.solve(up_here, previous_.q, data_);
    const IkOutcome b = solver_.solve(up_there, next.q, data_);
    if (!a.ok() || !b.ok())
      throw Infeasible(unreachable_message(
          input_, line, solver_, data_, !a.ok() ? up_here : up_there, !a.ok() ? previous_.q : next.q,
          fmt::format("the axis limits force a change of solution, and the retract point {} mm along the tool axis "
                      "is out of reach: {}",
                      d, !a.ok() ? a.failure.message : b.failure.message)));
    summary_.notices.push_back(fmt::format(
        "{}:{}: the axis limits force a change of solution (rotary {} -> {} deg): retract {} mm along the tool "
        "axis, reorient, re-engage",
        input_, line, degrees_list(previous_.q.rotary_rad, 3), degrees_list(next.q.rotary_rad, 3), d));
    ++summary_.retracts;
    writer_.comment("retract, reorient, re-engage (axis limits)");
    const SolvedPoint p1{up_here, *a.position}, p2{up_there, *b.position};
    emit(previous_, p1, line, false);
    emit(p1, p2, line, true);
    previous_ = p2;
  }

  void emit(const SolvedPoint& from, const SolvedPoint& to, int line, bool rapid) {
    NcMotion m;
    m.rapid = rapid;
    if (plane_) {
      const Vec3d in_plane = plane_->words.to_plane(to.cl.tip_mm + home_offset_);
      for (int i = 0; i < 3; ++i) m.values[static_cast<std::size_t>(i)] = in_plane[i];
    } else if (options_.rtcp) {
      const Vec3d tip_mm = solver_.programmed_tip(to.cl, to.q);
      for (int i = 0; i < 3; ++i) m.values[static_cast<std::size_t>(i)] = tip_mm[i];
    }
    for (int i = (options_.rtcp || plane_) ? 3 : 0; i < words_.count; ++i) {  // the words of the solver (CommandWords)
      const auto u = static_cast<std::size_t>(i);
      m.values[u] = words_.angle[u] ? rad_to_deg(to.q[i]) : to.q[i];
    }
    // the control executes the rounded values (in a tilted plane: through the plane's words)
    AxisPosition executed = to.q;
    if (plane_) {
      executed = plane_executed(Vec3d(m.values[0], m.values[1], m.values[2]));
    } else {
      for (int i = 0; i < words_.count; ++i)
        executed[i] = words_.angle[static_cast<std::size_t>(i)] ? deg_to_rad(writer_.rounded(i, rad_to_deg(to.q[i])))
                                                                : writer_.rounded(i, to.q[i]);
    }
    const double feed = records_.feed_mm_min(options_.default_feed_mm_min);
    const double rotary_travel_deg =
        words_.rotary_count > 0 ? rad_to_deg(max_abs_step(to.q.rotary_rad, from.q.rotary_rad)) : 0.0;
    // (in a tilted plane the control turned the rotary axes before: the block moves X Y Z only)
    const bool simultaneous = !plane_ && words_.rotary_count > 0 && rotary_travel_deg > 1e-9;
    const bool inverse = !options_.rtcp && options_.feed_mode != PostOptions::FeedMode::per_minute &&
                         (options_.feed_mode == PostOptions::FeedMode::inverse_time || simultaneous);
    if (inverse && !rapid && writer_.dialect().motion.inverse_time.empty())
      // an inverse-time number written as a plain feed would run at the wrong feed
      throw Infeasible(fmt::format(
          "{}:{}: this move turns a rotary axis while the tool cuts, and the {} dialect has no inverse-time feed "
          "(G93) for it ([motion] inverse_time is empty in {}): post with --rtcp (the control's tool-tip control "
          "keeps the feed)",
          input_, line, writer_.dialect().name, writer_.dialect().file));
    if (inverse) {
      // the block's time by the rule of inverse_time.hpp: the executed tip path over the feed
      const bool tip_moves = (to.cl.tip_mm - from.cl.tip_mm).norm() > kStillTipMm;
      const double path_mm = tip_moves && !rapid ? executed_tip_path_mm(last_executed_, executed) : 0.0;
      const double minutes = inverse_time_minutes(path_mm, tip_moves, rotary_travel_deg, feed);
      m.feed_mode = NcMotion::FeedMode::inverse_time;
      m.feed = minutes > 0.0 ? 1.0 / minutes : 99999.0;
    } else {
      m.feed = feed;
    }
    bool split = false;
    std::optional<detail::ReadBackBlock> first_block, block;  // read back (--verify)
    WrittenState in_force = read_back_ ? writer_.in_force() : WrittenState{};
    if (rapid && options_.order_rapids && last_values_) {
      split = write_retract_or_approach(from, to, m);
      if (split && read_back_) {
        first_block = read_written(in_force, from.cl, to.cl, line);
        in_force = writer_.in_force();
      }
    }
    last_values_ = m.values;
    const bool written = writer_.motion(m);
    if (written && split) ++summary_.rapid_splits;
    if (!written && !split) return;  // the control is already there
    // (a split rapid that keeps Z is written whole by its first block: the machine is at `to` all the same)
    if (written && read_back_) block = read_written(in_force, from.cl, to.cl, line);
    if (read_back_) check_written(from, to, line, rapid, m, first_block, block);
    if (written && options_.on_block && have_position_)
      options_.on_block(WrittenBlock{line, rapid, from.cl, to.cl, last_executed_, executed});
    solver_.advance(executed, data_);
    last_executed_ = executed;
  }

  // ---- --verify: the program as written, read back (read_back.hpp) -------------------------
  /// The block just written, read back from the words in force before it (`in_force`).
  detail::ReadBackBlock read_written(const WrittenState& in_force, const ClPoint& from, const ClPoint& to, int line) {
    detail::ReadBackBlock b;
    b.from = in_force;
    b.text = writer_.last_line();
    b.program_line = writer_.lines_written();
    b.cl_line = line;
    b.cl_from_mm = from.tip_mm;
    b.cl_to_mm = to.tip_mm;
    read_back_->start_from(in_force);
    try {
      b.to = read_back_->read(b.text);
    } catch (const std::runtime_error& e) {
      detail::add_defect(summary_.verify, b.program_line, line, e.what());
      b.to = writer_.in_force();
    }
    return b;
  }

  /// The commands (mm, rad) the control reaches at the words `v` (machine axes or a tilted plane).
  AxisPosition commands_of(const PerAxis<double>& v) const {
    if (plane_) return plane_executed(Vec3d(v[0], v[1], v[2]));
    AxisPosition q = words_.home();
    for (int i = 0; i < words_.count; ++i) {
      const auto u = static_cast<std::size_t>(i);
      q[i] = words_.angle[u] ? deg_to_rad(v[u]) : v[u];
    }
    return q;
  }

  /// The words of `a` and `b` interpolated at t (a word not in force stands at the other's value).
  PerAxis<double> words_at(const WrittenState& a, const WrittenState& b, double t) const {
    PerAxis<double> v{};
    for (int i = 0; i < words_.count; ++i) {
      const auto u = static_cast<std::size_t>(i);
      const double va = a.values[u].value_or(b.values[u].value_or(0.0)), vb = b.values[u].value_or(va);
      v[u] = va + t * (vb - va);
    }
    return v;
  }

  /// Where the tool is (W) at t of the move from the words `a` to `b` (detail::ExecuteWords).
  ToolPoseT<double> execute_words(const WrittenState& a, const WrittenState& b, double t) const {
    const PerAxis<double> v = words_at(a, b, t);
    ToolPoseT<double> pose = solver_.execute(commands_of(v), data_);
    if (options_.rtcp && !plane_) pose.tip_mm = Vec3d(v[0], v[1], v[2]);  // the control holds the tip on the words
    return pose;
  }

  /// --verify of the blocks written for one CL motion: their words, feeds and (rapids) their lines.
  void check_written(const SolvedPoint& from, const SolvedPoint& to, int line, bool rapid, const NcMotion& m,
                     const std::optional<detail::ReadBackBlock>& first,
                     const std::optional<detail::ReadBackBlock>& block) {
    const detail::ExecuteWords execute = [this](const WrittenState& a, const WrittenState& b, double t) {
      return execute_words(a, b, t);
    };
    const double tol = detail::kRapidLineToleranceMm;
    for (const auto* b : {&first, &block}) {
      if (!*b) continue;
      const auto kind = (*b)->to.motion;
      if (kind != (rapid ? WrittenState::Motion::rapid : WrittenState::Motion::linear))
        detail::add_defect(summary_.verify, (*b)->program_line, line,
                           fmt::format("'{}' is not written as a {}", (*b)->text, rapid ? "rapid" : "feed move"));
    }
    if (rapid) {
      const std::optional<detail::ReadBackBlock>& leaving = first ? first : block;
      // (rapids cut to the tolerance, subdivide_rapids, follow the CL line within it: not checked here)
      if (last_was_feed_ && leaving && !options_.subdivide_rapids &&
          (to.cl.tip_mm - from.cl.tip_mm).dot(from.cl.axis.normalized()) > tol) {
        const double off = detail::rapid_off_line_mm(*leaving, true, execute);
        if (off > tol)
          detail::add_defect(
              summary_.verify, leaving->program_line, line,
              fmt::format("the rapid out of the cut leaves the tool axis line (and the straight CL rapid) "
                          "by {:.4f} mm: the tool is dragged sideways",
                          off));
      }
      last_rapid_ = block ? block : first;
      last_was_feed_ = false;
      return;
    }
    if (last_rapid_ && !options_.subdivide_rapids &&
        (last_rapid_->cl_from_mm - from.cl.tip_mm).dot(from.cl.axis.normalized()) > tol) {
      const double off = detail::rapid_off_line_mm(*last_rapid_, false, execute);
      if (off > tol)
        detail::add_defect(
            summary_.verify, last_rapid_->program_line, last_rapid_->cl_line,
            fmt::format("the rapid into the cut of CL line {} leaves the tool axis line (and the straight "
                        "CL rapid) by {:.4f} mm: the tool comes in sideways",
                        line, off));
    }
    last_rapid_.reset();
    last_was_feed_ = true;
    if (!block) return;
    check_feed_word(*block, from, to, line, m);
    if (options_.rtcp || !have_position_) return;  // under RTCP the control does the kinematics
    const double contour_mm =
        verify_block(solver_, data_, from.cl, commands_of(words_at(block->from, block->to, 0.0)), to.cl,
                     commands_of(words_at(block->from, block->to, 1.0)), line, summary_.verify);
    if (options_.on_verified) options_.on_verified(line, contour_mm);
  }

  /// The feed word of a written feed block against its rule: per minute the CL feed; inverse time
  /// 1 / (executed tip path / CL feed) (inverse_time.hpp) on the words as written.
  void check_feed_word(const detail::ReadBackBlock& b, const SolvedPoint& from, const SolvedPoint& to, int line,
                       const NcMotion& m) {
    const MotionWords& w = writer_.dialect().motion;
    const double feed = records_.feed_mm_min(options_.default_feed_mm_min);
    const bool inverse = m.feed_mode == NcMotion::FeedMode::inverse_time;
    for (int i = 0; i < words_.count; ++i)  // the first motion: it starts where the machine happens to be
      if (inverse && !b.from.values[static_cast<std::size_t>(i)]) return;
    if (b.to.inverse_time != inverse || !b.to.feed) {
      detail::add_defect(summary_.verify, b.program_line, line,
                         fmt::format("'{}' runs {}, the block needs {}", b.text,
                                     !b.to.feed          ? "with no feed in force"
                                     : b.to.inverse_time ? "in inverse time"
                                                         : "per minute",
                                     inverse ? "inverse time (G93: it turns a rotary axis)" : "a feed per minute"));
      return;
    }
    double expected = feed;
    double allowed = 0.5 * std::pow(10.0, -w.feed_decimals) + 1e-9;
    if (inverse) {
      const bool tip_moves = (to.cl.tip_mm - from.cl.tip_mm).norm() > kStillTipMm;
      const double path_mm = tip_moves ? executed_tip_path_mm(commands_of(words_at(b.from, b.to, 0.0)),
                                                              commands_of(words_at(b.from, b.to, 1.0)))
                                       : 0.0;
      const double deg = words_.rotary_count > 0 ? rad_to_deg(max_abs_step(to.q.rotary_rad, from.q.rotary_rad)) : 0.0;
      const double minutes = inverse_time_minutes(path_mm, tip_moves, deg, feed);
      expected = minutes > 0.0 ? 1.0 / minutes : 99999.0;
      allowed = 0.5 * std::pow(10.0, -w.inverse_time_decimals) + 1e-4 * expected;
    }
    if (std::abs(*b.to.feed - expected) > allowed)
      detail::add_defect(summary_.verify, b.program_line, line,
                         fmt::format("the feed word of '{}' is {}; by its rule it is {:.4f} ({})", b.text, *b.to.feed,
                                     expected, inverse ? "1 / (tip path / CL feed)" : "the CL feed, mm/min"));
  }

  /// The words of a written arc block: its direction word and its feed (per minute, the CL feed).
  void check_arc_words(const detail::ReadBackBlock& b, const NcArc& arc) {
    using Motion = WrittenState::Motion;
    const Motion meant = arc.clockwise ? Motion::clockwise : Motion::counter_clockwise;
    if (b.to.motion != meant)
      detail::add_defect(summary_.verify, b.program_line, b.cl_line,
                         fmt::format("'{}' turns the arc {}: the CL circle runs {} in the program's plane", b.text,
                                     b.to.motion == Motion::clockwise           ? "clockwise"
                                     : b.to.motion == Motion::counter_clockwise ? "counter-clockwise"
                                                                                : "not as an arc",
                                     arc.clockwise ? "clockwise" : "counter-clockwise"));
    const double allowed = 0.5 * std::pow(10.0, -writer_.dialect().motion.feed_decimals) + 1e-9;
    if (b.to.inverse_time || !b.to.feed || std::abs(*b.to.feed - arc.feed_mm_min) > allowed)
      detail::add_defect(
          summary_.verify, b.program_line, b.cl_line,
          fmt::format("the feed of '{}' is not the CL feed {:.1f} mm/min per minute", b.text, arc.feed_mm_min));
  }

  /// The model the program's times are computed on: the post's (under --verify-on, not the
  /// verifying machine's, so that the program does not depend on it).
  const KinematicModel& feed_solver() const { return options_.feed_solver ? *options_.feed_solver : solver_; }

  /// The first block of a rapid in two (PostOptions::order_rapids): going up, the tool leaves
  /// along its axis at `from` until it is level with the target; going down, it travels to the
  /// point on the axis line of `to` level with where it is, then (the caller's block) descends
  /// along that line. Level: Z of the program frame. With the tool along +Z of the program frame
  /// this is Z first up / Z last down. Not split (one straight block, as the CL data give it) where
  /// the tool axis is within 60 deg of horizontal in the program frame or the point on the line
  /// is beyond a linear axis's limits. True when the block was written.
  bool write_retract_or_approach(const SolvedPoint& from, const SolvedPoint& to, const NcMotion& m) {
    const PerAxis<double>& last = *last_values_;
    const bool up = m.values[2] > last[2];
    const SolvedPoint& still = up ? from : to;
    const Vec3d d = tool_axis_in_program(still.cl, still.q.rotary_rad);
    if (!(d.z() >= 0.5)) return false;
    const Vec3d at_still = up ? Vec3d(last[0], last[1], last[2]) : Vec3d(m.values[0], m.values[1], m.values[2]);
    const double level = up ? m.values[2] : last[2];
    const Vec3d on_line = at_still + ((level - at_still.z()) / d.z()) * d;
    NcMotion first = m;
    if (up) first.values = last;  // the rotary axes turn in the second block
    for (int i = 0; i < 3; ++i) {
      first.values[static_cast<std::size_t>(i)] = on_line[i];
      const Axis& axis = machine_.axes[static_cast<std::size_t>(i)];
      if (!plane_ && !options_.rtcp && axis.limits && !axis.limits->contains(on_line[i])) return false;
    }
    return writer_.motion(first);  // nothing is written if no word changes
  }

  /// The direction, in the program frame's X Y Z words, in which the tool tip moves along the tool
  /// axis of `cl` (unit length in W) with the rotary axes at `rotary_rad`: +Z in a tilted plane,
  /// the CL axis under RTCP (the words are the tip in W), else the linear axes' direction.
  Vec3d tool_axis_in_program(const ClPoint& cl, const RotaryAngles& rotary_rad) const {
    if (plane_) return Vec3d::UnitZ();
    if (options_.rtcp) return cl.axis.normalized();
    const Vec3d tip = solver_.with_rotary(cl, rotary_rad, data_).linear_mm;
    const Vec3d above =
        solver_.with_rotary(ClPoint{cl.tip_mm + cl.axis.normalized(), cl.axis}, rotary_rad, data_).linear_mm;
    return above - tip;
  }

  /// The length (mm) of the tool tip's path in W while the axes run linearly from `q0` to `q1`.
  double executed_tip_path_mm(const AxisPosition& q0, const AxisPosition& q1) const {
    return tip_path_length_mm(
        [&](double t) { return feed_solver().execute(nonlinear::lerp(q0, q1, t), data_).tip_mm; });
  }

  void move_along_arc(const cl::Circle& c, const cl::Motion& end, bool rapid) {
    const Vec3d start = previous_.cl.tip_mm;
    const Vec3d stop = end.point.tip_mm;
    const Vec3d n = c.axis;
    const Vec3d r0 = (start - c.center_mm) - (start - c.center_mm).dot(n) * n;
    const Vec3d r1 = (stop - c.center_mm) - (stop - c.center_mm).dot(n) * n;
    auto sweep = angle_about(n, r0, r1, 1e-9);
    if (!sweep || r0.norm() < 1e-9) {
      move_to(end.point, end.where.line, rapid);
      return;
    }
    double angle = *sweep;
    if (angle <= 1e-12) angle += 2.0 * kPi;  // counter-clockwise about the circle axis
    angle += 2.0 * kPi * c.extra_turns;      // a helix of several turns (one pitch over all of them)
    if (c.extra_turns == 0 && native_arc(c, end, rapid, angle)) return;
    const double radius = r0.norm();
    const double tol = std::min(options_.arc_tolerance_mm, 0.5 * radius);
    const double step = 2.0 * std::acos(1.0 - tol / radius);
    const int n_steps = std::max(1, static_cast<int>(std::ceil(angle / step)));
    const double along0 = (start - c.center_mm).dot(n), along1 = (stop - c.center_mm).dot(n);
    const Vec3d axis0 = previous_.cl.axis;
    for (int i = 1; i <= n_steps; ++i) {
      const double t = static_cast<double>(i) / n_steps;
      ClPoint p;
      p.tip_mm = i == n_steps
                     ? stop
                     : c.center_mm + rotation_about<double>(n, t * angle) * r0 + (along0 + t * (along1 - along0)) * n;
      p.axis = nonlinear::slerp(axis0, end.point.axis, t);  // a great circle also between opposite axes
      move_to(p, end.where.line, rapid);
    }
  }

  /// The arc from the current point to `end` about `c` (sweep `angle` counter-clockwise about the
  /// circle axis) as one G2/G3 block, when the program's frame sees it in a principal plane; a
  /// helix (the end higher or lower along the axis) carries the third coordinate in the same block.
  bool native_arc(const cl::Circle& c, const cl::Motion& end, bool rapid, double angle) {
    if (!options_.native_arcs || rapid || !writer_.dialect().arcs || !have_position_) return false;
    const Vec3d n = c.axis.normalized();
    const Vec3d start = previous_.cl.tip_mm, stop = end.point.tip_mm;
    if (previous_.cl.axis.cross(n).norm() > 1e-9 || end.point.axis.cross(n).norm() > 1e-9) return false;
    const IkOutcome ik = solver_.solve(end.point, previous_.q, data_);
    if (!ik.ok() || max_abs_step(ik.position->rotary_rad, previous_.q.rotary_rad) > 1e-12) return false;
    const Vec3d centre = c.center_mm + (start - c.center_mm).dot(n) * n;  // in the plane of the arc
    // the arc in the program's frame: W under RTCP, else the linear axes for the fixed rotary angles
    auto frame = [&](const Vec3d& p) -> Vec3d {
      if (plane_) return plane_->words.to_plane(p + home_offset_);
      if (options_.rtcp) return p;
      return solver_.with_rotary(ClPoint{p, n}, previous_.q.rotary_rad, data_).linear_mm;
    };
    const Vec3d xs = frame(start), xe = frame(stop), xc = frame(centre);
    const Vec3d normal = frame(centre + n) - xc;  // the circle axis in the frame (unit: a rigid map)
    int plane_axis = -1;
    for (int k = 0; k < 3; ++k)
      if (std::abs(std::abs(normal[k]) - 1.0) < 1e-9) plane_axis = k;
    if (plane_axis < 0) return false;
    // a helix rises along the circle axis: its radius is measured in the plane of the arc
    const Vec3d to_end = xe - xc;
    const double r_start = (xs - xc).norm(), r_end = (to_end - to_end.dot(normal) * normal).norm();
    // CAM data carry 4 decimals; controls accept a few µm between the start and end radii
    if (r_start < 1e-3 || std::abs(r_start - r_end) > 5e-4 || angle < 1e-6) return false;
    NcArc arc;
    arc.plane = plane_axis == 2 ? 17 : plane_axis == 1 ? 18 : 19;
    arc.clockwise = normal[plane_axis] < 0.0;  // counter-clockwise about the frame's −axis is clockwise about +axis
    for (int k = 0; k < 3; ++k) {
      arc.end_mm[static_cast<std::size_t>(k)] = xe[k];
      arc.centre_offset_mm[static_cast<std::size_t>(k)] = xc[k] - xs[k];
    }
    arc.feed_mm_min = records_.feed_mm_min(options_.default_feed_mm_min);
    const WrittenState arc_in_force = read_back_ ? writer_.in_force() : WrittenState{};
    writer_.arc(arc);
    std::optional<detail::ReadBackBlock> written;  // read back (--verify)
    if (read_back_) {
      written = read_written(arc_in_force, previous_.cl, end.point, end.where.line);
      check_arc_words(*written, arc);
      last_rapid_.reset();
      last_was_feed_ = true;
    }
    const std::optional<PerAxis<double>> start_words = last_values_;  // as the control has them
    if (last_values_)
      for (int k = 0; k < 3; ++k) (*last_values_)[static_cast<std::size_t>(k)] = writer_.rounded(k, xe[k]);
    SolvedPoint next{end.point, plane_ ? solver_.with_rotary(end.point, plane_->rotary_rad, data_) : *ik.position};
    AxisPosition executed = next.q;
    if (plane_)
      executed = plane_executed(xe);
    else
      for (int i = 0; i < 3; ++i) executed.linear_mm[i] = writer_.rounded(i, next.q.linear_mm[i]);
    if (written && !options_.rtcp) verify_native_arc(*written, arc, start_words, normal, angle, c, end, executed);
    solver_.advance(executed, data_);
    last_executed_ = executed;
    previous_ = next;
    ++summary_.arcs_out;
    return true;
  }

  /// `post --verify` of a native arc: the circle the control interpolates from the words as written
  /// (the start where the axes stand, the centre offset and the end rounded), executed on the
  /// machine, against the CL circle (verify_arc.hpp). Before previous_ and last_executed_ move on.
  void verify_native_arc(const detail::ReadBackBlock& written, const NcArc& arc,
                         const std::optional<PerAxis<double>>& start_words, const Vec3d& normal, double angle,
                         const cl::Circle& c, const cl::Motion& end, const AxisPosition& executed_end) {
    FrameArc run;
    run.start_mm = plane_ && start_words ? Vec3d((*start_words)[0], (*start_words)[1], (*start_words)[2])
                                         : Vec3d(last_executed_.linear_mm);
    // the circle of the words as written: the centre offset and the end read back, and the way
    // round the written G2/G3 gives (the other way round: about -normal, the rest of the turn)
    const PerAxis<double> end_words = words_at(written.from, written.to, 1.0);
    for (int k = 0; k < 3; ++k) {
      run.centre_mm[k] = run.start_mm[k] + written.to.centre_offset_mm[static_cast<std::size_t>(k)];
      run.end_mm[k] = end_words[static_cast<std::size_t>(k)];
    }
    const bool as_meant = (written.to.motion == WrittenState::Motion::clockwise) == arc.clockwise;
    run.normal = as_meant ? normal : Vec3d(-normal);
    run.sweep_rad = as_meant ? angle : 2.0 * kPi - angle;
    const RotaryAngles rotary = last_executed_.rotary_rad;
    const std::function<AxisPosition(const Vec3d&)> commands_at = [&](const Vec3d& x) {
      if (plane_) return plane_executed(x);
      AxisPosition q = executed_end;
      q.linear_mm = x;
      q.rotary_rad = rotary;
      return q;
    };
    const ClArc cl{previous_.cl.tip_mm, c.center_mm, end.point.tip_mm, c.axis.normalized(), previous_.cl.axis, angle};
    const double contour_mm = verify_arc(solver_, data_, run, commands_at, cl, end.where.line, summary_.verify);
    if (options_.on_verified) options_.on_verified(end.where.line, contour_mm);
  }

  /// One hole of the active cycle: native (cycle_words.hpp) where the hole runs down −Z of the
  /// program frame, else explicit moves along the tool axis (post_cycle.hpp).
  void drill(const cl::Motion& m) {
    const detail::HolePlanes p = detail::hole_planes(cycle_, m.point);
    const double rpm = records_.spindle_rpm();
    const SourcePosition at{input_, m.where.line, m.where.column};
    double feed = records_.feed_mm_min(options_.default_feed_mm_min);
    if (cycle_.feed && cycle_.feed_per_rev && !(rpm > 0.0))
      throw InputError(at, "a cycle feed per revolution before any spindle speed (give SPINDL/rpm before the cycle)");
    if (cycle_.feed) feed = cycle_.feed_per_rev ? *cycle_.feed * rpm : *cycle_.feed;
    if (cycle_.kind == cl::Cycle::Kind::tap) {
      if (!(rpm > 0.0))
        throw InputError(at,
                         "a tapped hole before any spindle speed: the tapping feed (pitch x rpm) is unknown "
                         "(give SPINDL/rpm before the cycle)");
      feed = cycle_.pitch_mm * rpm;
    }
    if (native_hole(p, feed, m.where.line)) return;
    const RecordBlocks::Saved saved = records_.save();
    move_to(p.retract, m.where.line, true);
    for (const detail::HoleStep& s : detail::expand_hole(cycle_, p, feed, records_.spindle_ccw())) {
      using Kind = detail::HoleStep::Kind;
      if (s.kind == Kind::rapid || s.kind == Kind::feed) {
        records_.set_feed(s.feed_mm_min > 0.0 ? s.feed_mm_min : feed);
        move_to(s.to, m.where.line, s.kind == Kind::rapid);
      } else if (s.kind == Kind::dwell) {
        for (const std::string& b : dwell_blocks(writer_.dialect(), s.dwell_s)) writer_.block(b);
      } else if (s.turn == detail::HoleStep::Turn::stop) {
        writer_.spindle_stop();
      } else {
        writer_.spindle_turn(s.turn == detail::HoleStep::Turn::counter_clockwise);
      }
    }
    records_.restore(saved);
  }

  bool native_hole(const detail::HolePlanes& p, double feed, int line) {
    const auto words = cycle_words(writer_.dialect());
    if (!options_.native_cycles || !words) return false;
    const IkOutcome ik = solver_.solve(p.retract, previous_.q, data_);
    if (!ik.ok()) return false;  // the expansion names the failure
    const RotaryAngles rotary = ik.position->rotary_rad;
    auto frame = [&](const ClPoint& c) -> Vec3d {
      if (plane_) return plane_->words.to_plane(c.tip_mm + home_offset_);
      return options_.rtcp ? solver_.programmed_tip(c, *ik.position) : solver_.with_rotary(c, rotary, data_).linear_mm;
    };
    const Vec3d xt = frame(p.retract), xr = frame(p.r_plane), xb = frame(p.bottom);
    // in a tilted plane its Z (rounded angles) is within ~1e-6 rad of the hole: the hole is native
    // where that leaves its top within half the words' resolution of the bottom's X Y
    const double across = plane_ ? 0.5 * std::pow(10.0, -writer_.dialect().linear_decimals) : 1e-7;
    auto on_axis = [&](const Vec3d& a) {
      return std::abs(a.x() - xb.x()) < across && std::abs(a.y() - xb.y()) < across;
    };
    if (!on_axis(xt) || !on_axis(xr) || !(xb.z() < xr.z()) || xt.z() < xr.z() - 1e-9) return false;
    std::string note;
    const auto nc = detail::native_hole(cycle_, *words, xr, xb, p.retract_to_r, feed, records_.spindle_rpm(),
                                        writer_.dialect().linear_decimals, note);
    if (!nc) return false;
    if (!note.empty() && noticed_cycle_line_ != cycle_.where.line) {
      notice(cycle_.where, note);
      noticed_cycle_line_ = cycle_.where.line;
    }
    const SolvedPoint at_retract{p.retract, *ik.position};
    const bool same_rotary = !have_position_ || max_abs_step(rotary, previous_.q.rotary_rad) < 1e-12;
    if (have_position_ && same_rotary && writer_.continues(*nc, p.retract_to_r ? xr.z() : xt.z())) {
      // the modal cycle travels there itself: the tool stands at the return level over the hole
      AxisPosition executed = at_retract.q;
      if (plane_)
        executed = plane_executed(xt);
      else
        for (int i = 0; i < 3; ++i) executed.linear_mm[i] = writer_.rounded(i, executed.linear_mm[i]);
      solver_.advance(executed, data_);
      last_executed_ = executed;
      previous_ = at_retract;
      if (last_values_)
        for (int k = 0; k < 3; ++k) (*last_values_)[static_cast<std::size_t>(k)] = writer_.rounded(k, xt[k]);
    } else {
      writer_.end_cycle();
      move_to(p.retract, line, true);
    }
    writer_.cycle(*nc);
    last_rapid_.reset();  // the cycle leaves and enters its holes along Z itself
    last_was_feed_ = false;
    ++summary_.cycles_out;
    if (options_.verify && !options_.rtcp) {
      // the feed of the cycle block re-executed: R plane to the bottom (and back for taps and bores)
      auto executed = [&](const ClPoint& c) {
        if (plane_) return plane_executed(frame(c));
        AxisPosition q = solver_.with_rotary(c, rotary, data_);
        for (int i = 0; i < 3; ++i) q.linear_mm[i] = writer_.rounded(i, q.linear_mm[i]);
        return q;
      };
      const double e = verify_block(solver_, data_, p.r_plane, executed(p.r_plane), p.bottom, executed(p.bottom), line,
                                    summary_.verify);
      if (options_.on_verified) options_.on_verified(line, e);
    }
    return true;
  }

  /// CUTCOM/LEFT|RIGHT|OFF as G41/G42 D<n> / G40 (cycle_words.hpp `comp_words`).
  void on(const cl::CutterComp& c) {
    const SourcePosition at{input_, c.where.line, c.where.column};
    if (!words_.serial && c.side != cl::CutterComp::Side::off)
      throw InputError(at,
                       fmt::format("cutter radius compensation is not posted on the {} machine (its control "
                                   "compensates in no plane of these axes): post the tool centre path without "
                                   "CUTCOM",
                                   machine_.name),
                       "CUTCOM/" + c.text);
    if (!words_.serial) return;  // CUTCOM/OFF: nothing was on
    const auto words = comp_words(writer_.dialect());
    if (!words)
      throw InputError(at,
                       fmt::format("CUTCOM: the {} dialect writes no radius compensation ([compensation] native "
                                   "= false in {}); post with a dialect that has it, or post the path without "
                                   "CUTCOM",
                                   writer_.dialect().name, writer_.dialect().file),
                       "CUTCOM/" + c.text);
    comp_ = c;
    if (c.side == cl::CutterComp::Side::off) {
      writer_.block(words->off);
      return;
    }
    if (words->register_letter.empty() && c.offset_register && *c.offset_register != tool_)
      // (Sinumerik: G41/G42 take the radius of the edge the tool call selected, D1)
      throw InputError(at,
                       fmt::format("CUTCOM/{}: radius register {} cannot be written in the {} dialect (G41/G42 "
                                   "take the radius of the active tool's edge: [compensation] register_letter is "
                                   "empty in {}); give the tool's own radius (CUTCOM/{} without a register), or "
                                   "post with a dialect that writes one (fanuc, haas, linuxcnc)",
                                   c.text, *c.offset_register, writer_.dialect().name, writer_.dialect().file,
                                   c.side == cl::CutterComp::Side::left ? "LEFT" : "RIGHT"),
                       "CUTCOM/" + c.text);
    if (!words->register_letter.empty() && !c.offset_register && !tool_numbered_)
      throw InputError(at,
                       fmt::format("{}: the {} dialect names the radius register, by default the tool's number, "
                                   "but the tool was called by name: give its number in a tool table "
                                   "(--tool-table FILE; docs/formats.md, Tool tables)",
                                   c.text, writer_.dialect().name),
                       c.text);
    const int reg = c.offset_register.value_or(tool_);
    writer_.block(
        (c.side == cl::CutterComp::Side::left ? words->left : words->right) +
        (words->register_letter.empty() ? std::string() : " " + words->register_letter + std::to_string(reg)));
  }

  /// With G41/G42 active the motion must keep the tool axis and have it along Z of the program
  /// frame (the control compensates in the XY plane): else the post stops.
  void check_comp(const cl::Motion& m) {
    if (!comp_ || comp_->side == cl::CutterComp::Side::off || !have_position_) return;
    const std::string side = comp_->side == cl::CutterComp::Side::left ? "LEFT" : "RIGHT";
    const SourcePosition at{input_, m.where.line, m.where.column};
    if (m.point.axis.cross(previous_.cl.axis).norm() > 1e-9)
      throw InputError(at, fmt::format("CUTCOM/{} (line {}) is active in a simultaneous five-axis move (the tool axis "
                                       "turns): G41/G42 compensate in a plane normal to a fixed tool axis; post the "
                                       "path without CUTCOM (the CL data are then the tool centre path)",
                                       side, comp_->where.line));
    if (plane_) return;  // the plane's Z is the tool axis: G41/G42 compensate in its XY
    const Vec3d tip = options_.rtcp ? previous_.cl.tip_mm
                                    : solver_.with_rotary(previous_.cl, previous_.q.rotary_rad, data_).linear_mm;
    const Vec3d up = options_.rtcp
                         ? Vec3d(previous_.cl.tip_mm + previous_.cl.axis)
                         : solver_
                               .with_rotary(ClPoint{previous_.cl.tip_mm + previous_.cl.axis, previous_.cl.axis},
                                            previous_.q.rotary_rad, data_)
                               .linear_mm;
    if ((up - tip - Vec3d::UnitZ()).norm() > 1e-6)
      throw InputError(at, fmt::format("CUTCOM/{} (line {}): the tool axis is not along Z of the program frame here, "
                                       "and G41/G42 compensate in the XY plane; post the path without CUTCOM",
                                       side, comp_->where.line));
  }

  const std::string& input_;
  const detail::AheadSolve* ahead_ = nullptr;  ///< the current record's motion solved ahead
  std::optional<RotaryAngles> planned_rotary_;
  bool unplanned_run_ = false;  ///< in a run too long to plan (continues_unplanned_run)  ///< the current record's
                                ///< rotary angles chosen by the branch plan
  std::deque<detail::AheadItem> pending_;   ///< records read and planned, not posted yet
  std::optional<detail::AheadItem> carry_;  ///< a rapid read by the last plan: it opens the next run
  SolverData plan_data_;                    ///< the solver's working data of the branch plan
  const KinematicModel& solver_;
  SolverData& data_;  ///< the solver's working data on the post's thread
  NcWriter& writer_;
  const PostOptions& options_;
  const Machine& machine_;
  const CommandWords words_;  ///< what each command slot is (read once: no virtual call per point)
  PostSummary summary_;
  SolvedPoint previous_{};
  AxisPosition last_executed_{};
  std::optional<PerAxis<double>> last_values_;       ///< words of the last motion block (mm, deg)
  std::optional<WrittenBlockReader> read_back_;      ///< --verify: the blocks as written, read back
  std::optional<detail::ReadBackBlock> last_rapid_;  ///< the last rapid written (an approach if a feed follows)
  bool last_was_feed_ = false;                       ///< the last motion written was a feed move
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

  // ---- tilted work planes (PostOptions::tilted_plane, tilted_plane.hpp) ------------------------
  /// The plane the program is in: its words (what the control reads) and where the control turns
  /// the rotary axes (the tool along the plane's Z).
  struct Plane {
    TiltedPlane words;
    Vec3d axis_W = Vec3d::UnitZ();     ///< the CL tool axis of the run
    RotaryAngles rotary_rad;           ///< the post's solution (limits, continuity)
    RotaryAngles executed_rotary_rad;  ///< the control's: the tool along the words' Z, nearest it
  };

  /// The program frame at home P = W + home_offset_ (W is parallel to M at home).
  Vec3d home_offset() const {
    return solver_.with_rotary(ClPoint{Vec3d::Zero(), Vec3d::UnitZ()}, words_.home().rotary_rad, data_).linear_mm;
  }

  /// Before a CL motion: stay in the plane (same tool axis), leave it, or open one (a rapid, or the
  /// first motion, to a tool axis other than +Z of W).
  void update_plane(const cl::Motion& m, bool rapid) {
    if (!options_.tilted_plane || !writer_.dialect().tilted_plane || machine_.rotary_count() != 2 || !words_.serial)
      return;
    const Vec3d k = m.point.axis.normalized();
    if (plane_ && (k - plane_->axis_W).norm() <= 1e-9) return;
    close_plane();
    if (k.z() > 1.0 - 1e-12 || m.rotary_rad || !(rapid || !have_position_)) return;
    open_plane(m.point);
  }

  void open_plane(const ClPoint& cl) {
    const TiltedPlaneWords& tw = *writer_.dialect().tilted_plane;
    const IkOutcome ik = solver_.solve_quiet(cl, previous_.q, data_, nullptr);
    if (!ik.ok()) return;  // the motion names the failure
    const RotaryAngles rotary = ik.position->rotary_rad;
    // the program frame's axes seen from the tilted part (W) at this solution
    const Vec3d o = solver_.with_rotary(ClPoint{Vec3d::Zero(), cl.axis}, rotary, data_).linear_mm;
    Mat3d P_from_W;
    for (int i = 0; i < 3; ++i)
      P_from_W.col(i) = solver_.with_rotary(ClPoint{Vec3d::Unit(i), cl.axis}, rotary, data_).linear_mm - o;
    const Mat3d R = plane_frame(cl.axis, P_from_W.row(0).transpose(), P_from_W.row(1).transpose());
    Plane p;
    p.words.convention = tw.angles;
    std::array<double, 3> angles = plane_angles(tw.angles, R, last_plane_angles_);
    for (double& a : angles) a = writer_.rounded(3, a);
    p.words.angles_deg = angles;
    p.words.P_R_F = plane_rotation(tw.angles, angles);
    const Vec3d origin_P = cl.tip_mm + home_offset_;
    for (int i = 0; i < 3; ++i) p.words.origin_P_mm[i] = writer_.rounded(i, origin_P[i]);
    p.axis_W = cl.axis.normalized();
    p.rotary_rad = rotary;
    const IkOutcome e = solver_.solve_quiet(ClPoint{cl.tip_mm, p.words.P_R_F.col(2)}, *ik.position, data_, nullptr);
    p.executed_rotary_rad = e.ok() ? e.position->rotary_rad : rotary;
    // which of the two solutions: +1 the one with the larger first rotary angle
    int dir = 1;
    for (const RotarySolution& s : rotary_solutions(machine_, cl.axis)) {
      double apart = 0.0;
      for (Eigen::Index k = 0; k < rotary.size(); ++k)
        apart += std::abs(std::remainder(s.rotary_rad[k] - rotary[k], 2.0 * kPi));
      const double d0 = rotary.size() > 0 ? std::remainder(s.rotary_rad[0] - rotary[0], 2.0 * kPi) : 0.0;
      if (apart > 1e-6 && d0 > 0.0) dir = -1;  // the other solution is larger
    }
    std::string rotary_words;
    for (int k = 0; k < machine_.rotary_count(); ++k)
      rotary_words += (k ? " " : "") + std::string(1, writer_.letters()[static_cast<std::size_t>(3 + k)]) +
                      writer_.word_value(3 + k, rad_to_deg(rotary[k]));
    std::vector<std::string> blocks;
    for (std::string b : tw.on) {
      b = with_value(b, "{x}", writer_.word_value(0, p.words.origin_P_mm.x()));
      b = with_value(b, "{y}", writer_.word_value(1, p.words.origin_P_mm.y()));
      b = with_value(b, "{z}", writer_.word_value(2, p.words.origin_P_mm.z()));
      b = with_value(b, "{a}", writer_.word_value(3, angles[0]));
      b = with_value(b, "{b}", writer_.word_value(3, angles[1]));
      b = with_value(b, "{c}", writer_.word_value(3, angles[2]));
      b = with_value(b, "{dir}", dir > 0 ? "1" : "-1");
      b = with_value(b, "{rotary}", rotary_words);
      blocks.push_back(std::move(b));
    }
    writer_.tilted_plane(blocks, true);
    ++summary_.tilted_planes;
    last_plane_angles_ = angles;
    // where the tool stands in the plane once the rotary axes have turned (linear axes still)
    if (have_position_) {
      AxisPosition q = last_executed_;
      q.rotary_rad = p.executed_rotary_rad;
      const Vec3d at = p.words.to_plane(solver_.execute(q, data_).tip_mm + home_offset_);
      last_values_ =
          PerAxis<double>{writer_.rounded(0, at.x()), writer_.rounded(1, at.y()), writer_.rounded(2, at.z())};
    } else {
      last_values_.reset();
    }
    plane_ = p;
  }

  void close_plane() {
    if (!plane_) return;
    writer_.tilted_plane(writer_.dialect().tilted_plane->off, false);
    // back in the program frame: the machine stands at the last executed commands
    if (have_position_) {
      PerAxis<double> v{};
      for (int i = 0; i < 3; ++i) v[static_cast<std::size_t>(i)] = writer_.rounded(i, last_executed_.linear_mm[i]);
      for (int k = 0; k < machine_.rotary_count(); ++k)
        v[static_cast<std::size_t>(3 + k)] = rad_to_deg(last_executed_.rotary_rad[k]);
      last_values_ = v;
    }
    plane_.reset();
  }

  /// The commands the control executes for the plane's words X Y Z (`in_plane`, rounded here):
  /// the plane's transform into W, then the machine at the rotary angles the control turned to.
  AxisPosition plane_executed(const Vec3d& in_plane) const {
    Vec3d r;
    for (int i = 0; i < 3; ++i) r[i] = writer_.rounded(i, in_plane[i]);
    return executed_in_plane(solver_, data_, plane_->words, home_offset_, plane_->executed_rotary_rad, r);
  }

  std::optional<Plane> plane_;
  std::optional<std::array<double, 3>> last_plane_angles_;  ///< of the last plane (continuity)
  const Vec3d home_offset_ = home_offset();
};

}  // namespace

PostSummary post_program(cl::Reader& reader, const std::string& input_name, const KinematicModel& solver,
                         NcWriter& writer, const PostOptions& options, SolverData& data) {
  Poster poster(input_name, solver, data, writer, options);
  return poster.run(reader);
}

PostSummary post_program(cl::Reader& reader, const std::string& input_name, const KinematicModel& solver,
                         NcWriter& writer, const PostOptions& options) {
  SolverData data;
  return post_program(reader, input_name, solver, writer, options, data);
}

}  // namespace ncpost
