// SPDX-License-Identifier: Apache-2.0
// Klartext -> CL records: line source, block tokenizer, the TNC's modal meaning, then the nominal
// kinematics of the machine (klartext_reader.hpp).
#include "ncpost/postproc/read/klartext/klartext_reader.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cctype>
#include <array>
#include <cmath>
#include <deque>
#include <limits>
#include <map>
#include <set>

#include "ncpost/kinematics/forward.hpp"
#include "ncpost/kinematics/inverse.hpp"
#include "ncpost/machines/input_error.hpp"
#include "ncpost/postproc/read/klartext/klartext_arc.hpp"
#include "ncpost/postproc/read/klartext/klartext_block.hpp"
#include "ncpost/postproc/read/line_source.hpp"
#include "ncpost/postproc/read/tool_table.hpp"

#include "read/klartext/klartext_corner.hpp"
#include "read/klartext/klartext_cycle_def.hpp"
#include "read/klartext/klartext_drilling.hpp"
#include "read/klartext/klartext_flow.hpp"
#include "read/klartext/klartext_hole_path.hpp"
#include "read/klartext/klartext_plane.hpp"
#include "read/klartext/klartext_q.hpp"
#include "read/klartext/klartext_refusals.hpp"

namespace ncpost::klartext {
namespace {

constexpr const char* kWhatALineIs = "a Klartext block";
constexpr std::string_view kSlots = "XYZABC";  ///< ProgramPoint order

/// The slot (0..5) of an axis word X..C or IX..IC, or -1; `incremental` set for I words.
int axis_slot(const std::string& name, bool& incremental) {
  incremental = name.size() == 2 && name[0] == 'I';
  const std::string letter = incremental ? name.substr(1) : name;
  if (letter.size() != 1) return -1;
  const std::size_t at = kSlots.find(letter[0]);
  return at == std::string_view::npos ? -1 : static_cast<int>(at);
}

/// What one L / C / CR / CT / CP / M block asks besides its path.
struct BlockWords {
  ProgramPoint target{};
  std::array<bool, 6> programmed{};
  bool any_axis = false;
  bool rapid = false;
  std::optional<double> feed;
  std::optional<cl::CutterComp::Side> comp;
  std::vector<std::pair<int, int>> m;  ///< code, column
  std::optional<double> retract_mm;    ///< M140 MB: the distance (infinity: MAX)
  int retract_column = 0;
  // arcs
  std::optional<bool> counter_clockwise;       ///< DR+ / DR-
  std::optional<double> radius_mm;             ///< CR R
  std::optional<double> polar_rad;             ///< CP / LP PA
  std::optional<double> polar_step_rad;        ///< CP / LP IPA
  std::optional<double> polar_radius_mm;       ///< LP PR
  std::optional<double> polar_radius_step_mm;  ///< LP IPR
};

}  // namespace

struct KlartextReader::State {
  LineSource source;
  ProgramFlow flow;  ///< labels, calls and jumps: which line runs next
  QParameters q;     ///< Q, QL, QR
  std::string file;
  Machine machine;
  Setup setup;
  ReaderOptions options;
  std::array<int, 2> rotary_slot{-1, -1};  ///< ProgramPoint slot of machine rotary k

  // ---- modal state of the TNC
  ProgramPoint pos{};
  std::array<bool, 6> known{};
  std::array<int, 6> first_line{};  ///< the line that first programmed each axis
  std::array<bool, 6> first_by_rapid{};
  bool rtcp = false;
  std::optional<PlaneFrame> plane;        ///< PLANE ...: X Y Z are the tool tip in the plane
  std::optional<RotaryAngles> plane_rad;  ///< the rotary angles the plane asks (Q120 .. Q122)
  bool shortest_rotary = false;           ///< M126
  bool modal_cycle_call = false;          ///< M89 until M99
  std::optional<double> feed;
  std::optional<double> auto_feed;  ///< TOOL CALL F, for FAUTO
  cl::CutterComp::Side comp = cl::CutterComp::Side::off;
  cl::Spindle::Direction spindle = cl::Spindle::Direction::off;
  double rpm = 0.0;
  bool delta_radius = false;               ///< TOOL CALL DR/DR2 not 0
  Vec3d datum_shift_mm = Vec3d::Zero();    ///< CYCL DEF 7: added to absolute X Y Z words
  std::optional<Eigen::Vector2d> centre;   ///< CC
  std::optional<Eigen::Vector2d> tangent;  ///< direction of the last contour element in X Y
  /// The last straight line in X Y at a feed, its motion held back while the next block may be RND / CHF.
  struct HeldLine {
    cl::Motion motion;
    ProgramPoint from;
  };
  std::optional<HeldLine> corner_line;
  /// An RND / CHF read, waiting for the line after it.
  struct PendingCorner {
    bool rounding = true;
    double length_mm = 0.0;  ///< RND R, CHF side length
    std::optional<double> feed;
    cl::Location where;
  };
  std::optional<PendingCorner> corner;
  std::optional<ProgramPoint> line_start;   ///< where the last L block started
  std::optional<ProgramPoint> corner_join;  ///< where the last RND / CHF joined the line after it
  bool begun = false;
  bool ended = false;

  // ---- output
  std::deque<cl::Record> out;
  struct Held {
    std::size_t index;  ///< into `held`
    ProgramPoint p;
    std::array<bool, 6> assumed;
    bool rtcp;
  };
  std::vector<cl::Record> held;
  std::vector<Held> held_motions;
  bool settled = false;
  bool rotary_zero_noticed = false;
  std::vector<std::string> notices;
  std::set<std::string> noticed;

  std::vector<std::pair<std::string, int>> continuation;  ///< the '~' lines of the current block, with their line
  std::optional<DrillingCycle> drilling;                  ///< CYCL DEF 200 / 207, for CYCL CALL and M99
  std::optional<ExpandedCycle> expanded;  ///< CYCL DEF 201 / 203 / 208 / 240 / 241, for CYCL CALL and M99
  std::string tool_called;                ///< the last TOOL CALL's tool as written ("" none)
  double delta_radius_mm = 0.0;           ///< its DR
  std::optional<double> preset_number;    ///< CYCL DEF 247 Q339
  int shift_in_plane = 0;                 ///< a CYCL DEF 7 changed the shift in a plane (its column; 0: none)

  // the current line, for messages
  int line_number = 0;
  std::string line_text;

  State(std::istream& in, std::string f, const Machine& m, const Setup& s, ReaderOptions o)
      : source(in, f, kWhatALineIs),
        flow(source, [](std::string_view l) { return label_defined_in(l); }),
        file(std::move(f)),
        machine(m),
        setup(s),
        options(o) {
    for (int k = 0; k < machine.rotary_count() && k < 2; ++k)
      rotary_slot[static_cast<std::size_t>(k)] = static_cast<int>(kSlots.find(machine.rotary(k).letter));
  }

  [[noreturn]] void fail(int column, const std::string& what) const {
    throw InputError({file, line_number, column}, what, line_text);
  }
  void notice(int column, const std::string& what) {
    notices.push_back(column > 0 ? fmt::format("{}:{}:{}: {}", file, line_number, column, what)
                                 : fmt::format("{}:{}: {}", file, line_number, what));
  }
  void notice_once(const std::string& key, int column, const std::string& what) {
    if (noticed.insert(key).second) notice(column, what);
  }
  cl::Location at(int column) const { return {line_number, column}; }

  void emit(cl::Record r) {
    if (settled)
      out.push_back(std::move(r));
    else
      held.push_back(std::move(r));
  }

  // ---- the machine -------------------------------------------------------------------------
  bool machine_has(int slot) const {
    if (slot < 3) return true;
    return std::find(rotary_slot.begin(), rotary_slot.end(), slot) != rotary_slot.end();
  }

  AxisPosition commands_of(const ProgramPoint& p) const {
    AxisPosition q = AxisPosition::zero(machine.rotary_count());
    q.linear_mm = Vec3d(p[0], p[1], p[2]);
    if (plane) q.linear_mm = plane->origin_W + plane->W_R_plane * q.linear_mm;
    for (int k = 0; k < machine.rotary_count(); ++k)
      q.rotary_rad[k] = p[static_cast<std::size_t>(rotary_slot[static_cast<std::size_t>(k)])];
    return q;
  }

  /// The tool tip in W of program point `p` (no limit check: a circle's centre need not be reachable).
  Vec3d tip_of(const ProgramPoint& p, bool tip_program) const {
    const AxisPosition q = commands_of(p);
    return tip_program ? q.linear_mm : forward(machine, q, setup).tip_mm;
  }

  /// The tip and axis in W of program point `p`, its angles, and the limit check.
  cl::Motion locate(const ProgramPoint& p, bool tip_program, cl::Location where) const {
    cl::Motion m;
    m.where = where;
    m.axis_given = true;
    AxisPosition q = commands_of(p);
    if (machine.rotary_count() > 0) m.rotary_rad = q.rotary_rad;
    const ToolPoseT<double> pose = forward(machine, q, setup);
    m.point.axis = pose.axis;
    m.point.tip_mm = tip_program ? q.linear_mm : pose.tip_mm;
    if (tip_program) q.linear_mm = linear_for(machine, q.rotary_rad, q.linear_mm, setup);
    if (options.check_limits) check_limits(q, tip_program, where);
    return m;
  }

  void check_limits(const AxisPosition& q, bool tip_program, cl::Location where) const {
    for (std::size_t i = 0; i < machine.axes.size(); ++i) {
      const Axis& axis = machine.axes[i];
      const double v = q[static_cast<int>(i)];
      if (!axis.limits || axis.limits->contains(v, axis.is_rotary() ? 1e-9 : 1e-6)) continue;
      const double scale = axis.is_rotary() ? 180.0 / kPi : 1.0;
      const char* unit = axis.is_rotary() ? "deg" : "mm";
      throw Infeasible(fmt::format(
          "{}:{}:{}: {}{} {:.3f} {}, beyond the travel {:.3f} .. {:.3f} {} of machine {}: the program does not fit "
          "the machine; {}",
          file, where.line, where.column,
          tip_program && !axis.is_rotary() ? "the programmed tool tip needs machine " : "", axis.letter, v * scale,
          unit, axis.limits->min * scale, axis.limits->max * scale, unit, machine.name,
          axis.is_rotary() ? "check the program's angles against the machine file"
                           : "check --workpiece-origin and --tool-length, or the machine file"));
    }
  }

  // ---- the program's X Y Z: machine axes, the tool tip (M128), or the tip in a tilted plane -----
  bool tip_mode() const { return rtcp || plane.has_value(); }
  bool position_known() const { return settled && known[0] && known[1] && known[2]; }

  /// X Y Z of the program for the tool tip at `tip_W` with the rotary axes at `rotary_rad`, in
  /// the current mode.
  Vec3d program_xyz(const Vec3d& tip_W, const RotaryAngles& rotary_rad) const {
    if (plane) return plane->W_R_plane.transpose() * (tip_W - plane->origin_W);
    if (rtcp) return tip_W;
    return linear_for(machine, rotary_rad, tip_W, setup);
  }

  /// A change of mode (M128, M129, PLANE): the machine stays where it is, so the program's X Y Z
  /// of the current position are recomputed in the new mode.
  template <class Change>
  void switch_mode(Change change) {
    const bool here = position_known();
    const Vec3d tip_W = here ? tip_of(pos, tip_mode()) : Vec3d::Zero();
    change();
    if (!here) return;
    const Vec3d xyz = program_xyz(tip_W, commands_of(pos).rotary_rad);
    for (std::size_t i = 0; i < 3; ++i) pos[i] = xyz[static_cast<int>(i)];
  }

  // ---- the start: rapids before X Y Z are known are held ----------------------------------
  void emit_motion(const ProgramPoint& p, cl::Location where, bool rapid, std::optional<double> block_feed) {
    check_no_stale_shift(where.column);
    if (!settled) {
      const bool all_linear = known[0] && known[1] && known[2];
      if (!all_linear) {
        if (!rapid)
          fail(where.column, fmt::format("a cutting motion before {} {} programmed: where the tool starts is not "
                                         "known; program X, Y and Z on a rapid (FMAX) first",
                                         unknown_linear(), unknown_count() > 1 ? "are" : "is"));
        cl::Motion m;
        m.where = where;
        m.rapid = true;
        held_motions.push_back(Held{held.size(), p, assumed_now(), tip_mode()});
        held.push_back(std::move(m));
        return;
      }
      release(where, rapid);
    }
    note_rotary_zero(where);
    cl::Motion m = locate(p, tip_mode(), where);
    m.rapid = rapid;
    m.feed = block_feed;
    out.push_back(std::move(m));
  }

  std::array<bool, 6> assumed_now() const {
    std::array<bool, 6> a{};
    for (std::size_t i = 0; i < 3; ++i) a[i] = !known[i];
    return a;
  }
  int unknown_count() const { return int(!known[0]) + int(!known[1]) + int(!known[2]); }
  std::string unknown_linear() const {
    std::string s;
    for (std::size_t i = 0; i < 3; ++i)
      if (!known[i]) s += std::string(s.empty() ? "" : ", ") + kSlots[i];
    return s;
  }

  void note_rotary_zero(cl::Location where) {
    if (rotary_zero_noticed) return;
    std::string missing;
    for (int k = 0; k < machine.rotary_count() && k < 2; ++k)
      if (!known[static_cast<std::size_t>(rotary_slot[static_cast<std::size_t>(k)])])
        missing += std::string(missing.empty() ? "" : ", ") + machine.rotary(k).letter;
    if (missing.empty()) return;
    rotary_zero_noticed = true;
    notices.push_back(fmt::format("{}:{}:{}: {} not programmed yet: taken as 0 (the machine's home)", file, where.line,
                                  where.column, missing));
  }

  /// The held rapids take the first values of the axes they lacked; `rapid`: the block that
  /// makes X Y Z known is itself a rapid (a cutting motion may not lend its first values).
  void release(cl::Location where, bool rapid) {
    for (Held& h : held_motions) {
      for (std::size_t i = 0; i < 3; ++i) {
        if (!h.assumed[i]) continue;
        if (!rapid && first_line[i] == where.line) {
          const cl::Location held_at = std::get<cl::Motion>(held[h.index]).where;
          throw InputError({file, held_at.line, held_at.column},
                           fmt::format("this rapid does not say where {} goes, and {} is first programmed by the "
                                       "cutting motion at line {}: program {} on a rapid (FMAX) before it",
                                       kSlots[i], kSlots[i], where.line, kSlots[i]));
        }
        h.p[i] = first_value(i);
      }
      cl::Motion& m = std::get<cl::Motion>(held[h.index]);
      note_rotary_zero(m.where);
      cl::Motion located = locate(h.p, h.rtcp, m.where);
      located.rapid = true;
      m = std::move(located);
    }
    for (auto& r : held) out.push_back(std::move(r));
    held.clear();
    held_motions.clear();
    settled = true;
  }

  std::array<double, 6> first_values{};
  double first_value(std::size_t i) const { return first_values[i]; }

  void note_programmed(const std::array<bool, 6>& programmed, bool rapid) {
    for (std::size_t i = 0; i < 6; ++i)
      if (programmed[i] && !known[i]) {
        known[i] = true;
        first_values[i] = pos[i];
        first_line[i] = line_number;
        first_by_rapid[i] = rapid;
      }
  }

  // ---- blocks ------------------------------------------------------------------------------
  /// Reads and acts on the next block; false at the end of the program.
  bool read_block() {
    std::string_view line;
    if (!flow.next(line, line_number)) return finish_input();
    line_text = echo_of(line);
    Block b = parse_block(line, file, line_number);
    continuation.clear();
    while (b.continued) {  // the continuation lines of a cycle (its Q parameters)
      std::string_view more;
      int more_line = 0;
      if (!flow.next(more, more_line)) break;
      continuation.emplace_back(std::string(more), more_line);
      b.continued = parse_block(more, file, more_line).continued;
    }
    if (b.empty()) return true;
    if (b.deleted && options.block_skip) {
      notice_once("/", 1, "blocks that start with '/' (block skip) are left out, as the TNC does with block skip on");
      return true;
    }
    if (!begun) {
      if (b.statement.empty() || b.statement == "*") return true;  // comments before BEGIN PGM
      if (b.statement != "BEGIN PGM")
        fail(b.column,
             fmt::format("'{}' before BEGIN PGM: a Klartext program starts with BEGIN PGM name MM", b.statement));
      begin_program(b);
      return true;
    }
    return act_on(b);
  }

  /// A block of the program after BEGIN PGM; false when it ends the program.
  bool act_on(Block& b) {
    const std::string& s = b.statement;
    if (corner && !s.empty() && s != "*" && s != "L" && s != "LP")
      fail(b.column, fmt::format("'{}' after {} (line {}): the rounding or chamfer is read between two straight "
                                 "lines (L, LP) in X Y only",
                                 s, corner->rounding ? "RND" : "CHF", corner->where.line));
    if (corner_line && !corner && s != "RND" && s != "CHF") flush_corner_line();
    if (!b.comment.empty()) emit(cl::Comment{at(b.comment_column), b.comment});
    if (s.empty() || s == "*") return true;
    if (program_flow(b)) return true;
    resolve_q_words(b);
    if (s == "BEGIN PGM") fail(b.column, "a second BEGIN PGM (the previous program has no END PGM)");
    if (s == "END PGM") return end_program(at(b.column));
    if (s == "L" || s == "LP" || s == "M" || s == "STOP" || s == "C" || s == "CR" || s == "CT" || s == "CP")
      return motion_block(b);
    using Act = void (State::*)(const Block&);
    static const std::map<std::string, Act, std::less<>> kActs = {
        {"BLK FORM", &State::noted},       {"TOOL DEF", &State::noted},       {"TOOL CALL", &State::tool_call},
        {"FUNCTION TCPM", &State::tcpm},   {"FUNCTION RESET", &State::reset}, {"CYCL DEF", &State::cycle_def},
        {"CYCL CALL", &State::cycle_call}, {"CC", &State::circle_centre},     {"RND", &State::corner_block},
        {"CHF", &State::corner_block},
    };
    if (s.rfind("PLANE ", 0) == 0) {
      tilt(b);
      return true;
    }
    const auto act = kActs.find(s);
    if (act == kActs.end()) fail(b.column, refused_statement(b));
    (this->*(act->second))(b);
    return true;
  }

  /// BLK FORM, TOOL DEF: noted, nothing to post.
  void noted(const Block& b) {
    notice_once(b.statement, b.column,
                b.statement == "BLK FORM" ? "BLK FORM (the blank, for the TNC's graphics) is noted, not posted"
                                          : "TOOL DEF (the tool preselection) is noted, not posted");
  }
  /// FUNCTION RESET TCPM
  void reset(const Block& b) {
    if (b.words.size() != 1 || b.words[0].name != "TCPM") fail(b.column, refused_statement(b));
    switch_mode([&] { rtcp = false; });
  }
  /// CYCL CALL: the hole cycle where the tool stands.
  void cycle_call(const Block& b) {
    if (!b.text.empty()) fail(b.column, refused_statement(b));
    call_cycle(at(b.column), b.column);
  }

  // ---- Q parameters and program flow (klartext_q.hpp, klartext_flow.hpp) ------------------
  /// Q = formula, FN, LBL, CALL LBL: acted on here; false for every other statement.
  bool program_flow(const Block& b) {
    const std::string& s = b.statement;
    QError error;
    if (s == "Q" || s == "FN") {
      const auto st = s == "Q" ? q_assignment_of(b.text, error) : fn_statement_of(b.text, error);
      if (!st) fail(b.column, fmt::format("{} {}: {}", s == "Q" ? "" : "FN", b.text, error.what));
      if (!st->target.empty()) {
        q.set(st->target, formula_value(b, st->formula));
      } else if (unknown_condition(*st) && rest_is_inert()) {
        notice(b.column,
               fmt::format("FN {}: its condition reads a Q parameter this program does not set, but from here "
                           "on the program holds only labels, Q parameters and jumps among them: nothing "
                           "moves whichever way it jumps, so the program ends here",
                           b.text.substr(0, 1)));
        end_program(at(b.column));
      } else if (compare_holds(st->compare, formula_value(b, st->formula), formula_value(b, st->right))) {
        flow.jump(st->label, line_number);
      }
      return true;
    }
    if (s == "LBL") {
      const auto key = label_of(b.text);
      if (!key) fail(b.column, fmt::format("LBL {}: expected a label number or \"name\"", b.text));
      flow.label(*key, line_number);
      return true;
    }
    if (s == "CALL LBL") {
      call_label(b);
      return true;
    }
    return false;
  }

  /// A jump whose condition reads a Q parameter not set in this program (the TNC's value from before).
  bool unknown_condition(const QStatement& st) {
    QError left, right;
    return !q.evaluate(st.formula, left) || !q.evaluate(st.right, right);
  }

  /// From the current line to the end of the file only labels, Q assignments, jumps to labels among
  /// them, comments and END PGM, outside any subprogram call: no way through them moves or
  /// switches anything, whatever a parameter holds (hyperMILL's tool-edge checks after a skipped
  /// /M30).
  bool rest_is_inert() {
    std::set<std::string> defined, targets;
    const bool only_flow = flow.each_rest_line([&](std::string_view l, int n) {
      Block b;
      try {
        b = parse_block(l, file, n);
      } catch (const InputError&) {
        return false;
      }
      const std::string& s = b.statement;
      if (b.continued) return false;
      if (s.empty() || s == "END PGM") return true;
      if (s == "LBL") {
        const auto key = label_of(b.text);
        if (key) defined.insert(*key);
        return key.has_value();
      }
      if (s != "Q" && s != "FN") return false;
      QError e;
      const auto st = s == "Q" ? q_assignment_of(b.text, e) : fn_statement_of(b.text, e);
      if (st && st->target.empty()) targets.insert(st->label);
      return st.has_value();
    });
    return only_flow && std::includes(defined.begin(), defined.end(), targets.begin(), targets.end());
  }

  double formula_value(const Block& b, const std::string& formula) {
    QError error;
    const auto v = q.evaluate(formula, error);
    if (!v) fail(b.column, fmt::format("{}{}: {}", b.statement == "Q" ? "" : b.statement + " ", b.text, error.what));
    return *v;
  }

  /// CALL LBL n|"name" [REP m] (the TNC shows a running repeat as REP m/k: the k is left aside)
  void call_label(const Block& b) {
    const std::string& t = b.text;
    const auto key = label_of(t);
    if (!key) fail(b.column, fmt::format("CALL LBL {}: expected a label number or \"name\"", t));
    std::size_t p = t[0] == '"' ? t.find('"', 1) + 1 : t.find_first_not_of("0123456789");
    p = std::min(t.find_first_not_of(' ', std::min(p, t.size())), t.size());
    int repeats = 0;
    if (p < t.size()) {
      const bool rep = t.size() > p + 3 && (t.compare(p, 3, "REP") == 0 || t.compare(p, 3, "rep") == 0);
      const std::size_t digits = rep ? std::min(t.find_first_not_of(' ', p + 3), t.size()) : t.size();
      const std::size_t end = std::min(t.find_first_not_of("0123456789", digits), t.size());
      if (!rep || end == digits || end - digits > 5 || (end < t.size() && t[end] != '/' && t[end] != ' '))
        fail(b.column, fmt::format("CALL LBL {}: expected CALL LBL n [REP m]", t));
      repeats = std::stoi(t.substr(digits, end - digits));
    }
    flow.call(*key, repeats, line_number);
  }

  /// `X+Q1`, `FQ5`: the words take the parameters' values.
  void resolve_q_words(Block& b) {
    for (Word& w : b.words) {
      if (w.name == "FQ" && w.value && !w.q_parameter) {  // FQ5: the feed in Q5
        w.name = "F";
        w.q_parameter = true;
        w.text = fmt::format("Q{}", static_cast<long>(*w.value));
        w.sign = 0;
      }
      if (!w.q_parameter) continue;
      const auto v = q.get(w.text);
      if (!v)
        fail(w.column, fmt::format("{}{}{}: {} is not set in this program (the TNC would use the value it holds from "
                                   "before); set it before it is read",
                                   w.name, w.sign ? std::string(1, w.sign) : "", w.text, w.text));
      w.value = w.sign == '-' ? -*v : *v;
      w.q_parameter = false;
    }
  }

  void begin_program(const Block& b) {
    begun = true;
    const std::string& t = b.text;
    const std::size_t blank = t.find_last_of(" \t");
    const std::string unit = blank == std::string::npos ? std::string() : t.substr(blank + 1);
    std::string u;
    for (char c : unit) u += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (u == "INCH" || u == "IN")  // (NX posts write IN)
      fail(b.column, fmt::format("BEGIN PGM ... {}: an inch program is not read: the TNC 426 B / 430 user manual has "
                                 "F in an inch program entered ten times its inch/min value (0.1 inch/min), CAM posts "
                                 "write inch/min, and no manual found gives the newer TNCs' rule; have the CAM system "
                                 "write the program in MM",
                                 unit));
    if (u != "MM") fail(b.column, "expected BEGIN PGM name MM (the program's name and its unit)");
  }

  bool end_program(cl::Location where) {
    if (!settled) finish_start(where);
    emit(cl::End{where, true});
    ended = true;
    return false;
  }

  bool finish_input() {
    if (corner)
      throw InputError({file, corner->where.line, corner->where.column},
                       "the program ends after an RND or CHF, before the line after the corner");
    flush_corner_line();
    if (!begun) throw InputError({file, source.line_number(), 0}, "no BEGIN PGM: not a Klartext program");
    if (!options.allow_unterminated)
      throw InputError({file, source.line_number(), 0},
                       "the program ends without END PGM, M2 or M30 (truncated file?); --allow-unterminated posts it");
    notice(0, "the program ends without END PGM, M2 or M30");
    line_number = source.line_number();
    if (!settled) finish_start({line_number, 0});
    emit(cl::End{{line_number, 0}, true});
    return false;
  }

  /// The end while rapids are held: an axis never programmed has no value to give them.
  void finish_start(cl::Location where) {
    if (held_motions.empty()) {
      release(where, true);
      return;
    }
    if (unknown_count() > 0) {
      const cl::Location held_at = std::get<cl::Motion>(held[held_motions.front().index]).where;
      throw InputError({file, held_at.line, held_at.column},
                       fmt::format("{} {} never programmed: where this rapid goes is not known", unknown_linear(),
                                   unknown_count() > 1 ? "are" : "is"));
    }
    release(where, true);
  }

  // TOOL CALL n|"name" Z S.. F.. DL.. DR.. DR2..
  void tool_call(const Block& b) {
    std::optional<int> tool;
    std::optional<std::string> name;
    std::optional<double> speed;
    bool dr_nonzero = false;
    for (const Word& w : b.words) {
      if (w.q_parameter)
        fail(w.column,
             fmt::format("{}{}{}: Q parameters are not read", w.name, w.sign ? std::string(1, w.sign) : "", w.text));
      if (w.name.empty()) {
        if (!w.value || *w.value < 0 || *w.value != std::floor(*w.value) || *w.value > 1e9)
          fail(w.column, "expected a tool number (an integer >= 0)");
        tool = static_cast<int>(*w.value);
      } else if (w.name == "\"") {
        if (w.text.empty()) fail(w.column, "TOOL CALL \"\": expected a tool name between the quotes");
        name = w.text;
      } else if (w.name == "X" || w.name == "Y" || w.name == "Z") {
        if (w.value) fail(w.column, fmt::format("expected the tool axis alone ({} without a value)", w.name));
        if (w.name != "Z") fail(w.column, fmt::format("tool axis {}: only the tool axis Z is read", w.name));
      } else if (w.name == "S") {
        if (!w.value || *w.value < 0) fail(w.column, "expected a spindle speed (rpm >= 0)");
        speed = *w.value;
      } else if (w.name == "F") {
        if (!w.value || *w.value < 0) fail(w.column, "expected a feed (mm/min >= 0)");
        auto_feed = *w.value;
      } else if (w.name == "DL") {
        if (w.value && *w.value != 0.0)
          fail(w.column, fmt::format("DL{:+g}: a delta length moves the tool tip along its axis; the post takes the "
                                     "tool length from --tool-length: program DL+0",
                                     *w.value));
      } else if (w.name == "DR" || w.name == "DR2") {
        if (w.value && *w.value != 0.0) {
          dr_nonzero = true;
          notice(w.column, fmt::format("{}{:+g}: a delta radius acts only with RL/RR (refused beside it) and 3-D "
                                       "compensation; the tool tip path is posted as programmed",
                                       w.name, *w.value));
        }
      } else {
        fail(w.column, fmt::format("'{}' in TOOL CALL is not read (expected n Z S F DL DR)", w.name));
      }
    }
    delta_radius = dr_nonzero;  // each TOOL CALL sets its own deltas
    delta_radius_mm = 0.0;
    if (const Word* dr = b.find("DR"); dr && dr->value) delta_radius_mm = *dr->value;
    if (tool || name) tool_called = name ? fmt::format("\"{}\"", *name) : std::to_string(*tool);
    if (tool && name) fail(b.column, "TOOL CALL with both a number and a name: call the tool by one of them");
    if (tool || name) {
      cl::ToolChange change;
      change.where = at(b.column);
      change.number = tool.value_or(0);
      change.name = name.value_or("");
      emit(change);
      spindle = cl::Spindle::Direction::off;  // the tool change stops the spindle; M3/M4 start it
    }
    if (speed) {
      rpm = *speed;
      if (spindle != cl::Spindle::Direction::off) emit(cl::Spindle{at(b.column), spindle, rpm});
    }
  }

  /// CYCL DEF 9 (dwell time, active where it is defined): 9.0 is the header, 9.1 ends with the time
  /// in s after a word in the control's language (DWELL 1.5, V.IDO2, V.ZEIT 0.5).
  void dwell_cycle(const Block& b, const CycleDef& c) {
    if (c.part == 0) return;
    const std::string& t = c.rest;
    std::size_t end = t.find_last_not_of(" \t\r");
    std::size_t start = end == std::string::npos ? 0 : end + 1;
    while (start > 0 && (std::isdigit(static_cast<unsigned char>(t[start - 1])) || t[start - 1] == '.')) --start;
    const std::string number = end == std::string::npos ? "" : t.substr(start, end + 1 - start);
    if (c.part != 1 || number.empty() || number == "." || number.find('.') != number.rfind('.'))
      fail(b.column,
           fmt::format("CYCL DEF 9.{}: expected CYCL DEF 9.1 with the dwell time in s at its end (DWELL 1.5)", c.part));
    const double seconds = std::stod(number);
    if (seconds > cl::kMaxDwellSeconds) fail(b.column, fmt::format("CYCL DEF 9.1: a dwell of {:g} s", seconds));
    emit(cl::Dwell{at(b.column), seconds});
  }

  /// CYCL DEF 19 (working plane) read only where it tilts nothing: 19.0 (the header) and a 19.1 with
  /// no angles (the cycle switched off) or with all its angles 0 (the tilt reset), without F or MB
  /// (which would position the rotary axes, as the machine builder set). Angles other than 0 are
  /// axis or spatial angles by a machine parameter: refused.
  void working_plane_reset(const Block& b, const CycleDef& c) {
    if (c.part == 0) return;
    if (c.part != 1)
      fail(b.column, fmt::format("CYCL DEF 19{}: expected CYCL DEF 19.0 and 19.1",
                                 c.part < 0 ? std::string() : fmt::format(".{}", c.part)));
    if (c.words.empty() && c.rest.find_first_not_of(" \t\r") != std::string::npos)
      fail(b.column, fmt::format("CYCL DEF 19.1 {}: expected the rotary axes' angles (B+0 C+0) or none", c.rest));
    for (const Word& w : c.words) {
      bool incremental = false;
      const int slot = axis_slot(w.name, incremental);
      if (slot < 3 || incremental || w.q_parameter || !w.value)
        fail(w.column, fmt::format("CYCL DEF 19.1 {}: only the rotary axes' angles are read (the cycle with F or MB "
                                   "positions the rotary axes as the machine builder set)",
                                   w.name));
      if (*w.value != 0.0)
        fail(w.column,
             "CYCL DEF 19 (working plane): its angles are axis or spatial angles as the machine builder set "
             "(a machine parameter), so they are not read; program PLANE SPATIAL or PLANE AXIAL");
    }
    if (plane) fail(b.column, "CYCL DEF 19 while a PLANE is active: the TNC does not mix them; program PLANE RESET");
    notice_once("CYCL DEF 19", b.column,
                "CYCL DEF 19.1 with no angles or all 0 (the working plane's tilt reset): no plane is tilted, nothing "
                "moves");
  }

  /// CYCL DEF 7 (datum shift: X Y Z, absolute from the preset or I... from the last shift) and
  /// CYCL DEF 32 (the TNC's tolerance: noted); every other cycle is refused by name.
  void cycle_def(const Block& b) {
    const CycleDef c = cycle_def_of(b, file, line_number);
    if (c.number == 32 && c.part >= 0) {
      notice_once("CYCL DEF 32", b.column,
                  "CYCL DEF 32 (the TNC's path tolerance) is noted, not posted: the post's "
                  "tolerance is its own (--tolerance)");
      return;
    }
    if (is_hole_cycle(c.number) && c.part < 0) {
      define_hole_cycle(b, c.number);
      return;
    }
    if ((c.number == 332 || c.number == 392) && c.part < 0) {  // DMG's TUNING / ATC: servo dynamics, no motion
      notice_once("CYCL DEF 332", b.column,
                  fmt::format("CYCL DEF {} (the machine's dynamics tuning) is noted, not "
                              "posted: it moves nothing",
                              c.number));
      return;
    }
    if (c.number == 9 && c.part >= 0) {
      dwell_cycle(b, c);
      return;
    }
    if (c.number == 19) {
      working_plane_reset(b, c);
      return;
    }
    if (c.number == 247 && c.part < 0) {
      preset(b);
      return;
    }
    if (c.number != 7 || c.part < 0) fail(b.column, refused_statement(b));
    if (c.part == 0) return;  // CYCL DEF 7.0 DATUM SHIFT: the header
    if (c.rest.find('#') != std::string::npos)
      fail(b.column, "CYCL DEF 7: a datum shift from the datum table (#n) is not read; program the shift's values");
    if (c.words.size() != 1) fail(b.column, "CYCL DEF 7: expected one axis word per block (X+10, IY-5)");
    const Word& w = c.words[0];
    bool incremental = false;
    const int slot = axis_slot(w.name, incremental);
    if (slot < 0 || slot > 2)
      fail(w.column, fmt::format("CYCL DEF 7: a shift of {} is not read (X, Y and Z are)", w.name));
    if (w.q_parameter || !w.value) fail(w.column, fmt::format("CYCL DEF 7: {} without a number", w.name));
    const double shift = incremental ? datum_shift_mm[slot] + *w.value : *w.value;
    // in a plane: the shift's axes there are not read, so nothing may move before PLANE RESET or a new PLANE
    if (plane && shift != datum_shift_mm[slot]) shift_in_plane = b.column;
    datum_shift_mm[slot] = shift;
    notice_once("CYCL DEF 7", b.column,
                "CYCL DEF 7 (datum shift): the absolute X Y Z words after it are shifted by it");
  }

  /// CYCL DEF 247 Q339=n: the program's preset. The job's workpiece origin (--workpiece-origin) is
  /// taken as that preset; a program that changes to another preset is refused.
  void preset(const Block& b) {
    std::optional<double> number;
    for (const auto& [text, line] : continuation)
      if (const auto a = q_assignment(text); a && a->number == 339) number = a->value;
    if (!number) fail(b.column, "CYCL DEF 247 without Q339=n (the preset number)");
    if (preset_number && *preset_number != *number)
      fail(b.column, fmt::format("CYCL DEF 247 Q339={:g}: a second preset (after Q339={:g}) moves the workpiece "
                                 "origin by the preset table, which the post does not have; post each preset's part "
                                 "on its own",
                                 *number, *preset_number));
    preset_number = number;
    notice_once("CYCL DEF 247", b.column,
                fmt::format("CYCL DEF 247 Q339={:g}: the preset is taken as the job's "
                            "workpiece origin (--workpiece-origin)",
                            *number));
  }

  /// CYCL DEF 200 / 201 / 203 / 206 / 207 / 208 / 209 / 240 / 241 with its Q parameters on the '~' lines.
  void define_hole_cycle(const Block& b, int number) {
    std::map<int, double> q;
    for (const auto& [text, line] : continuation) {
      const std::optional<QAssignment> a = q_assignment(text);
      if (!a) continue;  // (a comment line)
      std::optional<double> value = a->value;
      QError error;
      if (!value && (a->number == 208 || a->number == 253) && (a->text == "MAX" || a->text == "FMAX"))
        value = std::numeric_limits<double>::infinity();     // a feed given as FMAX: the move is a rapid
      if (!value) value = this->q.evaluate(a->text, error);  // Q206=Q3: the parameter's value
      if (!value)
        throw InputError({file, line, 0},
                         fmt::format("Q{}={}: a cycle parameter that is not a number or a Q formula ({}) is not read; "
                                     "program the value",
                                     a->number, a->text, error.what),
                         echo_of(text));
      q[a->number] = *value;
    }
    drilling.reset();
    expanded.reset();
    if (number == 200 || number == 206 || number == 207 || number == 209) {
      auto d = number == 200   ? drilling_200(q, at(b.column))
               : number == 206 ? tapping_206(q, at(b.column))
               : number == 207 ? tapping_207(q, at(b.column))
                               : tapping_209(q, at(b.column));
      if (const std::string* why = std::get_if<std::string>(&d)) fail(b.column, *why);
      drilling = std::get<DrillingCycle>(d);
      return;
    }
    auto e = expanded_cycle(number, q);
    if (const std::string* why = std::get_if<std::string>(&e)) fail(b.column, *why);
    expanded = std::get<ExpandedCycle>(e);
    for (const std::string& note : expanded->notes) notice_once(note.substr(0, 16), b.column, note);
  }

  /// CYCL CALL or M99: one hole of the hole cycle where the tool stands (X Y), its top at Q203.
  void call_cycle(cl::Location where, int column) {
    if (!drilling && !expanded)
      fail(column, fmt::format("a cycle call without a hole cycle (CYCL DEF {}) before it (other cycles are not read)",
                               hole_cycles_listed("or")));
    if (rtcp)
      fail(column, "a cycle call under M128 / FUNCTION TCPM is not read; switch it off (M129) before the cycle");
    if (!settled || !known[0] || !known[1] || !known[2])
      fail(column, "a cycle call before X, Y and Z are programmed: the hole's position is not known");
    check_no_stale_shift(column);
    ProgramPoint top = pos;  // (in a plane: its coordinates, the datum shift in its origin)
    top[2] = (drilling ? drilling->surface_mm : expanded->surface_mm) + (plane ? 0.0 : datum_shift_mm.z());
    cl::Motion hole = locate(top, tip_mode(), where);
    ProgramPoint below = top;
    below[2] -= 1.0;
    if ((hole.point.tip_mm - tip_of(below, tip_mode()) - hole.point.axis).norm() > 1e-6)
      fail(column, plane ? "a cycle call in a tilted plane with the rotary axes not at the plane's angles is not read"
                         : "a cycle call where machine Z is not the tool axis (a tilted head) is not read");
    if (expanded) {
      run_hole_steps(top, where, column);
      pos[2] = top[2] + expanded->return_mm;
      return;
    }
    cl::Cycle c = drilling->cycle;
    c.where = where;
    if (drilling->tap_feed_mm_min) {  // 206: the pitch of the feed at this speed, the hand of this direction
      check_spindle_turns(column);
      c.pitch_mm = *drilling->tap_feed_mm_min / rpm;
      c.left_hand = spindle == cl::Spindle::Direction::ccw;
    } else if (c.kind == cl::Cycle::Kind::tap) {
      check_tap_spindle(column);
    }
    for (std::size_t k = 0; k < std::max<std::size_t>(1, drilling->infeed_depths_mm.size()); ++k) {
      cl::Cycle infeed = c;  // 209 with chip removal: a tap to each infeed depth, back to the set-up clearance
      if (k + 1 < drilling->infeed_depths_mm.size()) infeed.retract_mm.reset();
      if (!drilling->infeed_depths_mm.empty()) infeed.depth_mm = drilling->infeed_depths_mm[k];
      emit(infeed);
      emit(hole);  // (not rapid: the hole of the cycle)
    }
    cl::Cycle off;
    off.where = where;
    emit(off);
    pos[2] = top[2] + drilling->return_mm;  // where the TNC leaves the tool
  }

  /// A tapping cycle (206, 207) is called with the spindle turning at a known speed.
  void check_spindle_turns(int column) const {
    if (spindle == cl::Spindle::Direction::off || !(rpm > 0.0))
      fail(column, fmt::format("{} called with the spindle stopped: the tapping feed is pitch x speed (program M3 "
                               "with S before the call)",
                               drilling->cycle.kind_word));
  }

  /// CYCL DEF 207 / 209 tap with the spindle turning the thread's way (Q239 > 0: M3, < 0: M4).
  void check_tap_spindle(int column) const {
    const bool left = drilling->cycle.left_hand;
    check_spindle_turns(column);
    if ((spindle == cl::Spindle::Direction::ccw) != left)
      fail(column,
           fmt::format("{} with a {}-hand thread (Q239) called with the spindle {}: program {}",
                       drilling->cycle.kind_word, left ? "left" : "right", left ? "M3" : "M4", left ? "M4" : "M3"));
  }

  /// The diameter of the tool called (the tool table's, plus twice DR), if known.
  std::optional<double> tool_diameter_mm() const {
    if (!options.tool_table || tool_called.empty()) return std::nullopt;
    std::optional<double> d;
    for (const auto& [name, e] : options.tool_table->by_name)
      if (tool_called == (tool_called.front() == '"' ? fmt::format("\"{}\"", name) : std::to_string(e.number)))
        d = e.diameter_mm;
    if (d) *d += 2.0 * delta_radius_mm;
    return d;
  }

  /// One hole of CYCL DEF 203 / 208 / 241: its steps from the hole's top `top` (klartext_hole_path.hpp).
  void run_hole_steps(const ProgramPoint& top, cl::Location where, int column) {
    const auto steps = hole_steps(*expanded, HoleContext{spindle, rpm, tool_diameter_mm(), tool_called});
    if (const std::string* why = std::get_if<std::string>(&steps)) fail(column, *why);
    std::optional<double> feed_now;
    const auto set_feed = [&](double f) {
      if (feed_now != f) emit(cl::Feed{where, f, false});
      feed_now = f;
    };
    for (const HoleStep& s : std::get<std::vector<HoleStep>>(steps)) {
      ProgramPoint p = top;
      p[0] += s.dx;
      p[1] += s.dy;
      p[2] += s.z;
      using K = HoleStep::Kind;
      if (s.kind == K::rapid || s.kind == K::feed) {
        if (s.kind == K::feed) set_feed(s.feed_mm_min);
        emit_motion(p, where, s.kind == K::rapid, std::nullopt);
        pos = p;
      } else if (s.kind == K::arc) {
        set_feed(s.feed_mm_min);
        const ArcResult r = arc_polar(pos, Eigen::Vector2d(top[0] + s.cx, top[1] + s.cy), s.sweep_rad, p[2]);
        if (!r.arc) fail(column, fmt::format("CYCL DEF {}: {}", expanded->number, r.error));
        arc_motion(*r.arc, where, false, std::nullopt, column);
        pos = r.arc->end;
      } else if (s.kind == K::dwell) {
        emit(cl::Dwell{where, s.dwell_s});
      } else {
        emit(cl::Spindle{where, s.kind == K::spindle ? s.direction : spindle, s.kind == K::spindle ? s.rpm : rpm});
      }
    }
    if (feed && feed_now) emit(cl::Feed{where, *feed, false});  // the program's F again
  }

  // FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS [REFPNT TIP-TIP]
  void tcpm(const Block& b) {
    for (std::size_t i = 0; i < b.words.size(); ++i) {
      const Word& w = b.words[i];
      const auto refuse = [&](const std::string& why) {
        fail(w.column, fmt::format("FUNCTION TCPM ... {}: {}; ncpost reads F TCP, AXIS POS, PATHCTRL AXIS and "
                                   "REFPNT TIP-TIP",
                                   w.name, why));
      };
      if (w.name == "SPAT") refuse("the rotary words are spatial angles, not machine axes: not read");
      if (w.name == "CONT") refuse("a contouring feed over all axes: not read");
      if (w.name == "VECTOR") refuse("the tool axis interpolated in a plane: not read");
      if (w.name == "REFPNT") {
        const bool tip_tip = i + 2 < b.words.size() && b.words[i + 1].name == "TIP" && b.words[i + 1].sign == '-' &&
                             b.words[i + 2].name == "TIP";
        if (!tip_tip) refuse("a reference point other than the tool tip: not read");
      }
    }
    if (plane) fail(b.column, "FUNCTION TCPM in a tilted plane (PLANE ...) is not read; PLANE RESET first");
    switch_mode([&] { rtcp = true; });
  }

  // CC X Y (or IX IY from the last position; a missing coordinate: the last position's)
  void circle_centre(const Block& b) {
    if (!known[0] || !known[1])
      fail(b.column, "CC before X and Y are programmed (the pole's missing coordinates are the last position's)");
    Eigen::Vector2d c(pos[0], pos[1]);
    for (const Word& w : b.words) {
      bool incremental = false;
      const int slot = axis_slot(w.name, incremental);
      if (slot != 0 && slot != 1)
        fail(w.column, fmt::format("'{}' in CC: expected X and Y (the working plane of the tool axis Z)", w.name));
      if (w.q_parameter)
        fail(w.column,
             fmt::format("{}{}{}: Q parameters are not read", w.name, w.sign ? std::string(1, w.sign) : "", w.text));
      if (!w.value) fail(w.column, fmt::format("{} without a value", w.name));
      c[slot] = incremental ? pos[static_cast<std::size_t>(slot)] + *w.value
                            : *w.value + (plane ? 0.0 : datum_shift_mm[slot]);
    }
    centre = c;
  }

  // ---- PLANE (klartext_plane.hpp) ------------------------------------------------------------
  /// PLANE ...: the plane's frame, its angles in Q120 .. Q122, and the swivel (TURN) or none (STAY).
  void tilt(const Block& b) {
    auto parsed = plane_request(b, machine);
    if (const std::string* why = std::get_if<std::string>(&parsed)) fail(b.column, *why);
    const PlaneRequest& r = std::get<PlaneRequest>(parsed);
    if (rtcp) fail(b.column, fmt::format("{} under M128 / FUNCTION TCPM is not read; M129 first", b.statement));
    if (!held_motions.empty())
      fail(b.column, fmt::format("{} while earlier rapids wait for X, Y and Z: program X, Y and Z on a rapid before "
                                 "the PLANE",
                                 b.statement));
    if (r.retract)
      fail(b.column, fmt::format("{} ... MB (a retract along the tool axis before the swivel) is not read; program "
                                 "the retract with L or M140 before the PLANE",
                                 b.statement));
    if (r.motion == PlaneRequest::Motion::move)
      fail(b.column, fmt::format("{} MOVE is not read (the tool tip follows the swivel); program STAY and position the "
                                 "rotary axes with L A+Q120 B+Q121 C+Q122",
                                 b.statement));
    if (r.reset && !plane && r.motion == PlaneRequest::Motion::stay) {
      notice_once("PLANE RESET", b.column, "PLANE RESET STAY: no tilted plane is active, nothing moves");
      return;
    }
    const RotaryAngles now = commands_of(pos).rotary_rad;
    RotaryAngles target = r.reset ? RotaryAngles(RotaryAngles::Zero(now.size())) : now;
    if (!r.reset) {
      auto angles = plane_rotary(machine, r, now);
      if (const std::string* why = std::get_if<std::string>(&angles))
        fail(b.column, fmt::format("{}: {}", b.statement, *why));
      target = std::get<RotaryAngles>(angles);
    }
    shift_in_plane = 0;
    switch_mode([&] {
      if (r.reset) {
        plane.reset();
        plane_rad.reset();
        return;
      }
      plane = PlaneFrame{r.W_R_plane, datum_shift_mm};
      plane_rad = target;
    });
    if (!r.reset) set_plane_parameters(target);
    if (r.motion == PlaneRequest::Motion::turn) swivel(target, b, r);
  }

  /// Q120 .. Q122: the plane's angles of the machine's A, B, C axes in degrees.
  void set_plane_parameters(const RotaryAngles& angles_rad) {
    for (int k = 0; k < machine.rotary_count(); ++k) {
      const char letter = machine.rotary(k).letter;
      if (letter >= 'A' && letter <= 'C') q.set(fmt::format("Q{}", 120 + (letter - 'A')), rad_to_deg(angles_rad[k]));
    }
  }

  /// PLANE ... TURN: the rotary axes turn to `target`, the linear axes stay.
  void swivel(const RotaryAngles& target, const Block& b, const PlaneRequest& r) {
    if (!position_known())
      fail(b.column, fmt::format("{} TURN before X, Y and Z are programmed on a rapid: where the swivel happens is not "
                                 "known",
                                 b.statement));
    ProgramPoint to = pos;
    std::array<bool, 6> programmed{};
    for (int k = 0; k < machine.rotary_count(); ++k) {
      const auto slot = static_cast<std::size_t>(rotary_slot[static_cast<std::size_t>(k)]);
      to[slot] = target[k];
      programmed[slot] = true;
    }
    pos = turned(pos, to);
    note_programmed(programmed, true);
    emit_motion(pos, at(b.column), !r.feed, r.feed);
  }

  /// `to` (rotary axes moved from `from`) with X Y Z where the machine's linear axes stay.
  ProgramPoint turned(const ProgramPoint& from, ProgramPoint to) const {
    const Vec3d machine_xyz = linear_for(machine, commands_of(from).rotary_rad, tip_of(from, tip_mode()), setup);
    AxisPosition q = commands_of(to);
    q.linear_mm = machine_xyz;
    const Vec3d xyz = program_xyz(forward(machine, q, setup).tip_mm, q.rotary_rad);
    for (std::size_t i = 0; i < 3; ++i) to[i] = xyz[static_cast<int>(i)];
    return to;
  }

  /// After CYCL DEF 7 changed the shift in a plane nothing may move until PLANE RESET or a new PLANE.
  void check_no_stale_shift(int column) const {
    if (shift_in_plane)
      fail(column,
           "a motion after CYCL DEF 7 changed the datum shift inside a tilted plane (PLANE ...): the shift's "
           "axes in the tilted system are not read; PLANE RESET first, or shift the datum before the PLANE");
  }

  /// In a tilted plane a motion needs the tool axis of the plane (the rotary axes at Q120 .. Q122).
  void check_plane_axis(const Block& b, const ProgramPoint& target) const {
    if (!plane) return;
    const Vec3d axis_W = tool_frame_W(machine, commands_of(target).rotary_rad).col(2);
    if ((axis_W - plane->W_R_plane.col(2)).norm() > 1e-6)
      fail(b.column, fmt::format("{} in a tilted plane (PLANE ...) with the rotary axes not at the plane's angles: not "
                                 "read; position them first (L A+Q120 B+Q121 C+Q122 FMAX)",
                                 b.statement));
  }

  /// The words of a path block (L, C, CR, CT, CP, or M words alone).
  BlockWords words_of(const Block& b) {
    BlockWords bw;
    bw.target = pos;
    for (std::size_t i = 0; i < b.words.size(); ++i) {
      const Word& w = b.words[i];
      if (w.q_parameter)
        fail(w.column,
             fmt::format("{}{}{}: Q parameters are not read", w.name, w.sign ? std::string(1, w.sign) : "", w.text));
      bool incremental = false;
      const int slot = axis_slot(w.name, incremental);
      if (slot >= 0)
        axis_word(w, slot, incremental, bw);
      else if (w.name == "MB")
        retract_word(b, i, bw);
      else if (!path_word(b, w, bw))
        fail(w.column, fmt::format("'{}' in {} is not read", w.name, b.statement));
    }
    return bw;
  }

  /// X .. C, IX .. IC: the target of the axis in `slot` (M126: a continuous rotary axis the short way).
  void axis_word(const Word& w, int slot, bool incremental, BlockWords& bw) const {
    if (!machine_has(slot))
      fail(w.column, fmt::format("{}: the machine {} has no {} axis", w.name, machine.name,
                                 kSlots[static_cast<std::size_t>(slot)]));
    if (!w.value) fail(w.column, fmt::format("{} without a value", w.name));
    const auto s = static_cast<std::size_t>(slot);
    if (incremental && !known[s] && slot < 3)
      fail(w.column, fmt::format("{} before {} is programmed: the start is not known", w.name, kSlots[s]));
    const double v = slot >= 3 ? deg_to_rad(*w.value) : *w.value;
    bw.target[s] = incremental ? pos[s] + v : v + (slot < 3 && !plane ? datum_shift_mm[slot] : 0.0);
    if (!incremental && slot >= 3 && shortest_rotary && known[s] &&
        machine.axes[static_cast<std::size_t>(3 + rotary_index(slot))].continuous())
      bw.target[s] = pos[s] + std::remainder(v - pos[s], 2.0 * kPi);  // M126: the short way
    bw.programmed[s] = true;
    bw.any_axis = true;
  }

  /// MB d|MAX of M140 (the word at `i`; MAX is the next one).
  void retract_word(const Block& b, std::size_t& i, BlockWords& bw) const {
    const Word& w = b.words[i];
    bw.retract_column = w.column;
    if (w.value) {
      if (*w.value <= 0.0) fail(w.column, "M140 MB: expected a distance > 0 or MAX");
      bw.retract_mm = *w.value;
    } else if (i + 1 < b.words.size() && b.words[i + 1].name == "MAX") {
      bw.retract_mm = std::numeric_limits<double>::infinity();
      ++i;
    } else {
      fail(w.column, "M140 MB: expected a distance or MAX");
    }
  }

  /// R, RL, RR, DR, PA, IPA, PR, IPR, F, FMAX, FAUTO, M: false for any other word.
  bool path_word(const Block& b, const Word& w, BlockWords& bw) const {
    const auto polar = [&](std::optional<double>& absolute, std::optional<double>& step, bool angle) {
      if (!w.value) fail(w.column, fmt::format("{} without a value", w.name));
      (w.name[0] == 'I' ? step : absolute) = angle ? deg_to_rad(*w.value) : *w.value;
    };
    if (w.name == "R" && b.statement == "CR") {
      if (!w.value || *w.value == 0.0) fail(w.column, "CR: expected the radius R+ (up to 180 deg) or R- (beyond)");
      bw.radius_mm = *w.value;
    } else if (w.name == "R") {
      if (!w.value || *w.value != 0.0) fail(w.column, "expected R0, RL or RR (the radius compensation)");
      bw.comp = cl::CutterComp::Side::off;
    } else if (w.name == "RL" || w.name == "RR") {
      bw.comp = w.name == "RL" ? cl::CutterComp::Side::left : cl::CutterComp::Side::right;
      if (delta_radius)
        fail(w.column, fmt::format("{} with a delta radius DR from the TOOL CALL: the post's radius compensation "
                                   "would use the tool's own radius; program DR+0 or post the tool centre path",
                                   w.name));
    } else if (w.name == "DR") {
      if (w.sign == 0 || w.value) fail(w.column, "expected DR+ (counter-clockwise) or DR- (clockwise)");
      bw.counter_clockwise = w.sign == '+';
    } else if (w.name == "PA" || w.name == "IPA") {
      polar(bw.polar_rad, bw.polar_step_rad, true);
    } else if ((w.name == "PR" || w.name == "IPR") && b.statement == "LP") {
      polar(bw.polar_radius_mm, bw.polar_radius_step_mm, false);
    } else if (w.name == "M") {
      if (!w.value || *w.value < 0 || *w.value != std::floor(*w.value)) fail(w.column, "expected an M function number");
      bw.m.emplace_back(static_cast<int>(*w.value), w.column);
    } else {
      return feed_word(w, bw);
    }
    return true;
  }

  /// F, FMAX, FAUTO (FQ, FU, FZ refused): false for any other word.
  bool feed_word(const Word& w, BlockWords& bw) const {
    if (w.name == "F") {
      if (!w.value || *w.value < 0.0) fail(w.column, "expected a feed (mm/min >= 0), FMAX or FAUTO");
      bw.feed = *w.value;
    } else if (w.name == "FMAX") {
      bw.rapid = true;
    } else if (w.name == "FAUTO") {
      if (!auto_feed) fail(w.column, "FAUTO without a feed in the TOOL CALL (F)");
      bw.feed = *auto_feed;
    } else if (w.name == "FQ" || w.name == "FU" || w.name == "FZ") {
      fail(w.column, fmt::format("{}: {} is not read; program F in mm/min",
                                 w.name + (w.value ? fmt::format("{:g}", *w.value) : ""),
                                 w.name == "FQ"   ? "a feed from a Q parameter"
                                 : w.name == "FU" ? "a feed per revolution"
                                                  : "a feed per tooth"));
    } else {
      return false;
    }
    return true;
  }

  /// M91 / M92: the block's X Y Z words are machine coordinates, counted from each axis's
  /// `reference` (M91, the machine datum, as G53) or `reference2` (M92, the additional machine
  /// datum the machine builder sets; G30's point) in the machine file; the axes it does not name stay.
  void machine_coordinates(const Block& b, BlockWords& bw, int code, int column) {
    if (tip_mode())
      fail(column,
           fmt::format("M{} with axis words under M128 / FUNCTION TCPM or in a tilted plane is not read", code));
    const char* key = code == 91 ? "reference" : "reference2";
    for (const Word& w : b.words) {
      bool incremental = false;
      const int slot = axis_slot(w.name, incremental);
      if (slot < 0) continue;
      if (slot >= 3 && !incremental)
        fail(w.column, fmt::format("M{0} with {1}{2:g}: a rotary axis in machine coordinates is not read: the TNC "
                                   "manuals count M91 / M92 positions from the machine datum and the machine builder's "
                                   "additional one per axis, with no rule for a rotary axis (which datum its angle "
                                   "counts from, in which display range); program the rotary axes in a block of their "
                                   "own, without M{0}",
                                   code, w.name, w.value.value_or(0.0)));
      if (slot >= 3 || incremental)
        fail(w.column,
             fmt::format("M{} with {}: only absolute X, Y and Z in machine coordinates are read", code, w.name));
      const Axis& axis = machine.axes[static_cast<std::size_t>(slot)];
      const std::optional<double>& datum = code == 91 ? axis.reference : axis.reference2;
      if (!datum)
        fail(w.column, fmt::format("M{} {}{:g}: machine coordinates count from the axis's {}, which the machine file "
                                   "{} does not give; add [axes.{}] {} = ... (docs/formats.md)",
                                   code, w.name, *w.value,
                                   code == 91 ? "reference point"
                                              : "second reference point (the TNC's additional machine datum, M92)",
                                   machine.name, w.name, key));
      bw.target[static_cast<std::size_t>(slot)] = *datum + *w.value;
    }
    notice_once(
        fmt::format("M{}", code), column,
        fmt::format("M{}: the block's X Y Z are machine coordinates, counted from the axes' {} in the machine "
                    "file",
                    code, code == 91 ? "reference points (reference)" : "second reference points (reference2)"));
  }

  int rotary_index(int slot) const {
    for (int k = 0; k < 2; ++k)
      if (rotary_slot[static_cast<std::size_t>(k)] == slot) return k;
    return 0;
  }

  /// L, C, CR, CT, CP and blocks of M functions: compensation, feed, M functions at the start,
  /// the path, M functions at the end. False when the block ends the program.
  bool motion_block(const Block& b) {
    BlockWords bw = words_of(b);
    if (b.statement == "LP") bw = polar_line(b, bw);
    if (corner) finish_corner(b, bw);
    for (const auto& [code, column] : bw.m)
      if ((code == 91 || code == 92) && bw.any_axis) machine_coordinates(b, bw, code, column);
    const cl::Location where = at(b.column);
    const bool path = b.statement != "M" && b.statement != "STOP";
    if (!path && bw.feed && bw.m.size() == 1 && bw.m.front().first == 128) {  // M128 F: not the path's feed
      notice(b.column, fmt::format("M128 F{}: the feed limit of the control's compensating moves (the path's feed "
                                   "stays as programmed)",
                                   *bw.feed));
      bw.feed.reset();
    }
    if (!path && (bw.any_axis || bw.comp || bw.feed || bw.rapid))
      fail(b.column, fmt::format("{} with path words: program them in an L block", b.statement));
    BlockM m;
    for (const auto& [code, column] : bw.m) m_function(code, column, bw.any_axis, m);
    if (bw.retract_mm && !m.m140) fail(bw.retract_column, "MB without M140");
    if (m.m140 && !bw.retract_mm) fail(b.column, "M140 without MB (expected M140 MB MAX or M140 MB distance)");
    compensation_and_feed(bw, where);
    if (path) path_of(b, bw, where);
    if (!m.cycle_call && modal_cycle_call && path && bw.any_axis) m.cycle_call = true, m.cycle_call_column = b.column;
    if (m.cycle_call) call_cycle(at(m.cycle_call_column), m.cycle_call_column);
    if (b.statement == "STOP") m.after.push_back(cl::Stop{where, false, ""});
    if (m.m140) retract(bw);
    const bool records_after = !m.after.empty();
    for (auto& r : m.after) emit(std::move(r));
    if (m.program_end) return end_program(where);
    if (!records_after && !m.cycle_call && !m.m140) hold_corner_line(b, bw);
    return true;
  }

  /// What the M functions of a block ask besides what they emit at its start.
  struct BlockM {
    bool m140 = false, program_end = false, cycle_call = false;
    int cycle_call_column = 0;
    std::vector<cl::Record> after;  ///< records at the end of the block (M5, M9, M0 ...)
  };

  /// One M function of a motion block: at its start (spindle on, coolant on, modes) or at its end.
  void m_function(int code, int column, bool any_axis, BlockM& m) {
    if (code == 99 || code == 89) {  // the cycle, at the end of the block's positioning (M89: and of every later one)
      m.cycle_call = true;
      m.cycle_call_column = column;
      modal_cycle_call = code == 89;
      if (code == 89)
        notice_once("M89", column,
                    "M89 is read as the modal cycle call (the cycle after every positioning block until M99), "
                    "as the TNC's machine parameters usually set it");
      return;
    }
    if (auto why = refused_m(code)) fail(column, *why);
    const cl::Location mat = at(column);
    switch (code) {
      case 3:
      case 4:
      case 13:
      case 14:
        spindle = code == 3 || code == 13 ? cl::Spindle::Direction::cw : cl::Spindle::Direction::ccw;
        emit(cl::Spindle{mat, spindle, rpm});
        if (code >= 13) emit(cl::Coolant{mat, true, "FLOOD"});
        return;
      case 5:
        spindle = cl::Spindle::Direction::off;
        return m.after.push_back(cl::Spindle{mat, spindle, rpm});
      case 8:
        return emit(cl::Coolant{mat, true, "FLOOD"});
      case 9:
        return m.after.push_back(cl::Coolant{mat, false, "OFF"});
      case 0:
      case 1:
        return m.after.push_back(cl::Stop{mat, code == 1, ""});
      case 2:
      case 30:
        m.program_end = true;
        return;
      case 126:
      case 127:
        shortest_rotary = code == 126;
        return;
      case 128:
      case 129:
        if (plane && code == 128) fail(column, "M128 in a tilted plane (PLANE ...) is not read; PLANE RESET first");
        return switch_mode([&] { rtcp = code == 128; });
      case 140:
        m.m140 = true;
        return;
      default:
        if ((code == 91 || code == 92) && any_axis) return;  // (machine coordinates: machine_coordinates())
        m.after.push_back(cl::Unsupported{mat, fmt::format("M{}", code)});
        notice_once(fmt::format("M{}", code), column,
                    fmt::format("M{} is not acted on; passed through as a comment", code));
    }
  }

  /// RL / RR / R0 and F of a block, where they change.
  void compensation_and_feed(const BlockWords& bw, cl::Location where) {
    if (bw.comp && *bw.comp != comp) {
      comp = *bw.comp;
      cl::CutterComp c;
      c.where = where;
      c.side = comp;
      c.text = comp == cl::CutterComp::Side::off ? "R0" : comp == cl::CutterComp::Side::left ? "RL" : "RR";
      emit(c);
    }
    if (bw.feed) {
      feed = bw.feed;
      emit(cl::Feed{where, *bw.feed, false});
    }
  }

  // ---- RND / CHF (klartext_corner.hpp) ------------------------------------------------------
  /// An L (LP) in X Y at a feed whose motion ends `out`: held back, since an RND or CHF after it
  /// moves its end.
  void hold_corner_line(const Block& b, const BlockWords& bw) {
    if ((b.statement != "L" && b.statement != "LP") || !bw.any_axis || bw.rapid || !settled || out.empty()) return;
    const cl::Motion* m = std::get_if<cl::Motion>(&out.back());
    if (!m || m->where.line != line_number || !line_start) return;
    for (std::size_t i = 2; i < 6; ++i)
      if (pos[i] != (*line_start)[i]) return;
    corner_line = HeldLine{*m, *line_start};
    out.pop_back();
  }

  void flush_corner_line() {
    if (!corner_line) return;
    out.push_back(std::move(corner_line->motion));
    corner_line.reset();
  }

  /// RND R.. [F..] / CHF s [F..]: after a held line; the path is made with the line after it.
  void corner_block(const Block& b) {
    const bool rounding = b.statement == "RND";
    if (!corner_line)
      fail(b.column, fmt::format("{} without a straight line in X Y at a feed (L or LP) just before it: the rounding "
                                 "or chamfer is read between two such lines only",
                                 b.statement));
    PendingCorner c;
    c.rounding = rounding;
    c.where = at(b.column);
    for (const Word& w : b.words) {
      if (rounding ? w.name == "R" : w.name.empty()) {
        if (!w.value || !(*w.value > 0.0))
          fail(w.column, fmt::format("{}: expected {} > 0", b.statement, rounding ? "the radius R" : "the length"));
        c.length_mm = *w.value;
      } else if (w.name == "F" && w.value && *w.value > 0.0) {
        c.feed = *w.value;
      } else {
        fail(w.column, fmt::format("'{}' in {} is not read (expected {} and F)", w.name, b.statement,
                                   rounding ? "R" : "the chamfer's side length"));
      }
    }
    if (!(c.length_mm > 0.0))
      fail(b.column, fmt::format("{} without {}", b.statement, rounding ? "a radius R" : "a side length"));
    corner = c;
  }

  /// The held line up to where the corner leaves it, then the rounding or the chamfer to where it
  /// joins the line `bw` (at the feed in force, or the RND's / CHF's own F for it alone).
  void finish_corner(const Block& b, const BlockWords& bw) {
    const PendingCorner c = *corner;
    const HeldLine line = *corner_line;
    corner.reset();
    corner_line.reset();
    const char* what = c.rounding ? "RND" : "CHF";
    bool in_plane = bw.any_axis && !bw.rapid;
    for (std::size_t i = 2; i < 6; ++i) in_plane = in_plane && bw.target[i] == pos[i];
    if (!in_plane)
      fail(b.column, fmt::format("{} (line {}) followed by a line that is no straight line in X Y at a feed: the "
                                 "rounding or chamfer is read between two such lines only",
                                 what, c.where.line));
    if (bw.comp && *bw.comp != comp)
      fail(b.column, fmt::format("a change of the radius compensation right after {} (line {})", what, c.where.line));
    const auto xy = [](const ProgramPoint& p) { return Eigen::Vector2d(p[0], p[1]); };
    const auto made = corner_of(xy(line.from), xy(pos), xy(bw.target), c.length_mm, c.rounding);
    if (const std::string* why = std::get_if<std::string>(&made))
      throw InputError({file, c.where.line, c.where.column}, *why);
    const Corner& k = std::get<Corner>(made);
    ProgramPoint leave = pos, join = pos;
    leave[0] = k.leave_xy.x(), leave[1] = k.leave_xy.y();
    join[0] = k.join_xy.x(), join[1] = k.join_xy.y();
    cl::Motion shortened = locate(leave, tip_mode(), line.motion.where);
    shortened.feed = line.motion.feed;
    out.push_back(std::move(shortened));
    if (c.feed) emit(cl::Feed{c.where, *c.feed, false});
    if (c.rounding) {
      const ArcResult r = arc_about_centre(leave, join, k.centre_xy, k.counter_clockwise);
      if (!r.arc) fail(b.column, fmt::format("RND (line {}): {}", c.where.line, r.error));
      arc_motion(*r.arc, c.where, false, std::nullopt, c.where.column);
    } else {
      emit_motion(join, c.where, false, std::nullopt);
    }
    if (c.feed && feed) emit(cl::Feed{c.where, *feed, false});
    corner_join = join;
  }

  /// LP PR|IPR PA|IPA [Z|IZ]: the end in polar coordinates about the pole CC, a coordinate not
  /// given (or given incrementally) from the polar coordinates of the current position.
  BlockWords polar_line(const Block& b, BlockWords bw) const {
    if (!centre) fail(b.column, "LP without a CC before it: the pole is not known");
    if (bw.programmed[0] || bw.programmed[1]) fail(b.column, "LP with X or Y: a polar line gives PR and PA");
    if (bw.polar_rad && bw.polar_step_rad) fail(b.column, "LP with both PA and IPA");
    if (bw.polar_radius_mm && bw.polar_radius_step_mm) fail(b.column, "LP with both PR and IPR");
    if (!known[0] || !known[1]) fail(b.column, "LP before X and Y are programmed: the polar start is not known");
    const Eigen::Vector2d from = Eigen::Vector2d(pos[0], pos[1]) - *centre;
    const double radius_mm = bw.polar_radius_mm.value_or(from.norm() + bw.polar_radius_step_mm.value_or(0.0));
    const double angle_rad = bw.polar_rad.value_or(std::atan2(from.y(), from.x()) + bw.polar_step_rad.value_or(0.0));
    bw.target[0] = centre->x() + radius_mm * std::cos(angle_rad);
    bw.target[1] = centre->y() + radius_mm * std::sin(angle_rad);
    bw.programmed[0] = bw.programmed[1] = bw.any_axis = true;
    bw.polar_rad = bw.polar_step_rad = std::nullopt;
    return bw;
  }

  void path_of(const Block& b, const BlockWords& given, cl::Location where) {
    const std::string& s = b.statement;
    const BlockWords& bw = given;
    const std::optional<double> block_feed = bw.rapid ? std::nullopt : bw.feed;
    if (s == "L" || s == "LP") {
      if (!bw.any_axis) return;
      if (bw.radius_mm || bw.counter_clockwise || bw.polar_rad || bw.polar_step_rad)
        fail(b.column, "L with arc words (R, DR, PA, IPA): program C, CR or CP");
      const bool rotary_only = !bw.programmed[0] && !bw.programmed[1] && !bw.programmed[2];
      const ProgramPoint from = pos;
      line_start = corner_join.value_or(from);  // (after RND / CHF the line starts where the corner joined it)
      corner_join.reset();
      if (plane && rotary_only && position_known()) {  // in a plane: the linear axes stay, the tip moves
        pos = turned(pos, bw.target);
      } else {
        if (!rotary_only) check_plane_axis(b, bw.target);
        if (plane && !bw.rapid && commands_of(bw.target).rotary_rad != commands_of(pos).rotary_rad)
          fail(b.column, "L with rotary words and a feed in a tilted plane (PLANE ...) is not read");
        pos = bw.target;
      }
      note_programmed(bw.programmed, bw.rapid);
      const Eigen::Vector2d d(pos[0] - from[0], pos[1] - from[1]);
      if (d.norm() > 1e-9) tangent = d.normalized();
      emit_motion(pos, where, bw.rapid, block_feed);
      return;
    }
    arc_path(b, bw, where, block_feed);
  }

  void arc_path(const Block& b, const BlockWords& bw, cl::Location where, std::optional<double> block_feed) {
    const std::string& s = b.statement;
    if (!settled || !known[0] || !known[1] || !known[2])
      fail(b.column,
           fmt::format("{} before X, Y and Z are programmed on a rapid: the start of the arc is not known", s));
    for (std::size_t i = 3; i < 6; ++i)
      if (bw.programmed[i]) fail(b.column, fmt::format("{} with a rotary word: program rotary axes in L blocks", s));
    check_plane_axis(b, pos);
    if (bw.programmed[2] && s != "CP") fail(b.column, fmt::format("{} with Z: a helix is programmed with CP", s));
    if (s != "CR" && bw.radius_mm) fail(b.column, fmt::format("{} with a radius R: program CR", s));
    if (s != "CP" && (bw.polar_rad || bw.polar_step_rad)) fail(b.column, fmt::format("{} with PA/IPA: program CP", s));
    ProgramPoint end = bw.target;
    ArcResult r;
    if (s == "C" || s == "CP") {
      if (!centre) fail(b.column, fmt::format("{} without a CC before it: the circle centre is not known", s));
      if (!bw.counter_clockwise) fail(b.column, fmt::format("{} without DR+ or DR-: the direction is not known", s));
    }
    if (s == "C") {
      r = arc_about_centre(pos, end, *centre, *bw.counter_clockwise);
    } else if (s == "CR") {
      if (!bw.radius_mm) fail(b.column, "CR without R");
      if (!bw.counter_clockwise) fail(b.column, "CR without DR+ or DR-: the direction is not known");
      r = arc_by_radius(pos, end, *bw.radius_mm, *bw.counter_clockwise);
    } else if (s == "CT") {
      if (bw.counter_clockwise) fail(b.column, "CT with DR: the tangent gives the direction");
      if (!tangent) fail(b.column, "CT without a contour element before it in X Y: the tangent is not known");
      r = arc_tangent(pos, end, *tangent);
    } else {  // CP
      if (bw.programmed[0] || bw.programmed[1]) fail(b.column, "CP with X or Y: a polar arc gives PA or IPA");
      if (bw.polar_rad.has_value() == bw.polar_step_rad.has_value())
        fail(b.column, "CP: expected PA or IPA (one of them)");
      double sweep = 0.0;
      const double a0 = std::atan2(pos[1] - centre->y(), pos[0] - centre->x());
      if (bw.polar_step_rad) {
        sweep = *bw.polar_step_rad;
        if ((sweep > 0.0) != *bw.counter_clockwise)
          fail(b.column, "CP: the signs of IPA and DR differ (the TNC requires IPA+ with DR+ and IPA- with DR-)");
      } else {
        sweep = sweep_between(a0, *bw.polar_rad, *bw.counter_clockwise);
      }
      r = arc_polar(pos, *centre, sweep, end[2]);
    }
    if (!r.arc) fail(b.column, fmt::format("{}: {}", s, r.error));
    arc_motion(*r.arc, where, bw.rapid, block_feed, b.column);
    pos = r.arc->end;
    note_programmed(bw.programmed, bw.rapid);
    tangent = end_tangent(*r.arc);
  }

  /// The arc as a cl::Circle and its end (one turn at most), else as points.
  void arc_motion(const ArcMove& a, cl::Location where, bool rapid, std::optional<double> block_feed, int column) {
    const long n = gcode::arc_segments(a, options.arc_chord_tolerance_mm);
    if (n > gcode::kMaxArcSegments)
      fail(column, fmt::format("the arc would need more than {} points at a chord tolerance of {} mm",
                               gcode::kMaxArcSegments, options.arc_chord_tolerance_mm));
    const bool circle =
        std::abs(a.sweep_rad) <= 2.0 * kPi + 1e-9 && std::abs(a.radius_start_mm - a.radius_end_mm) < 5e-4;
    if (circle) {
      for (long i = 1; i < n && options.check_limits; ++i)
        locate(a.at(static_cast<double>(i) / static_cast<double>(n)), tip_mode(), where);
      ProgramPoint centre_p = a.start;
      centre_p[0] = a.centre1_mm;
      centre_p[1] = a.centre2_mm;
      ProgramPoint above = centre_p;
      above[2] += 1.0;
      cl::Circle c;
      c.where = where;
      c.center_mm = tip_of(centre_p, tip_mode());
      const Vec3d up = tip_of(above, tip_mode()) - c.center_mm;
      c.axis = (a.sweep_rad > 0.0 ? 1.0 : -1.0) * up.normalized();
      c.radius_mm = a.radius_start_mm;
      emit(c);
      emit_motion(a.end, where, rapid, block_feed);
      return;
    }
    for (long i = 1; i <= n; ++i)
      emit_motion(a.at(static_cast<double>(i) / static_cast<double>(n)), where, rapid, block_feed);
  }

  /// M140 MB MAX|d: a rapid along the tool axis (from the tip toward the spindle) until the first
  /// linear axis reaches the end of its travel (MAX), or by d (at most that far). On a machine whose
  /// head tilts the tool axis follows the head's angles, which must be programmed by then.
  void retract(const BlockWords& bw) {
    if (plane)
      fail(bw.retract_column,
           "M140 in a tilted plane (PLANE ...) is not read; PLANE RESET first, or program the retract with L");
    if (!settled) {
      notice(bw.retract_column,
             "M140 before the first programmed position moves nothing in the posted program (where "
             "the tool stands is not known yet)");
      return;
    }
    for (int k = 0; k < machine.rotary_count(); ++k)
      if (std::count(machine.tool_side.begin(), machine.tool_side.end(), 3 + k) > 0 &&
          !known[static_cast<std::size_t>(rotary_slot[static_cast<std::size_t>(k)])])
        fail(bw.retract_column,
             fmt::format("M140 before {} is programmed, on the machine {} whose head tilts by {}: the tool axis is "
                         "not known; program {} first",
                         machine.rotary(k).letter, machine.name, machine.rotary(k).letter, machine.rotary(k).letter));
    AxisPosition q = commands_of(pos);
    if (rtcp) q.linear_mm = linear_for(machine, q.rotary_rad, q.linear_mm, setup);
    const Vec3d along = retract_direction(q);
    const double room = travel_along(q.linear_mm, along, bw.retract_column);
    const double t = std::isinf(*bw.retract_mm) ? room : std::min(room, *bw.retract_mm);
    if (t <= 0.0) return;  // (at the end of the travel already: the TNC stays)
    q.linear_mm += t * along;
    ProgramPoint p = pos;
    const Vec3d xyz = rtcp ? forward(machine, q, setup).tip_mm : q.linear_mm;
    for (std::size_t i = 0; i < 3; ++i) p[i] = xyz[static_cast<int>(i)];
    notice_once(
        "M140", bw.retract_column,
        fmt::format("M140 MB: a rapid along the tool axis by {:.3f} mm, to machine X {:.3f} Y {:.3f} Z {:.3f}{}", t,
                    q.linear_mm.x(), q.linear_mm.y(), q.linear_mm.z(),
                    std::isinf(*bw.retract_mm) ? ", the end of the travel in the machine file" : ""));
    pos = p;
    emit_motion(pos, at(bw.retract_column), true, std::nullopt);
  }

  /// The move of the machine's linear axes that takes the tool tip 1 mm along the tool axis at `q`
  /// (the tip is affine in the linear axes: each column of the map is exact).
  Vec3d retract_direction(const AxisPosition& q) const {
    const ToolPoseT<double> at_q = forward(machine, q, setup);
    Eigen::Matrix3d tip_per_mm;
    for (int i = 0; i < 3; ++i) {
      AxisPosition moved = q;
      moved.linear_mm[i] += 1.0;
      tip_per_mm.col(i) = forward(machine, moved, setup).tip_mm - at_q.tip_mm;
    }
    return tip_per_mm.colPivHouseholderQr().solve(at_q.axis.normalized());
  }

  /// How far the linear axes at `from_mm` may move by multiples of `along` within their travel.
  double travel_along(const Vec3d& from_mm, const Vec3d& along, int column) const {
    double room = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) {
      if (std::abs(along[i]) < 1e-12) continue;
      const Axis& axis = machine.axes[static_cast<std::size_t>(i)];
      if (!axis.limits)
        fail(column, fmt::format("M140: the machine file gives no {} travel, so the end of the retract is not known",
                                 axis.letter));
      const double end = along[i] > 0.0 ? axis.limits->max : axis.limits->min;
      room = std::min(room, (end - from_mm[i]) / along[i]);
    }
    return std::max(room, 0.0);
  }

  std::optional<cl::Record> next() {
    for (;;) {
      if (!out.empty()) {
        cl::Record r = std::move(out.front());
        out.pop_front();
        return r;
      }
      if (ended) return std::nullopt;
      if (!read_block()) ended = true;
    }
  }
};

KlartextReader::KlartextReader(std::istream& in, std::string file_name, const Machine& machine, const Setup& setup,
                               ReaderOptions options)
    : state_(std::make_unique<State>(in, std::move(file_name), machine, setup, options)) {}

KlartextReader::~KlartextReader() = default;

std::optional<cl::Record> KlartextReader::next() { return state_->next(); }

std::vector<std::string> KlartextReader::take_notices() {
  std::vector<std::string> out;
  out.swap(state_->notices);
  return out;
}

}  // namespace ncpost::klartext
